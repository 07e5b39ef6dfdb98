/* Restarted GMRES(m) with a right preconditioner (core/krylov.h). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "krylov.h"
#include "krylov_vectors.h"

/* The Arnoldi basis of one cycle and its Hessenberg matrix, reduced to upper
 * triangular form by Givens rotations as it grows (Saad 2003, Section 6.5.3): after
 * step j the least-squares residual of the cycle is |g[j + 1]|, known without
 * forming x. */
typedef struct {
    int m;
    int32_t n;
    double *basis;   /* m + 1 vectors of n */
    double *h;       /* column j at h + j (m + 1) */
    double *cs, *sn; /* the rotations */
    double *g;       /* the rotated right-hand side beta e_1 */
    double *z, *w;   /* M^-1 v, and A M^-1 v (also the residual) */
} arnoldi;

static double *column(const arnoldi *ar, int j)
{
    return ar->h + (size_t)j * (size_t)(ar->m + 1);
}

static double *vec(const arnoldi *ar, int j)
{
    return ar->basis + (size_t)j * (size_t)ar->n;
}

/* One cycle from x with residual w = b - A x of norm beta. Returns the number of
 * basis vectors k whose least-squares solution is to be applied, and sets *stop when
 * the cycle met a breakdown. */
static int cycle(const fsi_csr *a, const fsi_precond *pc, arnoldi *ar, double beta,
                 double goal, int max_iter, int *iterations, const char **stop)
{
    const int32_t n = ar->n;
    for (int32_t i = 0; i < n; i++)
        vec(ar, 0)[i] = ar->w[i] / beta;
    memset(ar->g, 0, (size_t)(ar->m + 1) * sizeof *ar->g);
    ar->g[0] = beta;
    int k = 0;
    for (int j = 0; j < ar->m && *iterations < max_iter; j++) {
        fsi_precond_apply(pc, vec(ar, j), ar->z);
        fsi_csr_multiply(a, ar->z, ar->w);
        const double norm_az = krylov_norm(ar->w, n);
        double *hj = column(ar, j);
        /* Modified Gram-Schmidt against the basis so far. */
        for (int i = 0; i <= j; i++) {
            const double *vi = vec(ar, i);
            hj[i] = krylov_dot(ar->w, vi, n);
            for (int32_t q = 0; q < n; q++)
                ar->w[q] -= hj[i] * vi[q];
        }
        const double next = krylov_norm(ar->w, n);
        hj[j + 1] = next;
        for (int i = 0; i < j; i++) {
            const double t = ar->cs[i] * hj[i] + ar->sn[i] * hj[i + 1];
            hj[i + 1] = -ar->sn[i] * hj[i] + ar->cs[i] * hj[i + 1];
            hj[i] = t;
        }
        ++*iterations;
        const double d = hypot(hj[j], hj[j + 1]);
        /* A diagonal of R at round-off level: A M^-1 v_j lies in the span of the basis
         * (A M^-1 is singular there); the column would divide by noise. */
        if (!isfinite(d) || d <= DBL_EPSILON * norm_az) {
            *stop = "breakdown: A M^-1 singular on the Krylov space";
            return k;
        }
        ar->cs[j] = hj[j] / d;
        ar->sn[j] = hj[j + 1] / d;
        hj[j] = d;
        hj[j + 1] = 0.0;
        ar->g[j + 1] = -ar->sn[j] * ar->g[j];
        ar->g[j] = ar->cs[j] * ar->g[j];
        k = j + 1;
        /* Done when the cycle's residual reaches the goal, or when the new direction
         * vanishes (the "lucky" breakdown: the space is invariant, x is in it). */
        if (fabs(ar->g[j + 1]) <= goal || next <= DBL_EPSILON * norm_az)
            break;
        if (j + 1 < ar->m)
            for (int32_t q = 0; q < n; q++)
                vec(ar, j + 1)[q] = ar->w[q] / next;
    }
    return k;
}

/* x += M^-1 V y with R y = g (back substitution on the first k columns); 0, or -1
 * when y is not finite (x then unchanged). */
static int apply_correction(const fsi_precond *pc, arnoldi *ar, int k, double *x)
{
    double *y = ar->g; /* solved in place */
    for (int i = k - 1; i >= 0; i--) {
        double s = y[i];
        for (int j = i + 1; j < k; j++)
            s -= column(ar, j)[i] * y[j];
        y[i] = s / column(ar, i)[i];
        if (!isfinite(y[i]))
            return -1;
    }
    memset(ar->w, 0, (size_t)ar->n * sizeof *ar->w);
    for (int i = 0; i < k; i++) {
        const double *vi = vec(ar, i);
        for (int32_t q = 0; q < ar->n; q++)
            ar->w[q] += y[i] * vi[q];
    }
    fsi_precond_apply(pc, ar->w, ar->z);
    for (int32_t q = 0; q < ar->n; q++)
        x[q] += ar->z[q];
    return 0;
}

fsi_krylov_result fsi_gmres(const fsi_csr *a, const fsi_precond *pc, const double *b,
                            double *x, const fsi_krylov_settings *settings, int restart)
{
    fsi_krylov_result res;
    const int32_t n = a->n_rows;
    const double norm_b = krylov_start(a, b, x, n, &res);   /* the residual's scale */
    if (norm_b == 0.0)
        return res;
    arnoldi ar = {restart > 0 ? restart : 1, n, NULL, NULL, NULL, NULL, NULL, NULL, NULL};
    const size_t m = (size_t)ar.m;
    ar.basis = malloc((m + 1) * ((size_t)n + 1) * sizeof *ar.basis);
    ar.h = malloc((m + 1) * m * sizeof *ar.h);
    ar.cs = malloc(m * sizeof *ar.cs);
    ar.sn = malloc(m * sizeof *ar.sn);
    ar.g = malloc((m + 1) * sizeof *ar.g);
    ar.z = malloc(((size_t)n + 1) * sizeof *ar.z);
    ar.w = malloc(((size_t)n + 1) * sizeof *ar.w);
    const char *stop = NULL;
    double beta = NAN;
    if (!ar.basis || !ar.h || !ar.cs || !ar.sn || !ar.g || !ar.z || !ar.w) {
        stop = "out of memory";
    } else {
        const double goal = settings->tol * norm_b;
        beta = krylov_residual(a, b, x, ar.w);
        while (!stop && beta > goal && res.iterations < settings->max_iter) {
            const int k = cycle(a, pc, &ar, beta, goal, settings->max_iter, &res.iterations,
                                &stop);
            if (k == 0 || apply_correction(pc, &ar, k, x) != 0) {
                if (!stop)
                    stop = "breakdown: non-finite correction";
                break;
            }
            const double beta_new = krylov_residual(a, b, x, ar.w);
            /* Each cycle minimises the residual over a space that holds the zero
             * correction, so it cannot rise but by round-off: if it does, undo. */
            if (!(beta_new <= beta)) {
                for (int32_t q = 0; q < n; q++)
                    x[q] -= ar.z[q];
                stop = "breakdown: a cycle raised the residual";
                break;
            }
            /* A system without solution stagnates at its least-squares residual. */
            if (beta_new > goal && beta_new > 0.999 * beta)
                stop = "stagnated: a cycle lowered the residual by less than 0.1 %";
            beta = beta_new;
        }
    }
    res.rel_residual = beta / norm_b;
    res.converged = res.rel_residual <= settings->tol;
    res.reason = res.converged ? "converged" : stop ? stop : "max_iter";
    free(ar.basis);
    free(ar.h);
    free(ar.cs);
    free(ar.sn);
    free(ar.g);
    free(ar.z);
    free(ar.w);
    return res;
}
