/* The Wendland C2 kernel (Wendland 1995), the kernel of WCSPH (004 Eq. 5) and of the
 * pseudo-spring SPH solid (004 §3; in core/ because both participants use it):
 *
 *     W(q) = alpha_d (q + 1/2) (2 - q)^4   for q = r / h <= 2,   0 beyond,
 *
 * support 2h, with alpha_d = 7 / (32 pi h^2) in 2D (004, after Eq. 5) and
 * 21 / (128 pi h^3) in 3D (the common form alpha'_d (1 - q/2)^4 (2q + 1) with
 * alpha'_d = 7 / (4 pi h^2), 21 / (16 pi h^3) is the same function: (1 - q/2)^4 (2q + 1)
 * = (2 - q)^4 (q + 1/2) / 8), so that the integral of W over its support is 1. Its
 * derivative has no singular factor at r = 0:
 *
 *     dW/dr = -5 alpha_d q (2 - q)^3 / h,   (dW/dr) / r = -5 alpha_d (2 - q)^3 / h^2,
 *
 * so the gradient with respect to x_I of W(|x_I - x_J|) is F(r) (x_I - x_J) with
 * F = (dW/dr) / r <= 0, finite at every distance. */
#ifndef FSI_WENDLAND_C2_H
#define FSI_WENDLAND_C2_H

#include <math.h>
#include <stdint.h>

typedef struct {
    double h;           /* smoothing length [m] */
    double support;     /* 2 h [m] */
    double support2;    /* (2 h)^2 [m^2] */
    double alpha;       /* alpha_d [1/m^DIM] */
    double inv_h;       /* 1 / h [1/m] */
    double grad_scale;  /* -5 alpha_d / h^2 [1/m^(DIM+2)] */
} wendland_c2_kernel;

/* alpha_d for dimension dim (2 or 3) and smoothing length h; 0 for another dimension or
 * a non-positive h. */
double wendland_c2_normalisation(int dim, double h);

/* Sets up the kernel of the build's dimension (FSI_DIM). 0, or -1 when h is not a
 * positive finite number (k is then zeroed). */
int wendland_c2_init(wendland_c2_kernel *k, double h);

/* W and F = (dW/dr) / r at squared distance r2 (0 and 0 at and beyond the support). */
static inline void wendland_c2_eval2(const wendland_c2_kernel *k, double r2, double *w,
                                     double *f)
{
    if (!(r2 < k->support2)) {
        *w = 0.0;
        *f = 0.0;
        return;
    }
    const double q = sqrt(r2) * k->inv_h, s = 2.0 - q, s3 = s * s * s;
    *w = k->alpha * (q + 0.5) * s3 * s;
    *f = k->grad_scale * s3;
}

/* F = (dW/dr) / r at squared distance r2, which must be inside the support (no test:
 * for loops over pairs already filtered). */
static inline double wendland_c2_f_inside(const wendland_c2_kernel *k, double r2)
{
    const double s = 2.0 - sqrt(r2) * k->inv_h;
    return k->grad_scale * s * s * s;
}

/* F over a row of pairs: r2_f[q] = F(r2_f[q]) for n squared distances all inside the
 * support (in place; the loop has no call and no branch, so it vectorises). */
static inline void wendland_c2_f_row(const wendland_c2_kernel *k, double *r2_f, int64_t n)
{
    for (int64_t q = 0; q < n; q++)
        r2_f[q] = wendland_c2_f_inside(k, r2_f[q]);
}

/* W at distance r. */
static inline double wendland_c2_w(const wendland_c2_kernel *k, double r)
{
    double w, f;
    wendland_c2_eval2(k, r * r, &w, &f);
    return w;
}

/* dW/dr at distance r. */
static inline double wendland_c2_dw(const wendland_c2_kernel *k, double r)
{
    double w, f;
    wendland_c2_eval2(k, r * r, &w, &f);
    return f * r;
}

#endif
