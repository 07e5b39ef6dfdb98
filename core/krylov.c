/* BiCGSTAB with a right preconditioner (core/krylov.h). */
#include "krylov.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "krylov_vectors.h"

enum { R, R0, P, V, S, T, PH, SH, BEST, GUESS, N_VECTORS };

/* x += alpha * u (+ omega * w when w is not NULL) */
static void update(double *x, double alpha, const double *u, double omega, const double *w,
                   int32_t n)
{
    for (int32_t i = 0; i < n; i++)
        x[i] += alpha * u[i] + (w ? omega * w[i] : 0.0);
}

/* The iterate with the smallest (updated) residual so far is kept in v[BEST]: what a
 * failed solve returns instead of a diverged last iterate. The copy costs about as
 * much as one of the ten vector updates of an iteration. */
typedef struct {
    double norm;
    int32_t n;
} best_iterate;

static void keep_if_best(best_iterate *best, double norm_r, const double *x, double *x_best)
{
    if (norm_r < best->norm) {
        best->norm = norm_r;
        memcpy(x_best, x, (size_t)best->n * sizeof *x);
    }
}

/* Once eps ||r_k|| exceeds the goal, the round-off of the updates alone keeps the
 * residual above it (the attainable accuracy of a recursive-residual method is about
 * eps max_k ||r_k||: Sleijpen & van der Vorst, Numer. Algorithms 10 (1995) 203-223):
 * iterating on cannot converge. */
static int diverged(double norm_r, double goal)
{
    return !(DBL_EPSILON * norm_r <= goal);
}

/* One BiCGSTAB run from the current x (Barrett et al. 1994, Fig. 2.10) until the
 * true residual is at most goal, max_iter iterations are done, or a breakdown.
 * NULL on the first two, else the breakdown's reason (x then holds the last good
 * iterate). *iterations counts on across runs. */
static const char *run(const fsi_csr *a, const fsi_precond *m, const double *b, double *x,
                       double goal, int max_iter, double *const *v, int *iterations,
                       best_iterate *best)
{
    const int32_t n = a->n_rows;
    double *r = v[R], *r0 = v[R0], *p = v[P], *av = v[V], *s = v[S], *t = v[T];
    double *ph = v[PH], *sh = v[SH];
    double norm_r = krylov_residual(a, b, x, r);
    keep_if_best(best, norm_r, x, v[BEST]);
    double norm_r0 = 0.0, rho_old = 1.0, alpha = 1.0, omega = 1.0;
    int fresh = 1; /* the recurrences (re)start from r */
    while (norm_r > goal) {
        if (*iterations >= max_iter)
            return NULL;
        if (fresh) {
            for (int32_t i = 0; i < n; i++)
                r0[i] = p[i] = r[i];
            norm_r0 = norm_r;
        }
        const double rho = krylov_dot(r0, r, n);
        if (krylov_vanishes(rho, norm_r0, norm_r))
            return "breakdown: rho = (r0, r) vanished";
        if (!fresh) {
            const double beta = (rho / rho_old) * (alpha / omega);
            for (int32_t i = 0; i < n; i++)
                p[i] = r[i] + beta * (p[i] - omega * av[i]);
        }
        fresh = 0;
        rho_old = rho;
        fsi_precond_apply(m, p, ph);
        fsi_csr_multiply(a, ph, av);
        const double r0v = krylov_dot(r0, av, n);
        if (krylov_vanishes(r0v, norm_r0, krylov_norm(av, n)))
            return "breakdown: (r0, A M^-1 p) vanished";
        alpha = rho / r0v;
        for (int32_t i = 0; i < n; i++)
            s[i] = r[i] - alpha * av[i];
        const double norm_s = krylov_norm(s, n);
        if (!isfinite(alpha) || diverged(norm_s, goal))
            return "diverged: ||r|| above tol ||b|| / eps";
        ++*iterations;
        if (norm_s <= goal) {
            /* Half a step is enough; the true residual decides (next loop test). */
            update(x, alpha, ph, 0.0, NULL, n);
            keep_if_best(best, norm_s, x, v[BEST]);
        } else {
            fsi_precond_apply(m, s, sh);
            fsi_csr_multiply(a, sh, t);
            const double norm_t = krylov_norm(t, n), ts = krylov_dot(t, s, n);
            if (krylov_vanishes(ts, norm_t, norm_s)) {
                update(x, alpha, ph, 0.0, NULL, n); /* the half step still lowers r to s */
                return "breakdown: omega = (t, s) / (t, t) vanished";
            }
            omega = ts / (norm_t * norm_t);
            update(x, alpha, ph, omega, sh, n);
            for (int32_t i = 0; i < n; i++)
                r[i] = s[i] - omega * t[i];
            norm_r = krylov_norm(r, n);
            if (!isfinite(omega) || diverged(norm_r, goal))
                return "diverged: ||r|| above tol ||b|| / eps";
            keep_if_best(best, norm_r, x, v[BEST]);
            if (norm_r > goal)
                continue;
        }
        /* The recursion says converged: recompute the true residual, and if it is
         * not below the goal, go on from it with fresh recurrences (residual
         * replacement; van der Vorst 1992 notes the drift of the updated residual). */
        norm_r = krylov_residual(a, b, x, r);
        fresh = 1;
    }
    return NULL;
}

fsi_krylov_result fsi_bicgstab(const fsi_csr *a, const fsi_precond *m, const double *b,
                               double *x, const fsi_krylov_settings *settings)
{
    fsi_krylov_result res;
    const int32_t n = a->n_rows;
    const double norm_b = krylov_start(a, b, x, n, &res);   /* the residual's scale */
    if (norm_b == 0.0)
        return res;
    double *w = malloc((size_t)N_VECTORS * ((size_t)n + 1) * sizeof *w);
    if (!w) {
        res.reason = "out of memory";
        res.converged = 0;
        res.rel_residual = NAN;
        return res;
    }
    double *v[N_VECTORS];
    for (int k = 0; k < N_VECTORS; k++)
        v[k] = w + (size_t)k * ((size_t)n + 1);
    const double goal = settings->tol * norm_b;
    memcpy(v[GUESS], x, (size_t)n * sizeof *x);
    best_iterate best = {INFINITY, n};
    const char *breakdown =
        run(a, m, b, x, goal, settings->max_iter, v, &res.iterations, &best);
    if (breakdown) {
        /* Restart once, from the best iterate: a new shadow residual usually gets past
         * an accidental orthogonality; a second failure means the system itself. */
        res.restarts = 1;
        memcpy(x, v[BEST], (size_t)n * sizeof *x);
        breakdown = run(a, m, b, x, goal, settings->max_iter, v, &res.iterations, &best);
    }
    res.rel_residual = krylov_residual(a, b, x, v[R]) / norm_b;
    res.converged = res.rel_residual <= settings->tol;
    /* Not converged: hand back the best of the last iterate, the best one by the
     * updated residual and the guess, by their true residuals (the updated residual
     * of a failing run can be far from the true one). */
    for (int k = BEST; k <= GUESS && !res.converged; k++) {
        const double candidate = krylov_residual(a, b, v[k], v[R]) / norm_b;
        if (candidate < res.rel_residual) {
            memcpy(x, v[k], (size_t)n * sizeof *x);
            res.rel_residual = candidate;
        }
    }
    res.reason = res.converged ? "converged" : breakdown ? breakdown : "max_iter";
    free(w);
    return res;
}
