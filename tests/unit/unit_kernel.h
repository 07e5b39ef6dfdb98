/* Helpers of the SPH kernel tests (test_wendland_kernel.c, test_cubic_spline_kernel.c):
 * the integral of a radial kernel over the plane or space, and its gradient by central
 * differences. A kernel is a W(r) function and the kernel it reads, so that one helper
 * serves every kernel type of core/. Header-only: every test is one executable. */
#ifndef FSI_UNIT_KERNEL_H
#define FSI_UNIT_KERNEL_H

#include <math.h>

/* W at distance r of the kernel k. */
typedef double (*unit_kernel_w)(const void *k, double r);

/* integral of W over R^dim (dim 2 or 3) for a kernel of support 'support': the radial
 * Simpson rule over n intervals (n even), integrand W(r) times the circle 2 pi r or
 * the sphere 4 pi r^2. */
static inline double unit_radial_integral(unit_kernel_w w, const void *k, double support,
                                          int dim, int n)
{
    const double pi = 3.14159265358979323846, step = support / n;
    double sum = 0.0;
    for (int i = 0; i <= n; i++) {
        const double r = i * step;
        const double shell = dim == 2 ? 2.0 * pi * r : 4.0 * pi * r * r;
        const double weight = (i == 0 || i == n) ? 1.0 : (i % 2 ? 4.0 : 2.0);
        sum += weight * shell * w(k, r);
    }
    return sum * step / 3.0;
}

/* The gradient of W(|(x, y)|) at (x, y) = r (cos 0.3, sin 0.3) by central differences
 * of step e, against F (x, y) (F = (dW/dr) / r at r): the larger of the two
 * components' differences. */
static inline double unit_kernel_gradient_error(unit_kernel_w w, const void *k, double r,
                                                double f, double e)
{
    const double x = r * cos(0.3), y = r * sin(0.3);
    const double gx = (w(k, hypot(x + e, y)) - w(k, hypot(x - e, y))) / (2.0 * e);
    const double gy = (w(k, hypot(x, y + e)) - w(k, hypot(x, y - e))) / (2.0 * e);
    return fmax(fabs(gx - f * x), fabs(gy - f * y));
}

#endif
