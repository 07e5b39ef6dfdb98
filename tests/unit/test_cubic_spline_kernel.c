/* The cubic B-spline kernel (core/cubic_spline.h; Monaghan & Lattanzio 1985, the
 * kernel of 003 §2.1):
 *  - the 2D normalisation alpha_d = 10 / (7 pi h^2) (and 1 / (pi h^3) in 3D), and the
 *    integral of W over its support is 1 in 2D and 3D (radial Simpson quadrature,
 *    1e-10: W r^(d-1) is a polynomial of degree <= 5 on each piece, which the rule
 *    integrates to O(step^4) = 1e-16, and the knot q = 1 ends a Simpson panel);
 *  - the support is 2h: W and its gradient vanish at and beyond it, W(0) = alpha_d,
 *    W > 0 and decreasing inside, F = (dW/dr) / r <= 0;
 *  - the gradient F(r) x = (dW/dr / r) x against central differences of W (1e-7 of
 *    alpha_d / h: the step 1e-6 h leaves a truncation error of 1e-12 and a
 *    cancellation error of 1e-10 of it, so 1e-7 also passes across the knot at q = 1,
 *    where the second derivative is continuous but the third jumps);
 *  - W and dW/dr are continuous at the knots q = 1 and q = 2 (both branches
 *    evaluated 1e-9 h either side agree to the slope's change over 2e-9 h: 1e-8 of
 *    alpha_d and alpha_d / h), and so is the second derivative (the kernel is C2);
 *  - a non-positive, NaN or infinite h is refused. */
#include <math.h>
#include <stdio.h>

#include "cubic_spline.h"
#include "dim.h"

#include "unit_check.h"
#include "unit_kernel.h"

static const double PI = 3.14159265358979323846;

static double w_at(const cubic_spline_kernel *k, double r)
{
    double w, f;
    cubic_spline_eval2(k, r * r, &w, &f);
    return w;
}

static double dw_at(const cubic_spline_kernel *k, double r)
{
    double w, f;
    cubic_spline_eval2(k, r * r, &w, &f);
    return f * r;
}

/* W of a cubic_spline_kernel for unit_kernel.h. */
static double w_of(const void *k, double r)
{
    return w_at(k, r);
}

/* The radial Simpson rule over 20000 intervals of the support: 10000 in each piece
 * q < 1, 1 <= q < 2, so that the knot is a panel's end. */
enum { RADIAL_INTERVALS = 20000 };

static void test_normalisation(void)
{
    const double h = 0.0123;
    const double a2 = cubic_spline_normalisation(2, h), a3 = cubic_spline_normalisation(3, h);
    printf("cubic spline: alpha_d h^2 = %.15f in 2D (10 / (7 pi) = %.15f), alpha_d h^3 = "
           "%.15f in 3D\n", a2 * h * h, 10.0 / (7.0 * PI), a3 * h * h * h);
    CHECK(fabs(a2 - 10.0 / (7.0 * PI * h * h)) < 1e-14 * a2, "2D alpha_d is not 10 / (7 pi h^2)");
    CHECK(fabs(a3 - 1.0 / (PI * h * h * h)) < 1e-14 * a3, "3D alpha_d is not 1 / (pi h^3)");
    CHECK(cubic_spline_normalisation(1, h) == 0.0 && cubic_spline_normalisation(2, -h) == 0.0 &&
              cubic_spline_normalisation(2, 0.0) == 0.0,
          "bad input gives a non-zero normalisation");
    cubic_spline_kernel k;
    CHECK(cubic_spline_init(&k, h) == 0, "init refused h = %g", h);
    CHECK(k.alpha == cubic_spline_normalisation(FSI_DIM, h), "init's alpha_d is not the "
          "build's dimension's");
    for (int dim = 2; dim <= 3; dim++) {
        /* The integral with dim's own alpha_d: rescale from the build's. */
        const double scale = cubic_spline_normalisation(dim, h) / k.alpha;
        const double integral =
            scale * unit_radial_integral(w_of, &k, k.support, dim, RADIAL_INTERVALS);
        printf("cubic spline: integral of W in %dD = %.15f\n", dim, integral);
        CHECK(fabs(integral - 1.0) < 1e-10, "%dD integral of W is %.15g, not 1", dim, integral);
    }
    const double bad[] = {0.0, -h, NAN, INFINITY};
    for (int i = 0; i < 4; i++) {
        k.h = 1.0;
        const int rc = cubic_spline_init(&k, bad[i]);
        CHECK(rc != 0 && k.h == 0.0 && k.alpha == 0.0, "init accepted h = %g (%d) or did "
              "not zero the kernel", bad[i], rc);
    }
}

static void test_support_and_gradient(void)
{
    const double h = 0.01;
    cubic_spline_kernel k;
    cubic_spline_init(&k, h);
    CHECK(k.support == 2.0 * h && k.support2 == k.support * k.support,
          "support is %g, not 2h", k.support);
    double w, f;
    cubic_spline_eval2(&k, k.support2, &w, &f);
    CHECK(w == 0.0 && f == 0.0, "W or F not zero at the support: %g %g", w, f);
    cubic_spline_eval2(&k, 1.0001 * k.support2, &w, &f);
    CHECK(w == 0.0 && f == 0.0, "W or F not zero beyond the support");
    CHECK(w_at(&k, 0.0) == k.alpha, "W(0) = %g, not alpha_d", w_at(&k, 0.0));
    double previous = INFINITY, worst = 0.0;
    int decreasing = 1, positive_f = 0;
    const double scale = k.alpha / h;
    for (int i = 0; i < 400; i++) {
        const double r = (i + 0.5) / 400.0 * k.support;
        const double here = w_at(&k, r);
        decreasing &= here > 0.0 && here < previous;
        previous = here;
        cubic_spline_eval2(&k, r * r, &w, &f);
        worst = fmax(worst, unit_kernel_gradient_error(w_of, &k, r, f, 1e-6 * h) / scale);
        positive_f += f > 0.0;
    }
    printf("cubic spline: gradient against central differences: %.3g of alpha_d / h\n", worst);
    CHECK(decreasing, "W not positive and decreasing inside the support");
    CHECK(positive_f == 0, "F > 0 at %d of 400 distances", positive_f);
    CHECK(worst < 1e-7, "gradient off central differences by %g alpha_d / h", worst);
    /* F is finite at r -> 0 (the inner branch's -3 alpha_d / h^2), zero slope there. */
    cubic_spline_eval2(&k, 0.0, &w, &f);
    CHECK(fabs(f / (-3.0 * k.alpha / (h * h)) - 1.0) < 1e-14, "F(0) = %g, not -3 alpha_d / h^2",
          f);
    CHECK(fabs(dw_at(&k, 1e-9 * h)) < 1e-8 * scale, "slope at r = 0");
}

/* W, dW/dr and d2W/dr2 (the last by differences of dW/dr over 2e, e = 1e-7 h, inside
 * one branch, centred 2e from the knot) on either side of the knots q = 1 and 2: a
 * jump in W or dW/dr would show at the size of the coefficients (alpha_d / 4 and
 * 3 alpha_d / (4 h) at q = 1), a continuous function only its slope over 2e-9 h
 * (1e-8). */
static void test_knots(void)
{
    const double h = 0.01, delta = 1e-9 * h, e = 1e-7 * h;
    cubic_spline_kernel k;
    cubic_spline_init(&k, h);
    const double scale_w = k.alpha, scale_dw = k.alpha / h, scale_d2w = k.alpha / (h * h);
    for (int q = 1; q <= 2; q++) {
        const double r = q * h, below = r - delta, above = r + delta;
        const double jump_w = fabs(w_at(&k, above) - w_at(&k, below)) / scale_w;
        const double jump_dw = fabs(dw_at(&k, above) - dw_at(&k, below)) / scale_dw;
        /* Second derivative of each branch, one-sided out of the knot. */
        const double d2_below = (dw_at(&k, r - e) - dw_at(&k, r - 3.0 * e)) / (2.0 * e);
        const double d2_above = q == 1 ? (dw_at(&k, r + 3.0 * e) - dw_at(&k, r + e)) / (2.0 * e)
                                       : 0.0;
        const double jump_d2w = fabs(d2_above - d2_below) / scale_d2w;
        printf("cubic spline: at q = %d, W jumps by %.3g alpha_d, dW/dr by %.3g alpha_d / h, "
               "d2W/dr2 by %.3g alpha_d / h^2 (W = %.3g alpha_d, dW/dr = %.3g alpha_d / h "
               "there)\n", q, jump_w, jump_dw, jump_d2w, w_at(&k, below) / scale_w,
               dw_at(&k, below) / scale_dw);
        CHECK(jump_w < 1e-8 && jump_dw < 1e-8, "q = %d: W jumps by %g alpha_d, dW/dr by %g "
              "alpha_d / h", q, jump_w, jump_dw);
        /* 1e-5: the quotients sit 2e from the knot, where the third derivatives
         * 4.5 and -1.5 alpha_d / h^3 move d2W/dr2 by 9e-7 and 3e-7 of alpha_d / h^2;
         * round-off 1e-16 / 1e-7. */
        CHECK(jump_d2w < 1e-5, "q = %d: d2W/dr2 jumps by %g alpha_d / h^2", q, jump_d2w);
    }
    /* The values at q = 1 are the branches' common alpha_d / 4 and -3 alpha_d / (4 h). */
    CHECK(fabs(w_at(&k, h) / k.alpha - 0.25) < 1e-15 &&
              fabs(dw_at(&k, h) / scale_dw + 0.75) < 1e-15,
          "W(h) = %.17g alpha_d, dW/dr(h) = %.17g alpha_d / h", w_at(&k, h) / k.alpha,
          dw_at(&k, h) / scale_dw);
}

int main(void)
{
    test_normalisation();
    test_support_and_gradient();
    test_knots();
    return unit_check_report("test_cubic_spline_kernel");
}
