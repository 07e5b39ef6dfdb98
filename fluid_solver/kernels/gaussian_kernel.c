/* The Gaussian kernel of 000 Eqs. 17-18: see gaussian_kernel.h. */
#include "gaussian_kernel.h"

#include "dim.h"

static const double PI = 3.14159265358979323846;

double gaussian_kernel_normalisation(int dim, double h, double q)
{
    if (!(h > 0.0) || !(q > 0.0))
        return 0.0;
    const double c = exp(-q * q);
    double integral; /* of exp(-(r/h)^2) - C over the ball r < q h, divided by h^dim */
    if (dim == 2)
        integral = PI * (1.0 - (1.0 + q * q) * c);
    else if (dim == 3)
        integral = pow(PI, 1.5) * erf(q) - 2.0 * PI * q * c - 4.0 / 3.0 * PI * q * q * q * c;
    else
        return 0.0;
    return 1.0 / (integral * pow(h, dim));
}

int gaussian_kernel_init(gaussian_kernel *k, double h, double support_factor)
{
    *k = (gaussian_kernel){0};
    if (!(h > 0.0) || !isfinite(h) || !(support_factor > 0.0) || !isfinite(support_factor))
        return -1;
    k->h = h;
    k->support_factor = support_factor;
    k->support = support_factor * h;
    k->support2 = k->support * k->support;
    k->shift = exp(-support_factor * support_factor);
    k->alpha = gaussian_kernel_normalisation(FSI_DIM, h, support_factor);
    k->inv_h2 = 1.0 / (h * h);
    return 0;
}
