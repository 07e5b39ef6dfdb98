/* The Wendland C2 kernel (004 Eq. 5): see wendland_c2.h. */
#include "wendland_c2.h"

#include "dim.h"

static const double PI = 3.14159265358979323846;

double wendland_c2_normalisation(int dim, double h)
{
    if (!(h > 0.0))
        return 0.0;
    if (dim == 2)
        return 7.0 / (32.0 * PI * h * h);
    if (dim == 3)
        return 21.0 / (128.0 * PI * h * h * h);
    return 0.0;
}

int wendland_c2_init(wendland_c2_kernel *k, double h)
{
    *k = (wendland_c2_kernel){0};
    if (!(h > 0.0) || !isfinite(h))
        return -1;
    k->h = h;
    k->support = 2.0 * h;
    k->support2 = k->support * k->support;
    k->alpha = wendland_c2_normalisation(FSI_DIM, h);
    k->inv_h = 1.0 / h;
    k->grad_scale = -5.0 * k->alpha / (h * h);
    return 0;
}
