/* The beginning every model's solid_model_create shares: solid_model_setup.h. */
#include "solid_model_setup.h"

#include <stdio.h>

int solid_model_setup(material *mat, double *dx, const fsi_case *c, const solid_particles *p,
                      const char *model, char *msg, size_t msg_size)
{
    if (msg && msg_size)
        msg[0] = '\0';
    if (material_from_case(mat, c, "solid", msg, msg_size) != 0)
        return -1;
    *dx = p->spacing;
    if (!(*dx > 0.0)) {
        snprintf(msg, msg_size, "%s: lattice spacing %g is not positive", model, *dx);
        return -1;
    }
    return 0;
}
