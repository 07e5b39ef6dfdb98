/* The vector operations and the start both Krylov solvers (core/krylov.c, core/gmres.c) use. The
 * dot products are summed in index order on one thread: the same value for any
 * OpenMP setting, which keeps the iterates independent of the thread count. */
#ifndef FSI_KRYLOV_VECTORS_H
#define FSI_KRYLOV_VECTORS_H

#include <float.h>
#include <math.h>
#include <stdint.h>

#include "krylov.h"
#include "sparse_matrix.h"

static inline double krylov_dot(const double *u, const double *v, int32_t n)
{
    double s = 0.0;
    for (int32_t i = 0; i < n; i++)
        s += u[i] * v[i];
    return s;
}

static inline double krylov_norm(const double *u, int32_t n)
{
    return sqrt(krylov_dot(u, u, n));
}

/* (u, v) vanishes when it is below its own round-off: a dot product of unit vectors
 * carries errors of order eps, so |(u, v)| <= eps |u| |v| says "orthogonal". */
static inline int krylov_vanishes(double uv, double norm_u, double norm_v)
{
    return !isfinite(uv) || fabs(uv) <= DBL_EPSILON * norm_u * norm_v;
}

/* r = b - A x; returns ||r||. */
static inline double krylov_residual(const fsi_csr *a, const double *b, const double *x,
                                     double *r)
{
    fsi_csr_multiply(a, x, r);
    for (int32_t i = 0; i < a->n_rows; i++)
        r[i] = b[i] - r[i];
    return krylov_norm(r, a->n_rows);
}

/* Starts a solve: *res says converged after 0 iterations, and returns the residual's
 * scale max(||b||, ||A x0||) (krylov.h). When b is 0 the solution is x = 0, set here,
 * and 0 is returned; the caller returns *res at once. */
static inline double krylov_start(const fsi_csr *a, const double *b, double *x, int32_t n,
                                  fsi_krylov_result *res)
{
    const fsi_krylov_result start = {0, 0.0, 1, 0, "converged"};
    *res = start;
    const double norm_b = krylov_norm(b, n);
    if (norm_b == 0.0) {
        for (int32_t i = 0; i < n; i++)
            x[i] = 0.0;
        return 0.0;
    }
    /* ||A x0||, row by row (no work vector yet) */
    double sum = 0.0;
    for (int32_t i = 0; i < n; i++) {
        double row = 0.0;
        for (int64_t e = a->row_start[i]; e < a->row_start[i + 1]; e++)
            row += a->val[e] * x[a->col[e]];
        sum += row * row;
    }
    const double norm_ax = sqrt(sum);
    return norm_ax > norm_b ? norm_ax : norm_b;
}

#endif
