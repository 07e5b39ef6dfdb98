/* The truncated, shifted Gaussian kernel of 000 Eq. 17 (ULPH's influence function),
 *
 *     w(r) = alpha_d (exp(-(r/h)^2) - C)   for r < delta,   0 beyond,
 *
 * with the smoothing length h (000: h = 1.2 dx), the support radius
 * delta = q h (000: q = 3) and the shift C = exp(-q^2) (000: C = e^-9), so that w
 * falls continuously to zero at the edge of the support. alpha_d normalises w over
 * its support, integral of w dV = 1 in d dimensions:
 *
 *     d = 2: alpha = 1 / (pi h^2 (1 - (1 + q^2) e^(-q^2)))
 *            (000 Eq. 18 for q = 3: 1 / (pi h^2 (1 - 10 e^-9)))
 *     d = 3: alpha = 1 / (h^3 (pi^(3/2) erf(q) - 2 pi q e^(-q^2) - 4/3 pi q^3 e^(-q^2)))
 *
 * (the integral of the Gaussian over the ball of radius q h less C times the ball's
 * volume). The non-local operators (ulph_operators.h) do not depend on alpha: it
 * cancels between M^-1 and the sums; the density filter (000 Eq. 24) does not
 * either. It matters for plain kernel sums. */
#ifndef FSI_GAUSSIAN_KERNEL_H
#define FSI_GAUSSIAN_KERNEL_H

#include <math.h>
#include <stdint.h>

#include "fast_exp.h"

typedef struct {
    double h;               /* smoothing length [m] */
    double support_factor;  /* q = delta / h */
    double support;         /* delta = q h [m] */
    double support2;        /* delta^2 [m^2] */
    double shift;           /* C = exp(-q^2) */
    double alpha;           /* alpha_d [1/m^DIM] */
    double inv_h2;          /* 1 / h^2 [1/m^2] */
} gaussian_kernel;

/* The normalisation alpha_d for dimension dim (2 or 3), smoothing length h and
 * support factor q; 0 for another dimension or non-positive h or q. */
double gaussian_kernel_normalisation(int dim, double h, double q);

/* Sets up the kernel of the build's dimension (FSI_DIM). Returns 0, or -1 when h or
 * support_factor is not a positive finite number (k is then zeroed: w = 0). */
int gaussian_kernel_init(gaussian_kernel *k, double h, double support_factor);

/* w at squared distance r2 (what the neighbour search returns: no square root).
 * Never negative: the difference exp(-r2/h^2) - C can round below zero just inside
 * the support. */
static inline double gaussian_kernel_w2(const gaussian_kernel *k, double r2)
{
    if (!(r2 < k->support2))
        return 0.0;
    const double w = fast_exp_neg(r2 * k->inv_h2) - k->shift;
    return w > 0.0 ? k->alpha * w : 0.0;
}

/* w over a row: r2_w[q] = w(r2_w[q]) for n squared distances all below the support's
 * square, without branches (a loop that vectorises where the target has a gather,
 * e.g. -mavx2, for the table of fast_exp.h); the same values as gaussian_kernel_w2. */
static inline void gaussian_kernel_w2_row(const gaussian_kernel *k, double *r2_w, int64_t n)
{
    for (int64_t q = 0; q < n; q++) {
        /* Both sides of each choice computed first: a pure select, no branch. */
        const double t = r2_w[q] * k->inv_h2, t_max = 700.0;
        const double w = fast_exp_neg_unchecked(t < t_max ? t : t_max) - k->shift;
        const double aw = k->alpha * w;
        r2_w[q] = w > 0.0 ? aw : 0.0;
    }
}

/* w at distance r. */
static inline double gaussian_kernel_w(const gaussian_kernel *k, double r)
{
    return gaussian_kernel_w2(k, r * r);
}

#endif
