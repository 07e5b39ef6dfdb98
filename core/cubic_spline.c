/* The cubic B-spline kernel (003 §2.1): see cubic_spline.h. */
#include "cubic_spline.h"

#include "dim.h"

static const double PI = 3.14159265358979323846;

double cubic_spline_normalisation(int dim, double h)
{
    if (!(h > 0.0))
        return 0.0;
    if (dim == 2)
        return 10.0 / (7.0 * PI * h * h);
    if (dim == 3)
        return 1.0 / (PI * h * h * h);
    return 0.0;
}

int cubic_spline_init(cubic_spline_kernel *k, double h)
{
    *k = (cubic_spline_kernel){0};
    if (!(h > 0.0) || !isfinite(h))
        return -1;
    k->h = h;
    k->support = 2.0 * h;
    k->support2 = k->support * k->support;
    k->alpha = cubic_spline_normalisation(FSI_DIM, h);
    k->inv_h = 1.0 / h;
    return 0;
}
