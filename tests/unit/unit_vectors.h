/* Dense vector measures the unit tests compare results with. */
#ifndef FSI_UNIT_VECTORS_H
#define FSI_UNIT_VECTORS_H

#include <math.h>

static inline double norm2(const double *u, int n)
{
    double s = 0.0;
    for (int i = 0; i < n; i++)
        s += u[i] * u[i];
    return sqrt(s);
}

/* |u - v| / |v| */
static inline double rel_diff(const double *u, const double *v, int n)
{
    double d = 0.0;
    for (int i = 0; i < n; i++)
        d += (u[i] - v[i]) * (u[i] - v[i]);
    return sqrt(d) / norm2(v, n);
}

static inline int all_finite(const double *u, int n)
{
    for (int i = 0; i < n; i++)
        if (!isfinite(u[i]))
            return 0;
    return 1;
}

#endif
