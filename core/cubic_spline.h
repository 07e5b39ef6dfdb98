/* The cubic B-spline kernel (Monaghan & Lattanzio 1985; Liu & Liu 2003), the kernel of
 * Salehizadeh & Shafiei 2022's ISPH and TLSPH (003 §2.1, h = 1.2 dx):
 *
 *     W(q) = alpha_d (1 - 3/2 q^2 + 3/4 q^3)   for 0 <= q < 1,
 *            alpha_d (2 - q)^3 / 4             for 1 <= q < 2,   0 beyond,  q = r / h,
 *
 * support 2h, alpha_d = 10 / (7 pi h^2) in 2D and 1 / (pi h^3) in 3D, so that W
 * integrates to 1. Its derivative over r is finite at r = 0 on the inner branch:
 *
 *     (dW/dr) / r = alpha_d (-3 + 9/4 q) / h^2           for q < 1,
 *                   -3/4 alpha_d (2 - q)^2 / (q h^2)      for 1 <= q < 2,
 *
 * so the gradient with respect to x_I of W(|x_I - x_J|) is F(r) (x_I - x_J), F <= 0.
 * Kept beside core/wendland_c2.h with the same small function set, so that a scheme
 * takes either. */
#ifndef FSI_CUBIC_SPLINE_H
#define FSI_CUBIC_SPLINE_H

#include <math.h>

typedef struct {
    double h;           /* smoothing length [m] */
    double support;     /* 2 h [m] */
    double support2;    /* (2 h)^2 [m^2] */
    double alpha;       /* alpha_d [1/m^DIM] */
    double inv_h;       /* 1 / h [1/m] */
} cubic_spline_kernel;

/* alpha_d for dimension dim (2 or 3) and smoothing length h; 0 for another dimension or
 * a non-positive h. */
double cubic_spline_normalisation(int dim, double h);

/* Sets up the kernel of the build's dimension (FSI_DIM). 0, or -1 when h is not a
 * positive finite number (k is then zeroed). */
int cubic_spline_init(cubic_spline_kernel *k, double h);

/* W and F = (dW/dr) / r at squared distance r2 (0 and 0 at and beyond the support). */
static inline void cubic_spline_eval2(const cubic_spline_kernel *k, double r2, double *w,
                                      double *f)
{
    if (!(r2 < k->support2)) {
        *w = 0.0;
        *f = 0.0;
        return;
    }
    const double q = sqrt(r2) * k->inv_h, scale = k->alpha * k->inv_h * k->inv_h;
    if (q < 1.0) {
        *w = k->alpha * (1.0 - 1.5 * q * q + 0.75 * q * q * q);
        *f = scale * (-3.0 + 2.25 * q);
    } else {
        const double s = 2.0 - q;
        *w = 0.25 * k->alpha * s * s * s;
        *f = -0.75 * scale * s * s / q;
    }
}

#endif
