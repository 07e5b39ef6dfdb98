/* Periodic keys of the fluid (fluid_periodic.h). */
#include "fluid_periodic.h"

#include "case_check.h"

#include <stdio.h>
#include <string.h>

int fluid_periodic_read(const fsi_case *c, const char *role, fsi_periodic *per, char *msg,
                        size_t msg_size)
{
    static const char axis_name[3] = {'x', 'y', 'z'};
    *per = (fsi_periodic){{0}, {0}, {0}};
    const char *axes = fsi_case_get(c, role, "periodic");
    if (!axes || strcmp(axes, "none") == 0)
        return 0;
    double lo[FSI_DIM], hi[FSI_DIM];
    if (fsi_case_get_vector(c, role, "periodic_min", lo) != 0 ||
        fsi_case_get_vector(c, role, "periodic_max", hi) != 0) {
        snprintf(msg, msg_size, "%s: [%s] periodic = %s needs periodic_min and periodic_max "
                 "(the period box)", fsi_case_where(c, role, "periodic"), role, axes);
        return -1;
    }
    for (int d = 0; d < FSI_DIM; d++) {
        if (!strchr(axes, axis_name[d]))
            continue;
        if (!(hi[d] > lo[d])) {
            snprintf(msg, msg_size, "%s: [%s] periodic_max: must exceed periodic_min along "
                     "%c (%g <= %g): give the period box", fsi_case_where(c, role, "periodic_max"), role,
                     axis_name[d], hi[d], lo[d]);
            return -1;
        }
        per->on[d] = 1;
        per->lo[d] = lo[d];
        per->length[d] = hi[d] - lo[d];
    }
    return 0;
}
