/* core/coupling_acceleration: constant, Aitken and IQN-ILS acceleration of a coupling
 * window's fixed point x = H(x), on a model of the added-mass instability:
 *
 *     H(x) = b - (1/mu) M x - c x^3 (componentwise)
 *
 * with M = K^-1 (x) C: K the 1D Dirichlet Laplacian tridiag(-1, 2, -1) over N = 50
 * interface particles (its inverse is the added mass of a slender channel, largest for
 * the smoothest mode, as in Causin, Gerbeau & Nobile 2005) and C a 2 x 2 SPD coupling of
 * the two components; mu is chosen so that the spectral radius of M / mu is 4 (the
 * fluid's added mass four times the structure's in the worst mode).
 *
 *   - c = 0: omega = 1 diverges; Aitken and IQN-ILS converge to |r| <= 1e-8 |H(x)| and
 *     to the solution of (I + M/mu) x = b found by Gaussian elimination.
 *   - 20 windows with slowly changing b, each from the last one's x: IQN-ILS needs fewer
 *     iterations than Aitken, and with reused windows fewer than without (printed).
 *   - c > 0: IQN-ILS converges to Newton's solution.
 *   - filter: inputs in a 2D affine subspace give at most two independent columns, the
 *     third is dropped and the step is exact; a repeated input adds no column.
 *   - ids: another order or another count drops the history (begin returns 1); the same
 *     ids keep it; a window begun again without being ended loses its own columns.
 *   - invalid settings are refused with a message. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "coupling_acceleration.h"

#include "unit_check.h"
#include "unit_random.h"
#include "unit_vectors.h"

enum { N = 50, NCOMP = 2, M_MAX = N * NCOMP };

static const double TOL = 1e-8;      /* |r| <= TOL |H(x)| ends a window */
static const double RHO = 4.0;       /* spectral radius of M / mu */

typedef struct {
    int m;
    double mat[M_MAX * M_MAX];  /* M / mu, row-major */
    double c;                   /* cubic term */
    double b[M_MAX];
} model;

/* M / mu for n particles: (K^-1)_pq = min(p,q) (n+1-max(p,q)) / (n+1) (1-based) times
 * C = [[1, 0.3], [0.3, 0.5]], scaled by the closed-form largest eigenvalues
 * 1 / (4 sin^2(pi / (2 (n+1)))) of K^-1 and (1.5 + sqrt(0.61)) / 2 of C to radius RHO. */
static void model_init(model *p, int n, double c)
{
    static const double cc[2][2] = {{1.0, 0.3}, {0.3, 0.5}};
    const double s = sin(M_PI / (2.0 * (n + 1)));
    const double lambda_max = 1.0 / (4.0 * s * s) * (1.5 + sqrt(0.61)) / 2.0;
    p->m = n * NCOMP;
    p->c = c;
    for (int i = 0; i < p->m; i++)
        for (int j = 0; j < p->m; j++) {
            const int pi = i / NCOMP + 1, pj = j / NCOMP + 1;
            const int lo = pi < pj ? pi : pj, hi = pi < pj ? pj : pi;
            const double kinv = (double)lo * (n + 1 - hi) / (n + 1);
            p->mat[i * p->m + j] = RHO / lambda_max * kinv * cc[i % NCOMP][j % NCOMP];
        }
    for (int i = 0; i < p->m; i++)
        p->b[i] = 2.0 * uniform() - 1.0;
}

static void apply_h(const model *p, const double *x, double *out)
{
    for (int i = 0; i < p->m; i++) {
        double s = 0.0;
        for (int j = 0; j < p->m; j++)
            s += p->mat[i * p->m + j] * x[j];
        out[i] = p->b[i] - s - p->c * x[i] * x[i] * x[i];
    }
}

/* Solves a x = y (a: m x m row-major, destroyed) by Gaussian elimination with partial
 * pivoting; y becomes x. */
static void gauss_solve(double *a, double *y, int m)
{
    for (int k = 0; k < m; k++) {
        int piv = k;
        for (int i = k + 1; i < m; i++)
            if (fabs(a[i * m + k]) > fabs(a[piv * m + k]))
                piv = i;
        for (int j = 0; j < m; j++) {
            const double t = a[k * m + j];
            a[k * m + j] = a[piv * m + j];
            a[piv * m + j] = t;
        }
        const double t = y[k];
        y[k] = y[piv];
        y[piv] = t;
        for (int i = k + 1; i < m; i++) {
            const double f = a[i * m + k] / a[k * m + k];
            for (int j = k; j < m; j++)
                a[i * m + j] -= f * a[k * m + j];
            y[i] -= f * y[k];
        }
    }
    for (int k = m - 1; k >= 0; k--) {
        for (int j = k + 1; j < m; j++)
            y[k] -= a[k * m + j] * y[j];
        y[k] /= a[k * m + k];
    }
}

/* The root of F(x) = x - H(x) by Newton's method, J_F = I + M/mu + 3 c diag(x^2). */
static void newton_solve(const model *p, double *x)
{
    static double jac[M_MAX * M_MAX];
    double h[M_MAX], f[M_MAX];
    const int m = p->m;
    memset(x, 0, (size_t)m * sizeof *x);
    for (int it = 0; it < 50; it++) {
        apply_h(p, x, h);
        for (int i = 0; i < m; i++)
            f[i] = h[i] - x[i];            /* -F */
        if (norm2(f, m) <= 1e-15 * norm2(p->b, m))
            return;
        for (int i = 0; i < m; i++)
            for (int j = 0; j < m; j++)
                jac[i * m + j] = p->mat[i * m + j] + (i == j) * (1.0 + 3.0 * p->c * x[i] * x[i]);
        gauss_solve(jac, f, m);
        for (int i = 0; i < m; i++)
            x[i] += f[i];
    }
}

static fsi_accel *make(fsi_accel_kind kind, double omega0, int reuse, int max_columns)
{
    const fsi_accel_settings s = {kind, omega0, reuse, 1e-10, max_columns};
    char msg[200] = "";
    fsi_accel *a = fsi_accel_create(&s, msg, sizeof msg);
    CHECK(a != NULL, "valid settings refused: %s", msg);
    if (!a)
        exit(unit_check_report("test_coupling_acceleration"));
    return a;
}

static int32_t ids[N];

/* Iterates one window from x until |r| <= TOL |H(x)|, at most max_iter evaluations of
 * H; x becomes the accepted H(x). Returns the evaluations, or -1 when not converged.
 * *max_cols (when not NULL) gets the most columns seen. */
static int window(fsi_accel *a, const model *p, double *x, int max_iter, int *max_cols)
{
    double xt[M_MAX], xn[M_MAX], r[M_MAX];
    const int m = p->m;
    for (int it = 1; it <= max_iter; it++) {
        apply_h(p, x, xt);
        for (int i = 0; i < m; i++)
            r[i] = xt[i] - x[i];
        if (!(norm2(r, m) <= 1e9 * norm2(p->b, m)))
            return -1;                     /* diverged */
        if (norm2(r, m) <= TOL * norm2(xt, m)) {
            memcpy(x, xt, (size_t)m * sizeof *x);
            fsi_accel_end_window(a);
            return it;
        }
        CHECK(fsi_accel_next(a, x, xt, xn) == 0, "fsi_accel_next failed in a window");
        if (max_cols && fsi_accel_columns(a) > *max_cols)
            *max_cols = fsi_accel_columns(a);
        memcpy(x, xn, (size_t)m * sizeof *x);
    }
    fsi_accel_end_window(a);
    return -1;
}

/* The linear model in one window from x = 0: constant omega = 1 diverges, Aitken and
 * IQN-ILS converge to the direct solution. */
static void single_window(void)
{
    static model p;
    static double a_mat[M_MAX * M_MAX];
    model_init(&p, N, 0.0);
    const int m = p.m;
    double exact[M_MAX];
    memcpy(exact, p.b, sizeof exact);
    for (int i = 0; i < m * m; i++)
        a_mat[i] = p.mat[i] + (i % (m + 1) == 0);
    gauss_solve(a_mat, exact, m);

    /* omega = 1: the smoothest mode's error is multiplied by -RHO = -4 per iteration;
     * after 20 iterations 4^20 = 1e12 times, so a growth of 1e6 holds unless b had less
     * than 1e-6 of its norm on that mode (it has about 1/sqrt(m)). */
    fsi_accel *a = make(FSI_ACCEL_CONSTANT, 1.0, 0, 0);
    double x[M_MAX] = {0}, xt[M_MAX], xn[M_MAX], res[M_MAX], r0 = 0.0, r = 0.0;
    CHECK(fsi_accel_begin_window(a, N, NCOMP, ids) == 0, "first window: not 0");
    for (int it = 0; it <= 20; it++) {
        apply_h(&p, x, xt);
        for (int i = 0; i < m; i++)
            res[i] = xt[i] - x[i];
        r = norm2(res, m);
        if (it == 0)
            r0 = r;
        fsi_accel_next(a, x, xt, xn);
        memcpy(x, xn, sizeof x);
    }
    CHECK(r > 1e6 * r0, "omega = 1 did not diverge: |r| from %g to %g in 20 iterations", r0, r);
    CHECK(fsi_accel_last_omega(a) == 1.0, "constant: omega %g", fsi_accel_last_omega(a));
    fsi_accel_free(a);

    /* Aitken and IQN-ILS from omega0 = 0.2 (stable for radius < 2 / 0.2 - 1 = 9). The
     * accepted x = H(x_i) has error (M/mu)(x* - x_i), and x* - x_i = (I + M/mu)^-1 r_i
     * with |(I + M/mu)^-1| <= 1 (M SPD): |x - x*| <= RHO |r| <= 4 TOL |x| (+ round-off:
     * 5 TOL). */
    for (int kind = FSI_ACCEL_AITKEN; kind <= FSI_ACCEL_IQN_ILS; kind++) {
        a = make((fsi_accel_kind)kind, 0.2, 0, M_MAX);
        memset(x, 0, sizeof x);
        fsi_accel_begin_window(a, N, NCOMP, ids);
        const int its = window(a, &p, x, 500, NULL);
        const double err = rel_diff(x, exact, m);
        const char *name = kind == FSI_ACCEL_AITKEN ? "Aitken" : "IQN-ILS";
        CHECK(its > 0, "%s did not converge in 500 iterations", name);
        CHECK(err <= 5.0 * TOL, "%s: relative error %g against the direct solution", name, err);
        printf("one window, radius %g: %s %d iterations, relative error %.2e\n", RHO, name,
               its, err);
        fsi_accel_free(a);
    }
    /* Aitken's first step uses omega0, the second its own factor. */
    a = make(FSI_ACCEL_AITKEN, 0.2, 0, 0);
    memset(x, 0, sizeof x);
    fsi_accel_begin_window(a, N, NCOMP, ids);
    apply_h(&p, x, xt);
    fsi_accel_next(a, x, xt, xn);
    CHECK(fsi_accel_last_omega(a) == 0.2, "Aitken's first omega %g", fsi_accel_last_omega(a));
    apply_h(&p, xn, xt);
    fsi_accel_next(a, xn, xt, x);
    CHECK(fsi_accel_last_omega(a) != 0.2 && isfinite(fsi_accel_last_omega(a)),
          "Aitken's second omega %g", fsi_accel_last_omega(a));
    fsi_accel_free(a);
}

/* 20 windows, b_k = b_0 + k db with |db| about 1 % of |b_0|, each from the last x.
 * Returns the total evaluations of H (-1 if a window did not converge). */
static int window_sequence(fsi_accel *a, model *p, int *max_cols)
{
    double b0[M_MAX], db[M_MAX], x[M_MAX] = {0};
    const uint64_t seed = rng_state;
    memcpy(b0, p->b, sizeof b0);
    for (int i = 0; i < p->m; i++)
        db[i] = 0.01 * (2.0 * uniform() - 1.0);
    rng_state = seed;                  /* every method sees the same sequence */
    int total = 0;
    for (int k = 0; k < 20; k++) {
        for (int i = 0; i < p->m; i++)
            p->b[i] = b0[i] + k * db[i];
        fsi_accel_begin_window(a, N, NCOMP, ids);
        const int its = window(a, p, x, 500, max_cols);
        if (its < 0)
            total = -1;
        if (total >= 0)
            total += its;
    }
    memcpy(p->b, b0, sizeof b0);
    return total;
}

static void sequences(void)
{
    static model p;
    model_init(&p, N, 0.0);
    enum { MAX_COLUMNS = 40, FEW_COLUMNS = 5 };
    int cols_aitken = 0, cols0 = 0, cols8 = 0, cols_few = 0;
    fsi_accel *aitken = make(FSI_ACCEL_AITKEN, 0.2, 0, 0);
    fsi_accel *iqn0 = make(FSI_ACCEL_IQN_ILS, 0.2, 0, MAX_COLUMNS);
    fsi_accel *iqn8 = make(FSI_ACCEL_IQN_ILS, 0.2, 8, MAX_COLUMNS);
    fsi_accel *few = make(FSI_ACCEL_IQN_ILS, 0.2, 8, FEW_COLUMNS);
    const int n_aitken = window_sequence(aitken, &p, &cols_aitken);
    const int n0 = window_sequence(iqn0, &p, &cols0);
    const int n8 = window_sequence(iqn8, &p, &cols8);
    const int n_few = window_sequence(few, &p, &cols_few);
    printf("20 windows, slowly changing b: Aitken %d iterations, IQN-ILS reuse 0 %d "
           "(most columns %d), reuse 8 %d (most columns %d of %d), reuse 8 with at most %d "
           "columns %d\n",
           n_aitken, n0, cols0, n8, cols8, MAX_COLUMNS, FEW_COLUMNS, n_few);
    CHECK(n_aitken > 0 && n0 > 0 && n8 > 0 && n_few > 0, "a window did not converge: %d %d %d %d",
          n_aitken, n0, n8, n_few);
    CHECK(n8 < n_aitken, "IQN-ILS (reuse 8) %d iterations, Aitken %d", n8, n_aitken);
    CHECK(n0 < n_aitken, "IQN-ILS (reuse 0) %d iterations, Aitken %d", n0, n_aitken);
    CHECK(n8 < n0, "IQN-ILS reuse 8 %d iterations, reuse 0 %d", n8, n0);
    CHECK(cols_aitken == 0, "Aitken has %d columns", cols_aitken);
    CHECK(cols8 <= MAX_COLUMNS && cols8 > cols0, "columns: reuse 8 at most %d, reuse 0 %d",
          cols8, cols0);
    CHECK(cols_few == FEW_COLUMNS, "limit %d: at most %d columns", FEW_COLUMNS, cols_few);
    fsi_accel_free(few);
    fsi_accel_free(aitken);
    fsi_accel_free(iqn0);
    fsi_accel_free(iqn8);
}

/* c = 0.5: at the solution |c x^3| is about 20 % of |x| (max |x_i| about 0.78). The
 * accepted H(x_i) is within |J_H| |x_i - x*| of x*, with |x_i - x*| <= |J_F^-1| |r| <=
 * |r| (J_F = I + M/mu + 3c diag(x^2) >= I) and |J_H| <= RHO + 3c max x^2 < 5, to first
 * order: 5 TOL, 1e-7 with room for the second-order term. */
static void nonlinear(void)
{
    static model p;
    model_init(&p, N, 0.5);
    fsi_accel *a = make(FSI_ACCEL_IQN_ILS, 0.2, 8, 40);
    double x[M_MAX] = {0}, exact[M_MAX];
    const double b1 = p.b[0];
    int total = 0;
    for (int k = 0; k < 5; k++) {
        p.b[0] = b1 + 0.02 * k;
        fsi_accel_begin_window(a, N, NCOMP, ids);
        const int its = window(a, &p, x, 200, NULL);
        CHECK(its > 0, "nonlinear window %d did not converge", k);
        total += its;
        newton_solve(&p, exact);
        const double err = rel_diff(x, exact, p.m);
        CHECK(err <= 1e-7, "nonlinear window %d: relative error %g against Newton", k, err);
    }
    printf("nonlinear (c = 0.5), 5 windows: IQN-ILS reuse 8 %d iterations\n", total);
    fsi_accel_free(a);
}

/* H(x) = x* - (M/mu)(x - x*) fed with inputs x* + s_i, s_i in span{e1, e2}: every
 * r_i = -(I + M/mu) s_i lies in a 2D space, so of three columns one is dependent (its
 * remainder after orthogonalisation is round-off, 1e-16 of its norm, far below 1e-10)
 * and must go. With two independent columns the least-squares model is exact on the
 * plane: x_next = x* up to round-off amplified by the conditioning of V (1e-10 leaves
 * four orders above it). */
static void filter(void)
{
    static model p;
    model_init(&p, N, 0.0);
    const int m = p.m;
    double xs[M_MAX], e1[M_MAX], e2[M_MAX], x[M_MAX], xt[M_MAX], xn[M_MAX];
    for (int i = 0; i < m; i++) {
        xs[i] = 2.0 * uniform() - 1.0;
        e1[i] = 2.0 * uniform() - 1.0;
        e2[i] = 2.0 * uniform() - 1.0;
    }
    /* b = x* + (M/mu) x* makes x* the fixed point. */
    static const double coef[4][2] = {{1.0, 0.0}, {0.3, 1.0}, {-0.7, 0.4}, {0.5, -0.8}};
    static const int expect[4] = {0, 1, 2, 2};
    for (int i = 0; i < m; i++) {
        p.b[i] = xs[i];
        for (int j = 0; j < m; j++)
            p.b[i] += p.mat[i * m + j] * xs[j];
    }
    fsi_accel *a = make(FSI_ACCEL_IQN_ILS, 0.5, 0, 10);
    fsi_accel_begin_window(a, N, NCOMP, ids);
    for (int it = 0; it < 4; it++) {
        for (int i = 0; i < m; i++)
            x[i] = xs[i] + coef[it][0] * e1[i] + coef[it][1] * e2[i];
        apply_h(&p, x, xt);
        fsi_accel_next(a, x, xt, xn);
        CHECK(fsi_accel_columns(a) == expect[it], "plane, iteration %d: %d columns, not %d", it,
              fsi_accel_columns(a), expect[it]);
        const double err = rel_diff(xn, xs, m);
        CHECK(it < 2 || err <= 1e-10, "plane, iteration %d: |x_next - x*| / |x*| = %g", it, err);
    }
    fsi_accel_end_window(a);

    /* The same input twice: the second gives the column 0, which goes, and the same step. */
    double first[M_MAX];
    fsi_accel_begin_window(a, N, NCOMP, ids);
    memset(x, 0, sizeof x);
    apply_h(&p, x, xt);
    fsi_accel_next(a, x, xt, xn);
    memcpy(x, xn, sizeof x);
    apply_h(&p, x, xt);
    fsi_accel_next(a, x, xt, first);
    CHECK(fsi_accel_columns(a) == 1, "distinct inputs: %d columns, not 1", fsi_accel_columns(a));
    fsi_accel_next(a, x, xt, xn);
    CHECK(all_finite(xn, m), "repeated input: x_next not finite");
    CHECK(fsi_accel_columns(a) == 1, "repeated input: %d columns, not 1", fsi_accel_columns(a));
    CHECK(rel_diff(xn, first, m) <= 1e-14, "repeated input: a different step (%g)",
          rel_diff(xn, first, m));
    fsi_accel_end_window(a);
    fsi_accel_free(a);
}

/* The history lives as long as the interface does. */
static void interface_changes(void)
{
    static model p, small;
    model_init(&p, N, 0.0);
    model_init(&small, 40, 0.0);
    int32_t reversed[N];
    for (int i = 0; i < N; i++)
        reversed[i] = ids[N - 1 - i];
    fsi_accel *a = make(FSI_ACCEL_IQN_ILS, 0.2, 8, 40);
    double x[M_MAX] = {0}, xt[M_MAX], xn[M_MAX];
    CHECK(fsi_accel_begin_window(a, N, NCOMP, ids) == 0, "first window: not 0");
    CHECK(window(a, &p, x, 200, NULL) > 0, "window 1 did not converge");
    const int kept = fsi_accel_columns(a);
    CHECK(kept > 0, "no columns kept after an accepted window with reuse 8");
    p.b[3] += 0.01;
    CHECK(fsi_accel_begin_window(a, N, NCOMP, ids) == 0, "same ids: not 0");
    CHECK(fsi_accel_columns(a) == kept, "same ids: %d columns, %d before", fsi_accel_columns(a),
          kept);
    CHECK(window(a, &p, x, 200, NULL) > 0, "window 2 did not converge");

    /* Begun, iterated, begun again without being accepted: its own columns go. */
    const int before = fsi_accel_columns(a);
    p.b[5] += 0.01;
    fsi_accel_begin_window(a, N, NCOMP, ids);
    for (int it = 0; it < 3; it++) {
        apply_h(&p, x, xt);
        fsi_accel_next(a, x, xt, xn);
        memcpy(x, xn, sizeof x);
    }
    CHECK(fsi_accel_columns(a) > before || fsi_accel_columns(a) == 40,
          "three iterations added no column (%d, %d before)", fsi_accel_columns(a), before);
    CHECK(fsi_accel_begin_window(a, N, NCOMP, ids) == 0, "same ids again: not 0");
    CHECK(fsi_accel_columns(a) <= before && fsi_accel_columns(a) > 0,
          "a window not accepted: %d columns, %d before it", fsi_accel_columns(a), before);
    CHECK(window(a, &p, x, 200, NULL) > 0, "repeated window did not converge");

    /* Same ids in another order: history dropped. */
    CHECK(fsi_accel_begin_window(a, N, NCOMP, reversed) == 1, "reordered ids: not 1");
    CHECK(fsi_accel_columns(a) == 0, "reordered ids: %d columns", fsi_accel_columns(a));
    CHECK(window(a, &p, x, 200, NULL) > 0, "window after reordering did not converge");
    /* Fewer particles. */
    double y[M_MAX] = {0};
    CHECK(fsi_accel_begin_window(a, 40, NCOMP, ids) == 1, "40 particles: not 1");
    CHECK(fsi_accel_columns(a) == 0, "40 particles: %d columns", fsi_accel_columns(a));
    CHECK(window(a, &small, y, 200, NULL) > 0, "window of 40 particles did not converge");
    CHECK(fsi_accel_begin_window(a, 40, NCOMP, ids) == 0, "40 particles again: not 1");
    CHECK(fsi_accel_columns(a) > 0, "40 particles again: no columns");
    fsi_accel_end_window(a);
    /* Back to 50 (memory of the first window reused), and another ncomp. */
    CHECK(fsi_accel_begin_window(a, N, NCOMP, ids) == 1, "50 particles again: not 1");
    CHECK(window(a, &p, x, 200, NULL) > 0, "window of 50 particles did not converge");
    CHECK(fsi_accel_begin_window(a, N / 2, 2 * NCOMP, ids) == 1, "ncomp 4: not 1");
    CHECK(fsi_accel_columns(a) == 0, "ncomp 4: %d columns", fsi_accel_columns(a));
    CHECK(fsi_accel_begin_window(a, -1, NCOMP, ids) == -1, "n = -1 accepted");
    CHECK(fsi_accel_next(a, x, xt, xn) == -1, "next without a window accepted");
    fsi_accel_free(a);
}

static void invalid_settings(void)
{
    static const fsi_accel_settings bad[] = {
        {FSI_ACCEL_CONSTANT, 0.0, 0, 1e-10, 10},   {FSI_ACCEL_AITKEN, -0.5, 0, 1e-10, 10},
        {FSI_ACCEL_AITKEN, 1.5, 0, 1e-10, 10},     {FSI_ACCEL_IQN_ILS, NAN, 0, 1e-10, 10},
        {FSI_ACCEL_IQN_ILS, 0.5, -1, 1e-10, 10},   {FSI_ACCEL_IQN_ILS, 0.5, 2, 1e-10, 0},
        {FSI_ACCEL_IQN_ILS, 0.5, 2, -1.0, 10},     {(fsi_accel_kind)7, 0.5, 0, 1e-10, 10},
    };
    for (size_t k = 0; k < sizeof bad / sizeof bad[0]; k++) {
        char msg[200] = "";
        fsi_accel *a = fsi_accel_create(&bad[k], msg, sizeof msg);
        CHECK(a == NULL && msg[0] != '\0', "invalid settings %zu accepted or without a message",
              k);
        fsi_accel_free(a);
    }
    char msg[200] = "";
    const fsi_accel_settings ok = {FSI_ACCEL_AITKEN, 1.0, 0, 0.0, 0};
    fsi_accel *a = fsi_accel_create(&ok, msg, sizeof msg);
    CHECK(a != NULL, "Aitken with omega0 = 1 and max_columns 0 refused: %s", msg);
    fsi_accel_free(a);
    CHECK(fsi_accel_create(&bad[5], NULL, 0) == NULL, "invalid settings without msg accepted");
}

/* A checkpoint (fsi_accel_save / fsi_accel_restore, docs/checkpoints.md): an IQN-ILS
 * acceleration saved after 6 windows of the sequence and restored into a new one goes
 * on bit for bit as the saved one does (same iterations, same x, memcmp). */
static void save_restore(void)
{
    model p;
    model_init(&p, N, 0.0);
    double b0[M_MAX], x[M_MAX] = {0}, x_saved[M_MAX];
    memcpy(b0, p.b, sizeof b0);
    fsi_accel *a = make(FSI_ACCEL_IQN_ILS, 0.2, 8, 40);
    fsi_state st = {0};
    int its_a[12], its_b[12];
    for (int k = 0; k < 12; k++) {
        if (k == 6) {
            CHECK(fsi_accel_save(a, &st, "accel.") == 0, "fsi_accel_save");
            memcpy(x_saved, x, sizeof x);
        }
        for (int i = 0; i < p.m; i++)
            p.b[i] = b0[i] * (1.0 + 0.01 * k);
        fsi_accel_begin_window(a, N, NCOMP, ids);
        its_a[k] = window(a, &p, x, 500, NULL);
    }
    double x_a[M_MAX];
    memcpy(x_a, x, sizeof x);
    fsi_accel *b = make(FSI_ACCEL_IQN_ILS, 0.2, 8, 40);
    CHECK(fsi_accel_restore(b, &st, "accel.") == 0, "fsi_accel_restore");
    memcpy(x, x_saved, sizeof x);
    int same = 1;
    for (int k = 6; k < 12; k++) {
        for (int i = 0; i < p.m; i++)
            p.b[i] = b0[i] * (1.0 + 0.01 * k);
        fsi_accel_begin_window(b, N, NCOMP, ids);
        its_b[k] = window(b, &p, x, 500, NULL);
        same &= its_b[k] == its_a[k];
    }
    CHECK(same, "the restored acceleration takes the same iterations per window");
    CHECK(memcmp(x, x_a, (size_t)p.m * sizeof *x) == 0,
          "the restored acceleration ends bit for bit where the saved one did");
    CHECK(fsi_accel_restore(b, &(fsi_state){0}, "accel.") != 0,
          "restoring from an empty state is refused");
    fsi_state_free(&st);
    fsi_accel_free(a);
    fsi_accel_free(b);
    memcpy(p.b, b0, sizeof b0);
}

int main(void)
{
    rng_state = 20240611;
    for (int i = 0; i < N; i++)
        ids[i] = 1000 + 3 * i;
    single_window();
    sequences();
    nonlinear();
    filter();
    interface_changes();
    invalid_settings();
    save_restore();
    return unit_check_report("test_coupling_acceleration");
}
