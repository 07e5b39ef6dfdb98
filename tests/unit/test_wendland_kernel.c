/* The Wendland C2 kernel (core/wendland_c2.h, 004 Eq. 5):
 *  - 004's 2D normalisation alpha_d = 7 / (32 pi h^2), and the integral of W over its
 *    support is 1 in 2D and 3D (radial Simpson quadrature, 1e-10);
 *  - on a square lattice of spacing dx the sum of W V over the lattice tends to 1 as
 *    h / dx grows: measured 1.05e-2 at 1.3, 5.1e-3 at the default 1.5, 3.05e-3 at 1.7,
 *    1.2e-3 at 2 (docs/wcsph.md), checked to within 1.1e-2, 5.2e-3 at 1.5, and
 *    decreasing over [1.3, 2];
 *  - the support is 2h: W and its gradient vanish at and beyond it, W > 0 inside, W
 *    decreasing;
 *  - the gradient F(r) x = (dW/dr / r) x against central differences of W (1e-7), and
 *    W is continuous with zero slope at r = 0 and at the support (C2 at the edge). */
#include <math.h>
#include <stdio.h>

#include "dim.h"
#include "wendland_c2.h"

#include "unit_check.h"
#include "unit_kernel.h"

static const double PI = 3.14159265358979323846;

/* W of a wendland_c2_kernel for unit_kernel.h. */
static double w_of(const void *k, double r)
{
    return wendland_c2_w(k, r);
}

static void test_normalisation(void)
{
    const double h = 0.0123;
    CHECK(fabs(wendland_c2_normalisation(2, h) - 7.0 / (32.0 * PI * h * h)) <
              1e-14 * wendland_c2_normalisation(2, h),
          "2D alpha_d is not 7 / (32 pi h^2)");
    CHECK(wendland_c2_normalisation(1, h) == 0.0 && wendland_c2_normalisation(2, -h) == 0.0,
          "bad input gives a non-zero normalisation");
    wendland_c2_kernel k;
    CHECK(wendland_c2_init(&k, h) == 0, "init refused h = %g", h);
    for (int dim = 2; dim <= 3; dim++) {
        /* The integral with dim's own alpha_d: rescale from the build's. */
        const double scale = wendland_c2_normalisation(dim, h) / k.alpha;
        const double integral = scale * unit_radial_integral(w_of, &k, k.support, dim, 20000);
        printf("wendland: integral of W in %dD = %.15f\n", dim, integral);
        CHECK(fabs(integral - 1.0) < 1e-10, "%dD integral of W is %.15g, not 1", dim, integral);
    }
    CHECK(wendland_c2_init(&k, 0.0) != 0 && wendland_c2_init(&k, NAN) != 0,
          "init accepted a non-positive or NaN h");
}

#if FSI_DIM == 2
/* sum_J W(x_J) dx^2 over a square lattice through the origin (a particle's own
 * family, itself included). */
static double lattice_sum(double h_over_dx)
{
    const double dx = 1e-3;
    wendland_c2_kernel k;
    wendland_c2_init(&k, h_over_dx * dx);
    const int m = (int)ceil(k.support / dx) + 1;
    double sum = 0.0;
    for (int i = -m; i <= m; i++)
        for (int j = -m; j <= m; j++)
            sum += wendland_c2_w(&k, hypot(i * dx, j * dx)) * dx * dx;
    return sum;
}

static void test_lattice_sum(void)
{
    double worst = 0.0, previous = INFINITY;
    int decreasing = 1;
    for (double f = 1.3; f <= 2.0 + 1e-9; f += 0.05) {
        const double error = fabs(lattice_sum(f) - 1.0);
        worst = fmax(worst, error);
        decreasing &= error < previous;
        previous = error;
    }
    const double at_default = lattice_sum(1.5);
    printf("wendland: lattice sum of W V: |error| <= %.3g for h/dx in [1.3, 2], %.3g at 1.5\n",
           worst, fabs(at_default - 1.0));
    CHECK(worst < 1.1e-2, "lattice sum off by %g for some h/dx in [1.3, 2]", worst);
    CHECK(decreasing, "lattice sum error does not decrease with h/dx over [1.3, 2]");
    CHECK(fabs(at_default - 1.0) < 5.2e-3, "lattice sum at h/dx = 1.5 off by %g",
          fabs(at_default - 1.0));
}
#endif

static void test_support_and_gradient(void)
{
    const double h = 0.01;
    wendland_c2_kernel k;
    wendland_c2_init(&k, h);
    CHECK(k.support == 2.0 * h, "support is %g, not 2h", k.support);
    double w, f;
    wendland_c2_eval2(&k, k.support2, &w, &f);
    CHECK(w == 0.0 && f == 0.0, "W or F not zero at the support: %g %g", w, f);
    wendland_c2_eval2(&k, 1.0001 * k.support2, &w, &f);
    CHECK(w == 0.0 && f == 0.0, "W or F not zero beyond the support");
    CHECK(wendland_c2_w(&k, 0.0) == k.alpha * 0.5 * 16.0, "W(0) = %g, not 8 alpha_d",
          wendland_c2_w(&k, 0.0));
    double previous = INFINITY, worst = 0.0;
    int decreasing = 1;
    for (int i = 0; i < 400; i++) {
        const double r = (i + 0.5) / 400.0 * k.support;
        const double here = wendland_c2_w(&k, r);
        decreasing &= here > 0.0 && here < previous;
        previous = here;
        /* d/dx of W(|x|) by central differences against F x, both components. */
        wendland_c2_eval2(&k, r * r, &w, &f);
        const double scale = k.alpha / h;
        worst = fmax(worst, unit_kernel_gradient_error(w_of, &k, r, f, 1e-6 * h) / scale);
        CHECK(f <= 0.0, "F > 0 at r = %g", r);
        CHECK(fabs(wendland_c2_dw(&k, r) - f * r) <= 1e-15 * scale, "dW/dr != F r");
    }
    printf("wendland: gradient against central differences: %.3g of alpha_d / h\n", worst);
    CHECK(decreasing, "W not positive and decreasing inside the support");
    CHECK(worst < 1e-7, "gradient off central differences by %g alpha_d / h", worst);
    /* Zero slope at the centre and at the edge. */
    CHECK(fabs(wendland_c2_dw(&k, 1e-9 * h)) < 1e-7 * k.alpha / h, "slope at r = 0");
    CHECK(fabs(wendland_c2_dw(&k, (2.0 - 1e-4) * h)) < 1e-9 * k.alpha / h, "slope at 2h");
}

int main(void)
{
    test_normalisation();
#if FSI_DIM == 2
    test_lattice_sum();
#endif
    test_support_and_gradient();
    return unit_check_report("test_wendland_kernel");
}
