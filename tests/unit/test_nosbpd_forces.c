/* NOSB-PD internal forces (000 Eqs. 32-33 in gather form, plus the Silling 2017
 * zero-energy mode control):
 *  - patch test: a pre-stressed lattice under a uniform stretch has zero net force
 *    at every point whose whole neighbourhood has complete families (depth >= 2
 *    horizons), to round-off relative to the edge forces (1e-10);
 *  - Newton's third law of the gather form: the forces of a random displacement
 *    field sum to zero, to round-off relative to the sum of their magnitudes (1e-12);
 *  - the result is the same, bit for bit, with 1 and 2 OpenMP threads (also while
 *    bonds break);
 *  - the checkerboard (hourglass) mode: with zero_energy_coefficient = 0 it costs
 *    no force at interior points (the spurious zero-energy mode; forces below 1e-9
 *    of the stabilised ones), with the default coefficient every interior point is
 *    pulled back (f . u < 0). */
#include <omp.h>

#include "test_nosbpd_common.h"

static const char *CASE_BASE = "[solid]\n"
                               "solver = nosbpd\n"
                               "density = 1000\n"
                               "youngs_modulus = 1e6\n"
                               "poisson_ratio = 0.25\n"
                               "plane = strain\n";

static double *copy_positions(const solid_particles *p)
{
    double *x = malloc((size_t)p->n * FSI_DIM * sizeof *x);
    memcpy(x, p->x, (size_t)p->n * FSI_DIM * sizeof *x);
    return x;
}

static void check_patch(const char *influence)
{
    const int n_axis[3] = {20, 18, 14};
    const double dx = 0.01;
    solid_particles *p = test_lattice(n_axis[0], n_axis[1], n_axis[2], dx, 1000.0);
    char text[512];
    snprintf(text, sizeof text, "%s[solid.nosbpd]\n"
                                "influence_function = %s\n", CASE_BASE, influence);
    solid_model *m = test_model(text, p);
    double *stress = nosbpd_stress(m);
    for (int i = 0; i < p->n; i++) {
        stress[i * 6 + 0] = 2000.0;
        stress[i * 6 + 1] = -500.0;
        stress[i * 6 + 3] = 300.0;
    }
    double *x_prev = copy_positions(p);
    double *force = malloc((size_t)p->n * FSI_DIM * sizeof *force);
    for (int i = 0; i < p->n; i++)
        p->x[i * FSI_DIM] = 1.001 * p->x0[i * FSI_DIM];
    CHECK(test_force(m, p, x_prev, force) == 0, "patch step failed");
    /* Uniform stress after the step: every point got the same increment, up to the
     * round-off of F = N K^-1 (about 1e-15) times E. */
    double spread = 0.0;
    for (int i = 1; i < p->n; i++)
        spread = fmax(spread, fabs(stress[i * 6] - stress[0]));
    CHECK(spread < 1e-13 * 1e6, "%s: stress not uniform after a uniform stretch (spread %g Pa)",
          influence, spread);
    double interior = 0.0, edge = 0.0;
    for (int i = 0; i < p->n; i++) {
        const double f = fsi_vec_norm(force + i * FSI_DIM);
        if (test_depth(p, i, n_axis) >= 6) /* 2 horizons of 3 dx */
            interior = fmax(interior, f);
        else
            edge = fmax(edge, f);
    }
    CHECK(edge > 0.0, "%s: no edge forces at all", influence);
    CHECK(interior <= 1e-10 * edge, "%s: patch test: interior force %g vs edge force %g",
          influence, interior, edge);
    free(x_prev);
    free(force);
    solid_model_free(m);
    test_lattice_free(p);
}

static void random_displacement(solid_particles *p, double amplitude)
{
    for (int i = 0; i < p->n * FSI_DIM; i++)
        p->x[i] = p->x0[i] + amplitude * (test_uniform() - 0.5);
}

static void check_newton(void)
{
    solid_particles *p = test_lattice(15, 12, 8, 0.01, 1000.0);
    solid_model *m = test_model(CASE_BASE, p);
    double *x_prev = copy_positions(p);
    double *force = malloc((size_t)p->n * FSI_DIM * sizeof *force);
    random_displacement(p, 1e-4);
    CHECK(test_force(m, p, x_prev, force) == 0, "random step failed");
    double sum[FSI_DIM] = {0}, mag = 0.0;
    for (int i = 0; i < p->n; i++)
        for (int d = 0; d < FSI_DIM; d++) {
            sum[d] += force[i * FSI_DIM + d];
            mag += fabs(force[i * FSI_DIM + d]);
        }
    CHECK(mag > 0.0, "no forces for a random displacement");
    for (int d = 0; d < FSI_DIM; d++)
        CHECK(fabs(sum[d]) <= 1e-12 * mag, "sum of forces along %d is %g (sum |f| = %g)", d,
              sum[d], mag);
    /* Angular momentum: sum x cross f = 0 as well (the force states keep it). */
    if (FSI_DIM == 2) {
        double torque = 0.0, scale = 0.0;
        for (int i = 0; i < p->n; i++) {
            const double *x = p->x + i * FSI_DIM, *f = force + i * FSI_DIM;
            torque += x[0] * f[1] - x[1] * f[0];
            scale += fsi_vec_norm(x) * fsi_vec_norm(f);
        }
        CHECK(fabs(torque) <= 1e-12 * scale, "net torque %g (scale %g)", torque, scale);
    }
    free(x_prev);
    free(force);
    solid_model_free(m);
    test_lattice_free(p);
}

/* Runs five steps of growing random displacement with failure on; returns the forces
 * of the last step (caller frees). */
static double *run_steps(int threads, int64_t *broken)
{
    omp_set_num_threads(threads);
    test_rng = 12345;
    solid_particles *p = test_lattice(30, 20, 6, 0.01, 1000.0);
    char text[512];
    snprintf(text, sizeof text, "%s[solid.nosbpd]\n"
                                "failure = true\ncritical_stretch = 0.02\n", CASE_BASE);
    solid_model *m = test_model(text, p);
    double *x_prev = malloc((size_t)p->n * FSI_DIM * sizeof *x_prev);
    double *force = malloc((size_t)p->n * FSI_DIM * sizeof *force);
    for (int step = 1; step <= 5; step++) {
        memcpy(x_prev, p->x, (size_t)p->n * FSI_DIM * sizeof *x_prev);
        random_displacement(p, 2e-4 * step);
        if (test_force(m, p, x_prev, force) != 0)
            CHECK(0, "step %d with %d threads failed", step, threads);
    }
    *broken = nosbpd_broken_bond_count(m);
    free(x_prev);
    solid_model_free(m);
    test_lattice_free(p);
    return force;
}

static void check_threads(void)
{
    int64_t broken1 = 0, broken2 = 0;
    double *f1 = run_steps(1, &broken1);
    double *f2 = run_steps(2, &broken2);
    const int n = 30 * 20 * (FSI_DIM == 3 ? 6 : 1);
    CHECK(broken1 > 0, "the thread test broke no bond (it should exercise failure)");
    CHECK(broken1 == broken2, "%ld bonds broke with 1 thread, %ld with 2", (long)broken1,
          (long)broken2);
    CHECK(memcmp(f1, f2, (size_t)n * FSI_DIM * sizeof *f1) == 0,
          "forces differ between 1 and 2 threads");
    free(f1);
    free(f2);
}

/* Checkerboard displacement u = a (-1)^(i+j) e_x. */
static void checkerboard_forces(const char *coefficient, double *interior_max,
                                int *restoring, int *interior_count)
{
    const int n_axis[3] = {24, 24, 14};
    const double dx = 0.01, a = 1e-4 * dx;
    solid_particles *p = test_lattice(n_axis[0], n_axis[1], n_axis[2], dx, 1000.0);
    char text[512];
    snprintf(text, sizeof text, "%s[solid.nosbpd]\n"
                                "zero_energy_coefficient = %s\n", CASE_BASE, coefficient);
    solid_model *m = test_model(text, p);
    double *x_prev = copy_positions(p);
    double *force = malloc((size_t)p->n * FSI_DIM * sizeof *force);
    for (int i = 0; i < p->n; i++) {
        int parity = 0;
        for (int d = 0; d < FSI_DIM; d++)
            parity += test_index(p, i, d);
        p->x[i * FSI_DIM] += (parity % 2 ? -a : a);
    }
    CHECK(test_force(m, p, x_prev, force) == 0, "checkerboard step failed");
    *interior_max = 0.0;
    *restoring = 0;
    *interior_count = 0;
    for (int i = 0; i < p->n; i++) {
        if (test_depth(p, i, n_axis) < 6)
            continue;
        (*interior_count)++;
        *interior_max = fmax(*interior_max, fsi_vec_norm(force + i * FSI_DIM));
        const double u = p->x[i * FSI_DIM] - p->x0[i * FSI_DIM];
        *restoring += force[i * FSI_DIM] * u < 0.0;
    }
    free(x_prev);
    free(force);
    solid_model_free(m);
    test_lattice_free(p);
}

static void check_zero_energy_mode(void)
{
    double f_off, f_on;
    int restoring_off, restoring_on, count;
    checkerboard_forces("0", &f_off, &restoring_off, &count);
    checkerboard_forces("0.1", &f_on, &restoring_on, &count);
    CHECK(count > 0, "no interior points");
    CHECK(f_on > 0.0, "the stabilised checkerboard has no interior force");
    CHECK(f_off <= 1e-9 * f_on,
          "without control the checkerboard costs force %g (stabilised %g): it should be a "
          "zero-energy mode of the correspondence model", f_off, f_on);
    CHECK(restoring_on == count, "only %d of %d interior points are pulled back", restoring_on,
          count);
}

int main(void)
{
    check_patch("inverse");
    check_patch("one");
    check_patch("gaussian");
    check_newton();
    check_threads();
    check_zero_energy_mode();
    return unit_check_report("nosbpd forces");
}
