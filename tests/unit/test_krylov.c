/* core/sparse_matrix, core/preconditioner, core/krylov, core/gmres: the sparse solve of the ISPH
 * pressure Poisson equation (issue #21), checked against UMFPACK's direct solution
 * (unit_umfpack.h) on matrices that look like the PPE (unit_ppe_matrices.h):
 *
 *   - CSR building: triplets (any order, duplicates) and rows give the same matrix;
 *     A x against a dense product; the diagonal; bad indices refused. Set-up
 *     refuses a zero diagonal and a vanishing ILU(0) pivot, naming the row.
 *   - BiCGSTAB with Jacobi and ILU(0) on the 5-point Laplacian (symmetric) and on a
 *     non-symmetric SPH Laplacian of a jittered lattice with Dirichlet rows: true
 *     relative residual <= tol, relative error against UMFPACK <= 10 tol cond_2(A)
 *     (the bound ||dx|| / ||x|| <= cond ||r|| / ||b||, with 10 for the estimate of
 *     cond_2 by power iteration, which approaches it from below), and ILU(0) needs
 *     fewer iterations than Jacobi.
 *   - warm starts: from UMFPACK's solution 0 or 1 iterations; from it plus 1e-3 noise
 *     fewer iterations than from zero.
 *   - a singular PPE (no Dirichlet row, random right-hand side: no solution) is
 *     reported as not converged with a reason, and the x returned is finite and no
 *     worse than the start.
 *   - GMRES(30) the same against UMFPACK and on the singular PPE; b = 0 gives x = 0.
 *   - A x and a Jacobi solve are the same to the bit on 1 and 2 threads.
 * It prints the iterations, residuals and times at 10 000 and 40 000 unknowns
 * (BiCGSTAB and GMRES(30) with Jacobi and ILU(0), UMFPACK: docs/isph.md, "Pressure solve"); no time is asserted. */
#include <math.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "krylov.h"
#include "preconditioner.h"
#include "sparse_matrix.h"
#include "timers.h"

#include "unit_check.h"
#include "unit_ppe_matrices.h"
#include "unit_random.h"
#include "unit_umfpack.h"
#include "unit_vectors.h"

static const double TOL = 1e-8;
static const int GMRES_RESTART = 30;

/* The two solvers behind one call: 0 BiCGSTAB, 1 GMRES(30). */
static fsi_krylov_result solve(int solver, const fsi_csr *a, const fsi_precond *m,
                               const double *b, double *x, const fsi_krylov_settings *s)
{
    return solver == 0 ? fsi_bicgstab(a, m, b, x, s) : fsi_gmres(a, m, b, x, s, GMRES_RESTART);
}

static const char *solver_name(int solver)
{
    return solver == 0 ? "BiCGSTAB" : "GMRES(30)";
}

/* y = A^T x (the tests' own loop, for the condition estimate). */
static void multiply_transposed(const fsi_csr *a, const double *x, double *y)
{
    memset(y, 0, (size_t)a->n_cols * sizeof *y);
    for (int32_t i = 0; i < a->n_rows; i++)
        for (int64_t k = a->row_start[i]; k < a->row_start[i + 1]; k++)
            y[a->col[k]] += a->val[k] * x[i];
}

/* cond_2(A) = sigma_max / sigma_min, each by 40 power iterations (on A^T A and on
 * A^-1 A^-T through the LU): a lower estimate, within a few per cent here. */
static double condition_estimate(const fsi_csr *a, unit_lu *lu)
{
    const int n = a->n_rows;
    double *u = malloc((size_t)n * sizeof *u), *w = malloc((size_t)n * sizeof *w);
    double sigma[2];
    for (int pass = 0; pass < 2; pass++) {
        uint64_t seed = 7;
        for (int i = 0; i < n; i++)
            u[i] = unit_uniform(&seed) - 0.5;
        double lambda = 0.0;
        for (int it = 0; it < 40; it++) {
            const double nu = norm2(u, n);
            for (int i = 0; i < n; i++)
                u[i] /= nu;
            if (pass == 0) {
                fsi_csr_multiply(a, u, w);
                multiply_transposed(a, w, u);
            } else {
                unit_lu_solve(lu, u, w, 1);
                unit_lu_solve(lu, w, u, 0);
            }
            lambda = norm2(u, n);
        }
        sigma[pass] = sqrt(lambda);
    }
    free(u);
    free(w);
    return sigma[0] * sigma[1];
}

static void test_building(void)
{
    /* A 3 x 4 matrix given as shuffled triplets with a duplicate, and as rows. */
    const int32_t ti[] = {2, 0, 1, 0, 2, 0, 2};
    const int32_t tj[] = {3, 2, 1, 0, 0, 2, 3};
    const double tv[] = {1.0, 2.0, 3.0, 4.0, 5.0, 0.5, 2.5};
    const double dense[3][4] = {{4, 0, 2.5, 0}, {0, 3, 0, 0}, {5, 0, 0, 3.5}};
    fsi_csr a, b;
    fsi_csr_init(&a);
    fsi_csr_init(&b);
    CHECK(fsi_csr_from_triplets(&a, 3, 4, 7, ti, tj, tv) == 0, "triplets refused");
    CHECK(a.nnz == 5, "triplets: %lld entries, expected 5 (duplicates summed)", (long long)a.nnz);
    CHECK(fsi_csr_begin(&b, 3, 4, 0) == 0, "begin refused");
    for (int i = 0; i < 3; i++) {
        int32_t c[4];
        double v[4];
        int k = 0;
        for (int j = 3; j >= 0; j--)   /* reversed: the row must come out sorted */
            if (dense[i][j] != 0.0)
                c[k] = j, v[k++] = dense[i][j];
        CHECK(fsi_csr_append_row(&b, k, c, v) == 0, "row %d refused", i);
    }
    CHECK(fsi_csr_complete(&b), "rows: not complete after 3 rows");
    const int32_t extra = 0;
    const double one = 1.0;
    CHECK(fsi_csr_append_row(&b, 1, &extra, &one) == -1, "a 4th row of 3 accepted");
    CHECK(a.nnz == b.nnz && memcmp(a.row_start, b.row_start, 4 * sizeof *a.row_start) == 0 &&
              memcmp(a.col, b.col, (size_t)a.nnz * sizeof *a.col) == 0 &&
              memcmp(a.val, b.val, (size_t)a.nnz * sizeof *a.val) == 0,
          "triplets and rows give different matrices");
    const double x[4] = {1.0, -2.0, 0.25, 3.0};
    double y[3], d[3];
    fsi_csr_multiply(&a, x, y);
    for (int i = 0; i < 3; i++) {
        double s = 0.0;
        for (int j = 0; j < 4; j++)
            s += dense[i][j] * x[j];
        CHECK(fabs(y[i] - s) <= 1e-15 * fabs(s), "A x row %d: %.17g, dense %.17g", i, y[i], s);
    }
    fsi_csr_diagonal(&a, d);
    CHECK(d[0] == 4.0 && d[1] == 3.0 && d[2] == 0.0, "diagonal %g %g %g, expected 4 3 0", d[0],
          d[1], d[2]);
    const int32_t bad_col = 4;
    CHECK(fsi_csr_from_triplets(&b, 3, 4, 1, ti, &bad_col, tv) == -1, "column 4 of 4 accepted");
    fsi_csr_free(&a);
    fsi_csr_free(&b);
}

/* Solves with both preconditioners and checks against UMFPACK; returns the
 * iterations of Jacobi and ILU(0). */
static void check_against_direct(const char *name, const fsi_csr *a, int *iterations)
{
    const int n = a->n_rows;
    double *b = malloc((size_t)n * sizeof *b), *x_lu = malloc((size_t)n * sizeof *x_lu);
    double *x = malloc((size_t)n * sizeof *x);
    uint64_t seed = 11;
    for (int i = 0; i < n; i++)
        b[i] = unit_uniform(&seed) - 0.3;
    unit_lu lu;
    CHECK(unit_lu_factor(&lu, a) == UMFPACK_OK, "%s: UMFPACK factorisation failed", name);
    CHECK(unit_lu_solve(&lu, b, x_lu, 0) == UMFPACK_OK, "%s: UMFPACK solve failed", name);
    const double cond = condition_estimate(a, &lu);
    const double bound = 10.0 * TOL * cond;
    const fsi_krylov_settings settings = {TOL, 5000};
    for (int kind = 0; kind < 2; kind++) {
        fsi_precond m;
        fsi_precond_init(&m);
        char err[200] = "";
        CHECK(fsi_precond_setup(&m, (fsi_precond_kind)kind, a, err, sizeof err) == 0,
              "%s: set-up: %s", name, err);
        memset(x, 0, (size_t)n * sizeof *x);
        const fsi_krylov_result r = fsi_bicgstab(a, &m, b, x, &settings);
        const double error = rel_diff(x, x_lu, n);
        printf("%s, %s, BiCGSTAB: %d iterations, residual %.2e, error against UMFPACK %.2e "
               "(bound 10 tol cond = %.2e, cond_2 ~ %.0f)\n",
               name, fsi_precond_name(m.kind), r.iterations, r.rel_residual, error, bound, cond);
        CHECK(r.converged && r.rel_residual <= TOL, "%s, %s: not converged (%s), residual %.3g",
              name, fsi_precond_name(m.kind), r.reason, r.rel_residual);
        CHECK(error <= bound, "%s, %s: error %.3g against UMFPACK above %.3g", name,
              fsi_precond_name(m.kind), error, bound);
        iterations[kind] = r.iterations;
        memset(x, 0, (size_t)n * sizeof *x);
        const fsi_krylov_result g = fsi_gmres(a, &m, b, x, &settings, GMRES_RESTART);
        const double g_error = rel_diff(x, x_lu, n);
        printf("%s, %s, GMRES(%d): %d iterations, residual %.2e, error against UMFPACK %.2e\n",
               name, fsi_precond_name(m.kind), GMRES_RESTART, g.iterations, g.rel_residual,
               g_error);
        CHECK(g.converged && g.rel_residual <= TOL && g_error <= bound,
              "%s, %s, GMRES: converged %d (%s), residual %.3g, error %.3g (bound %.3g)", name,
              fsi_precond_name(m.kind), g.converged, g.reason, g.rel_residual, g_error, bound);
        fsi_precond_free(&m);
    }
    CHECK(iterations[FSI_PRECOND_ILU0] < iterations[FSI_PRECOND_JACOBI],
          "%s: ILU(0) needs %d iterations, Jacobi %d: expected fewer", name,
          iterations[FSI_PRECOND_ILU0], iterations[FSI_PRECOND_JACOBI]);
    unit_lu_free(&lu);
    free(b);
    free(x_lu);
    free(x);
}

static void test_against_direct(void)
{
    fsi_csr a;
    fsi_csr_init(&a);
    int it[2];
    CHECK(unit_laplace5(&a, 30) == 0, "5-point Laplacian not built");
    check_against_direct("5-point Laplacian 30 x 30", &a, it);

    CHECK(unit_sph_laplace(&a, 40, 0.1, 0.5, 1, 3) == 0, "SPH Laplacian not built");
    /* It must really be non-symmetric: ||A - A^T||_F / ||A||_F. */
    double asym = 0.0, total = 0.0;
    for (int32_t i = 0; i < a.n_rows; i++)
        for (int64_t k = a.row_start[i]; k < a.row_start[i + 1]; k++) {
            const int64_t t = fsi_csr_find(&a, a.col[k], i);
            const double at = t >= 0 ? a.val[t] : 0.0;
            asym += (a.val[k] - at) * (a.val[k] - at);
            total += a.val[k] * a.val[k];
        }
    printf("SPH Laplacian 40 x 40: %.1f entries a row, ||A - A^T|| / ||A|| = %.3f\n",
           (double)a.nnz / a.n_rows, sqrt(asym / total));
    CHECK(sqrt(asym / total) > 0.05, "SPH Laplacian: asymmetry %.3g, expected > 0.05",
          sqrt(asym / total));
    CHECK(a.nnz > 18 * a.n_rows, "SPH Laplacian: %.1f entries a row, expected about 20",
          (double)a.nnz / a.n_rows);
    check_against_direct("SPH Laplacian 40 x 40, non-symmetric", &a, it);
    fsi_csr_free(&a);
}

static void test_warm_start(void)
{
    fsi_csr a;
    fsi_csr_init(&a);
    unit_sph_laplace(&a, 40, 0.1, 0.5, 1, 5);
    const int n = a.n_rows;
    double *b = malloc((size_t)n * sizeof *b), *x_lu = malloc((size_t)n * sizeof *x_lu);
    double *x = malloc((size_t)n * sizeof *x);
    uint64_t seed = 13;
    for (int i = 0; i < n; i++)
        b[i] = unit_uniform(&seed);
    unit_lu lu;
    unit_lu_factor(&lu, &a);
    unit_lu_solve(&lu, b, x_lu, 0);
    const fsi_krylov_settings settings = {TOL, 5000};
    for (int kind = 0; kind < 2; kind++) {
        fsi_precond m;
        fsi_precond_init(&m);
        char err[200];
        fsi_precond_setup(&m, (fsi_precond_kind)kind, &a, err, sizeof err);
        const char *pc = fsi_precond_name(m.kind);
        memcpy(x, x_lu, (size_t)n * sizeof *x);
        const fsi_krylov_result exact = fsi_bicgstab(&a, &m, b, x, &settings);
        CHECK(exact.converged && exact.iterations <= 1,
              "%s: from the exact solution %d iterations (%s), expected 0 or 1", pc,
              exact.iterations, exact.reason);
        memset(x, 0, (size_t)n * sizeof *x);
        const fsi_krylov_result cold = fsi_bicgstab(&a, &m, b, x, &settings);
        const double scale = norm2(x_lu, n) / sqrt((double)n);
        for (int i = 0; i < n; i++)
            x[i] = x_lu[i] + 1e-3 * scale * (2.0 * unit_uniform(&seed) - 1.0);
        const fsi_krylov_result warm = fsi_bicgstab(&a, &m, b, x, &settings);
        printf("warm start, %s: %d iterations from the solution, %d from it + 1e-3 noise, "
               "%d from zero\n", pc, exact.iterations, warm.iterations, cold.iterations);
        CHECK(cold.converged && warm.converged && warm.iterations < cold.iterations,
              "%s: %d iterations from a nearby x, %d from zero: expected fewer", pc,
              warm.iterations, cold.iterations);
        fsi_precond_free(&m);
    }
    unit_lu_free(&lu);
    free(b);
    free(x_lu);
    free(x);
    fsi_csr_free(&a);
}

static void test_singular(void)
{
    fsi_csr a;
    fsi_csr_init(&a);
    unit_sph_laplace(&a, 20, 0.1, 0.5, 0, 17); /* no Dirichlet row: row sums zero */
    const int n = a.n_rows;
    double *b = malloc((size_t)n * sizeof *b), *x = malloc((size_t)n * sizeof *x);
    uint64_t seed = 19;
    for (int i = 0; i < n; i++)
        b[i] = unit_uniform(&seed) - 0.5;
    const fsi_krylov_settings settings = {TOL, 2000};
    for (int kind = 0; kind < 2; kind++) {
        fsi_precond m;
        fsi_precond_init(&m);
        char err[200] = "";
        const char *pc = fsi_precond_name((fsi_precond_kind)kind);
        if (fsi_precond_setup(&m, (fsi_precond_kind)kind, &a, err, sizeof err) != 0) {
            printf("singular PPE, %s: set-up refused: %s\n", pc, err);
            CHECK(err[0] != '\0', "%s: set-up refused without a reason", pc);
        } else {
            for (int solver = 0; solver < 2; solver++) {
                memset(x, 0, (size_t)n * sizeof *x);
                const fsi_krylov_result r = solve(solver, &a, &m, b, x, &settings);
                printf("singular PPE, %s, %s: converged %d after %d iterations, %d restarts, "
                       "residual %.3g, reason \"%s\"\n", solver_name(solver), pc, r.converged,
                       r.iterations, r.restarts, r.rel_residual, r.reason);
                CHECK(!r.converged && r.reason && strcmp(r.reason, "converged") != 0,
                      "%s, %s: a system with no solution reported converged",
                      solver_name(solver), pc);
                CHECK(all_finite(x, n) && isfinite(r.rel_residual), "%s, %s: NaN or Inf in x",
                      solver_name(solver), pc);
                /* The best iterate is returned: never worse than the start x = 0. */
                CHECK(r.rel_residual <= 1.0,
                      "%s, %s: returned x has residual %.3g, worse than x = 0",
                      solver_name(solver), pc, r.rel_residual);
            }
        }
        fsi_precond_free(&m);
    }
    free(b);
    free(x);
    fsi_csr_free(&a);
}

/* Set-up refuses what it cannot invert, naming the row: a zero diagonal (Jacobi), a
 * missing one and a vanishing pivot (ILU(0): [[1, 1], [1, 1]] has u_22 = 0). */
static void test_refusals(void)
{
    const int32_t zi[] = {0, 1}, zj[] = {1, 0}, si[] = {0, 0, 1, 1}, sj[] = {0, 1, 0, 1};
    const double zv[] = {1.0, 1.0}, sv[] = {1.0, 1.0, 1.0, 1.0};
    fsi_csr a;
    fsi_csr_init(&a);
    fsi_precond m;
    fsi_precond_init(&m);
    char err[200];
    fsi_csr_from_triplets(&a, 2, 2, 2, zi, zj, zv);
    for (int kind = 0; kind < 2; kind++) {
        err[0] = '\0';
        CHECK(fsi_precond_setup(&m, (fsi_precond_kind)kind, &a, err, sizeof err) == -1 &&
                  strstr(err, "row 0"), "%s: [[0, 1], [1, 0]] accepted or row not named (%s)",
              fsi_precond_name((fsi_precond_kind)kind), err);
    }
    fsi_csr_from_triplets(&a, 2, 2, 4, si, sj, sv);
    err[0] = '\0';
    CHECK(fsi_precond_setup(&m, FSI_PRECOND_ILU0, &a, err, sizeof err) == -1 &&
              strstr(err, "pivot") && strstr(err, "row 1"),
          "ilu0: [[1, 1], [1, 1]] accepted or its pivot not named (%s)", err);
    fsi_precond_free(&m);
    fsi_csr_free(&a);
}

/* b = 0: x = 0 whatever the guess, converged in 0 iterations, by both solvers. */
static void test_zero_rhs(void)
{
    fsi_csr a;
    fsi_csr_init(&a);
    unit_laplace5(&a, 5);
    double b[25] = {0.0}, x[25];
    fsi_precond m;
    fsi_precond_init(&m);
    char err[200];
    fsi_precond_setup(&m, FSI_PRECOND_ILU0, &a, err, sizeof err);
    const fsi_krylov_settings settings = {TOL, 100};
    for (int solver = 0; solver < 2; solver++) {
        for (int i = 0; i < 25; i++)
            x[i] = 1.0 + i;
        const fsi_krylov_result r = solve(solver, &a, &m, b, x, &settings);
        double largest = 0.0;
        for (int i = 0; i < 25; i++)
            largest = fmax(largest, fabs(x[i]));
        CHECK(r.converged && r.iterations == 0 && largest == 0.0,
              "%s, b = 0: converged %d, %d iterations, max |x| %g; expected 1, 0, 0",
              solver_name(solver), r.converged, r.iterations, largest);
    }
    fsi_precond_free(&m);
    fsi_csr_free(&a);
}

static void test_threads(void)
{
    fsi_csr a;
    fsi_csr_init(&a);
    unit_sph_laplace(&a, 100, 0.1, 0.5, 1, 23);
    const int n = a.n_rows;
    double *x = malloc((size_t)n * sizeof *x), *y[2], *s[2];
    uint64_t seed = 29;
    for (int i = 0; i < n; i++)
        x[i] = unit_uniform(&seed) - 0.5;
    fsi_precond m;
    fsi_precond_init(&m);
    char err[200];
    fsi_precond_setup(&m, FSI_PRECOND_JACOBI, &a, err, sizeof err);
    const fsi_krylov_settings settings = {TOL, 5000};
    const int saved = omp_get_max_threads();
    for (int t = 0; t < 2; t++) {
        omp_set_num_threads(t + 1);
        y[t] = malloc((size_t)n * sizeof *y[t]);
        s[t] = calloc((size_t)n, sizeof *s[t]);
        fsi_csr_multiply(&a, x, y[t]);
        fsi_bicgstab(&a, &m, x, s[t], &settings);
    }
    omp_set_num_threads(saved);
    CHECK(memcmp(y[0], y[1], (size_t)n * sizeof *x) == 0, "A x differs on 1 and 2 threads");
    CHECK(memcmp(s[0], s[1], (size_t)n * sizeof *x) == 0,
          "the Jacobi BiCGSTAB solution differs on 1 and 2 threads");
    for (int t = 0; t < 2; t++) {
        free(y[t]);
        free(s[t]);
    }
    free(x);
    fsi_precond_free(&m);
    fsi_csr_free(&a);
}

/* The measurement that picks the solver: no assertion on times. */
static void measure(int m)
{
    fsi_csr a;
    fsi_csr_init(&a);
    unit_sph_laplace(&a, m, 0.1, 0.5, 1, 31);
    const int n = a.n_rows;
    double *b = malloc((size_t)n * sizeof *b), *x = malloc((size_t)n * sizeof *x);
    uint64_t seed = 37;
    for (int i = 0; i < n; i++)
        b[i] = unit_uniform(&seed) - 0.3;
    const fsi_krylov_settings settings = {TOL, 20000};
    for (int kind = 0; kind < 2; kind++) {
        fsi_precond pc;
        fsi_precond_init(&pc);
        char err[200];
        const double t0 = fsi_wall_seconds();
        fsi_precond_setup(&pc, (fsi_precond_kind)kind, &a, err, sizeof err);
        const double t1 = fsi_wall_seconds();
        for (int solver = 0; solver < 2; solver++) {
            memset(x, 0, (size_t)n * sizeof *x);
            const double t2 = fsi_wall_seconds();
            const fsi_krylov_result r = solve(solver, &a, &pc, b, x, &settings);
            const double t3 = fsi_wall_seconds();
            printf("timing, %d unknowns, %s + %s: %d iterations, residual %.2e, "
                   "set-up %.3f s + solve %.3f s (%d threads)\n", n, solver_name(solver),
                   fsi_precond_name(pc.kind), r.iterations, r.rel_residual, t1 - t0, t3 - t2,
                   omp_get_max_threads());
        }
        fsi_precond_free(&pc);
    }
    unit_lu lu;
    const double t0 = fsi_wall_seconds();
    unit_lu_factor(&lu, &a);
    const double t1 = fsi_wall_seconds();
    unit_lu_solve(&lu, b, x, 0);
    const double t2 = fsi_wall_seconds();
    double *ax = malloc((size_t)n * sizeof *ax);
    fsi_csr_multiply(&a, x, ax);
    for (int i = 0; i < n; i++)
        ax[i] -= b[i];
    printf("timing, %d unknowns, UMFPACK: residual %.2e, factor %.3f s + solve %.3f s, "
           "%.0f entries in L+U (A: %lld)\n", n, norm2(ax, n) / norm2(b, n), t1 - t0, t2 - t1,
           lu.info[UMFPACK_LNZ] + lu.info[UMFPACK_UNZ], (long long)a.nnz);
    free(ax);
    unit_lu_free(&lu);
    free(b);
    free(x);
    fsi_csr_free(&a);
}

int main(void)
{
    test_building();
    test_against_direct();
    test_warm_start();
    test_singular();
    test_zero_rhs();
    test_refusals();
    test_threads();
    measure(100);
#ifdef NDEBUG
    /* 40 000 unknowns only in the release build: its times are the ones reported,
     * and under the sanitizers (Debug) it would take most of a minute. */
    measure(200);
#endif
    return unit_check_report("test_krylov");
}
