/* The "where" of a model's error message: see solid_point_text.h. */
#include "solid_point_text.h"

#include <stdint.h>
#include <stdio.h>

void solid_describe_point(const solid_particles *p, int i, char *buf, size_t size)
{
    int len = snprintf(buf, size, "point id %d at (", p->id ? p->id[i] : i);
    for (int d = 0; d < FSI_DIM && len > 0 && (size_t)len < size; d++)
        len += snprintf(buf + len, size - (size_t)len, "%s%.6g", d ? ", " : "",
                        p->x[(int64_t)i * FSI_DIM + d]);
    for (int d = 0; d < FSI_DIM && len > 0 && (size_t)len < size; d++)
        len += snprintf(buf + len, size - (size_t)len, "%s%.6g", d ? ", " : ") (reference (",
                        p->x0[(int64_t)i * FSI_DIM + d]);
    if (len > 0 && (size_t)len < size)
        snprintf(buf + len, size - (size_t)len, "))");
}
