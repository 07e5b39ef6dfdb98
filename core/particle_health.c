/* Shared health-check helpers of the particle participants (particle_health.h). */
#include "particle_health.h"

#include <math.h>
#include <stdio.h>

const char *fsi_point_text(const double *x, char *buf, size_t size)
{
    int len = snprintf(buf, size, "(");
    for (int d = 0; d < FSI_DIM && len < (int)size; d++)
        len += snprintf(buf + len, size - (size_t)len, "%s%.6g", d ? ", " : "", x[d]);
    if (len < (int)size)
        snprintf(buf + len, size - (size_t)len, ")");
    return buf;
}

void fsi_escape_box(const double *x, int n, double diagonals, double min_size,
                    double *box_min, double *box_max)
{
    for (int d = 0; d < FSI_DIM; d++) {
        box_min[d] = INFINITY;
        box_max[d] = -INFINITY;
    }
    for (int i = 0; i < n; i++)
        for (int d = 0; d < FSI_DIM; d++) {
            box_min[d] = fmin(box_min[d], x[i * FSI_DIM + d]);
            box_max[d] = fmax(box_max[d], x[i * FSI_DIM + d]);
        }
    double diag = 0.0;
    for (int d = 0; d < FSI_DIM; d++)
        diag += (box_max[d] - box_min[d]) * (box_max[d] - box_min[d]);
    diag = fmax(sqrt(diag), min_size);
    for (int d = 0; d < FSI_DIM; d++) {
        box_min[d] -= diagonals * diag;
        box_max[d] += diagonals * diag;
    }
}

int fsi_outside_box(const double *x, int n, const double *box_min, const double *box_max)
{
    for (int i = 0; i < n; i++)
        for (int d = 0; d < FSI_DIM; d++)
            if (!(x[i * FSI_DIM + d] >= box_min[d] && x[i * FSI_DIM + d] <= box_max[d]))
                return i;
    return -1;
}

int fsi_fastest(const double *v, int n, double *speed)
{
    int fastest = 0;
    double v2max = n > 0 ? -1.0 : 0.0;
    for (int i = 0; i < n; i++) {
        double v2 = 0.0;
        for (int d = 0; d < FSI_DIM; d++)
            v2 += v[i * FSI_DIM + d] * v[i * FSI_DIM + d];
        if (v2 > v2max || !isfinite(v2)) {
            v2max = v2;
            fastest = i;
            if (!isfinite(v2))
                break;
        }
    }
    *speed = sqrt(v2max);
    return fastest;
}
