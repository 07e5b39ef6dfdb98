/* The contract of solid_model.h, checked for one model: compiled once per model of
 * FSI_SOLID_MODELS (solid_solver/CMakeLists.txt) and linked with that model's library
 * only. The material is the shared linear elastic one ([solid] keys of materials/);
 * the model's own keys keep their defaults unless tests/contract/solid_<model>.ini
 * (the first argument, when it exists) sets them.
 *
 *  1. a rigid translation and a rigid rotation (1e-3 rad in one step, 30 degrees in
 *     ten steps) give no internal force beyond round-off;
 *  2. a uniform stretch e = 1e-4 stores the strain energy of linear elasticity,
 *     (lambda + 2 mu) e^2 / 2 per unit volume (plane strain), within 10 e, and leaves
 *     no net force on the points two reaches from the edges;
 *  3. the stable step is positive, finite, and smaller for a stiffer material;
 *  4. the internal forces of a random small deformation sum to zero (and, in 2D, so
 *     do their moments);
 *  5. the forces do not depend, bit for bit, on the thread count;
 *  6. the density the fluid is sent (solid_model_density) is the material's, bit for
 *     bit, at creation, and after the uniform stretch of 2. lies between the
 *     material's and rho0 (1 - 2 e) at every point (a continuity density falls by
 *     about e, a total-Lagrangian model keeps rho0): positive, finite, in kg/m^3;
 *  7. the saved state is complete (solid_model_save_state / restore_state): after
 *     steps of a random deformation, restoring the state saved part-way, into the
 *     same model or a fresh one, and repeating the remaining steps gives the same
 *     forces, strain energy, density, stable step and saved state bit for bit; a
 *     store without the model's entries is refused and changes nothing. */
#include <math.h>
#include <omp.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "case_file.h"
#include "solid_model.h"
#include "solid_particles.h"
#include "state_store.h"

#include "unit_check.h"
#include "unit_random.h"
#include "unit_solid_lattice.h"

static const double DX = 0.01, RHO = 1000.0, E = 1e6, NU = 0.25;
static const char *model_name = FSI_CONTRACT_NAME;
static const char *settings_path;
static double reach; /* how far a point's interactions reach [m], from their count */

static const int SIDES[3] = {40, 30, 14};

static solid_particles *lattice(void)
{
    return test_lattice(SIDES[0], SIDES[1], SIDES[2], DX, RHO);
}

/* Distance of point i from the nearest edge of the lattice [m]. */
static double depth(const solid_particles *p, int i)
{
    double e = INFINITY;
    for (int d = 0; d < FSI_DIM; d++) {
        const double x = p->x0[i * FSI_DIM + d];
        e = fmin(e, fmin(x, SIDES[d] * DX - x));
    }
    return e;
}

/* The model for p: the settings file (its keys, if any) then the material. */
static solid_model *make_model(const solid_particles *p, double youngs_modulus)
{
    const char *dir = getenv("FSI_TEST_TMP");
    char path[512];
    snprintf(path, sizeof path, "%s/contract_solid_%ld.ini", dir && *dir ? dir : "/tmp",
             (long)getpid());
    FILE *out = fopen(path, "w");
    if (!out) {
        snprintf(path, sizeof path, "/tmp/contract_solid_%ld.ini", (long)getpid());
        out = fopen(path, "w");
    }
    if (!out) {
        fprintf(stderr, "cannot write %s\n", path);
        exit(2);
    }
    FILE *in = settings_path ? fopen(settings_path, "r") : NULL;
    int has_section = 0;
    if (in) {
        char line[512];
        while (fgets(line, sizeof line, in)) {
            fputs(line, out);
            has_section = has_section || strncmp(line, "[solid]", 7) == 0;
        }
        fclose(in);
    }
    if (!has_section)
        fputs("[solid]\n", out);
    fprintf(out, "density = %.17g\nyoungs_modulus = %.17g\npoisson_ratio = %.17g\n"
            "plane = strain\n", RHO, youngs_modulus, NU);
    fclose(out);
    fsi_case *c = fsi_case_read(path, stderr);
    remove(path);
    char msg[512];
    solid_model *m = c ? solid_model_create(c, p, msg, sizeof msg) : NULL;
    if (!m) {
        fprintf(stderr, "solid_model_create (%s): %s\n", model_name, c ? msg : "no case");
        exit(2);
    }
    fsi_case_free(c);
    return m;
}

static void force(solid_model *m, const solid_particles *p, const double *x_prev, double *f)
{
    char msg[512];
    if (solid_model_internal_force(m, p, x_prev, 1e-5, 0.0, f, msg, sizeof msg) != 0) {
        fprintf(stderr, "solid_model_internal_force (%s): %s\n", model_name, msg);
        exit(2);
    }
}

static double largest_force(const solid_particles *p, const double *f)
{
    double worst = 0.0;
    for (int i = 0; i < p->n; i++) {
        double s = 0.0;
        for (int d = 0; d < FSI_DIM; d++)
            s += f[i * FSI_DIM + d] * f[i * FSI_DIM + d];
        worst = fmax(worst, sqrt(s));
    }
    return worst;
}

/* The force of a strain of 1 on one point, E dx^(DIM - 1): a rigid motion's forces
 * are the round-off of positions of about 1 m in spacings of 0.01 m, 1e-14 strain,
 * so 1e-10 of it bounds them with room, while a strain of 1e-6 would not pass. */
static double unit_force(void)
{
    return E * pow(DX, FSI_DIM - 1);
}

static void test_rigid_motion(void)
{
    solid_particles *p = lattice();
    const size_t vec = (size_t)p->n * FSI_DIM * sizeof(double);
    double *f = malloc(vec), *x_prev = malloc(vec);
    const double tol = 1e-10 * unit_force();

    /* Translation by (0.3, -0.2, 0.1) m in one step. */
    solid_model *m = make_model(p, E);
    memcpy(x_prev, p->x, vec);
    for (int i = 0; i < p->n; i++)
        for (int d = 0; d < FSI_DIM; d++)
            p->x[i * FSI_DIM + d] += (d == 0 ? 0.3 : d == 1 ? -0.2 : 0.1);
    force(m, p, x_prev, f);
    const double translated = largest_force(p, f);
    solid_model_free(m);

    /* Rotation about the lattice's centre in the x-y plane: a small one in one step,
     * then a finite one of 30 degrees in ten steps (an incremental stress update must
     * be objective: it must not read the rotation as strain). */
    double c[FSI_DIM] = {0};
    for (int d = 0; d < FSI_DIM; d++)
        c[d] = 0.5 * SIDES[d] * DX;
    double rotated[2];
    const double angle[2] = {1e-3, M_PI / 6.0};
    const int steps[2] = {1, 10};
    for (int k = 0; k < 2; k++) {
        memcpy(p->x, p->x0, vec);
        m = make_model(p, E);
        rotated[k] = 0.0;
        for (int s = 1; s <= steps[k]; s++) {
            memcpy(x_prev, p->x, vec);
            const double a = angle[k] * s / steps[k], ca = cos(a), sa = sin(a);
            for (int i = 0; i < p->n; i++) {
                const double rx = p->x0[i * FSI_DIM] - c[0], ry = p->x0[i * FSI_DIM + 1] - c[1];
                p->x[i * FSI_DIM] = c[0] + ca * rx - sa * ry;
                p->x[i * FSI_DIM + 1] = c[1] + sa * rx + ca * ry;
            }
            force(m, p, x_prev, f);
            rotated[k] = fmax(rotated[k], largest_force(p, f));
        }
        solid_model_free(m);
    }
    printf("rigid motion: largest force %.3g N after a translation, %.3g N after a 1e-3 rad "
           "rotation, %.3g N during a 30 degree rotation (bound %.3g N)\n", translated,
           rotated[0], rotated[1], tol);
    CHECK(translated < tol, "a rigid translation gives internal forces: %.3g N", translated);
    CHECK(rotated[0] < tol, "a small rigid rotation gives internal forces: %.3g N",
          rotated[0]);
    CHECK(rotated[1] < tol, "a finite rigid rotation gives internal forces: %.3g N",
          rotated[1]);
    free(f);
    free(x_prev);
    test_lattice_free(p);
}

/* x = x0 + e x0_x e_x in one step from the reference: uniaxial strain e along x,
 * plane strain. Every point's deformation gradient is exact for a homogeneous field
 * (edge points included), so the energy is sum V (lambda + 2 mu) e^2 / 2 but for the
 * geometric terms of order e (the strain measure of a finite stretch, the volume
 * change): within 10 e relative. */
static void test_uniform_stretch(void)
{
    const double e = 1e-4;
    solid_particles *p = lattice();
    const size_t vec = (size_t)p->n * FSI_DIM * sizeof(double);
    double *f = malloc(vec), *x_prev = malloc(vec);
    solid_model *m = make_model(p, E);
    const double *rho0 = solid_model_density(m, p);
    int differ = 0;
    for (int i = 0; i < p->n; i++)
        differ += memcmp(&rho0[i], &p->density[i], sizeof rho0[i]) != 0;
    CHECK(differ == 0, "at creation the density of %d points is not the material's", differ);
    memcpy(x_prev, p->x, vec);
    for (int i = 0; i < p->n; i++)
        p->x[i * FSI_DIM] = (1.0 + e) * p->x0[i * FSI_DIM];
    force(m, p, x_prev, f);
    const double lambda = E * NU / ((1.0 + NU) * (1.0 - 2.0 * NU)), mu = E / (2.0 * (1.0 + NU));
    double volume = 0.0;
    for (int i = 0; i < p->n; i++)
        volume += p->volume[i];
    const double expected = volume * 0.5 * (lambda + 2.0 * mu) * e * e;
    const double energy = solid_model_strain_energy(m, p);
    double interior = 0.0, edge = 0.0, sum[FSI_DIM] = {0}, mag = 0.0;
    int n_interior = 0;
    for (int i = 0; i < p->n; i++) {
        double s = 0.0;
        for (int d = 0; d < FSI_DIM; d++) {
            s += f[i * FSI_DIM + d] * f[i * FSI_DIM + d];
            sum[d] += f[i * FSI_DIM + d];
            mag += fabs(f[i * FSI_DIM + d]);
        }
        if (depth(p, i) > 2.0 * reach) {
            interior = fmax(interior, sqrt(s));
            n_interior++;
        } else {
            edge = fmax(edge, sqrt(s));
        }
    }
    printf("uniform stretch e = %g: strain energy %.6g J, linear elasticity %.6g J "
           "(relative %.3g); largest force %.3g N at %d interior points, %.3g N at the "
           "edges\n", e, energy, expected, energy / expected - 1.0, interior, n_interior,
           edge);
    CHECK(fabs(energy - expected) < 10.0 * e * expected, "uniform stretch: strain energy "
          "%.6g J, linear elasticity gives %.6g J", energy, expected);
    /* The interior points, whose whole neighbourhood has complete families, are in
     * equilibrium under the uniform stress: round-off of the edge forces (1e-10). */
    CHECK(n_interior > 0 && edge > 0.0, "no interior points or no edge forces");
    CHECK(interior <= 1e-10 * edge, "uniform stretch: net force %.3g N on an interior point "
          "(edge forces %.3g N)", interior, edge);
    for (int d = 0; d < FSI_DIM; d++)
        CHECK(fabs(sum[d]) <= 1e-12 * mag, "uniform stretch: forces sum to %.3g N along %d",
              sum[d], d);
    const double *rho = solid_model_density(m, p);
    double rho_min = INFINITY, rho_max = -INFINITY;
    for (int i = 0; i < p->n; i++) {
        rho_min = fmin(rho_min, rho[i]);
        rho_max = fmax(rho_max, rho[i]);
    }
    printf("uniform stretch e = %g: density sent %.9g to %.9g kg/m^3 (rho0 %g)\n", e, rho_min,
           rho_max, RHO);
    CHECK(rho_min >= RHO * (1.0 - 2.0 * e) && rho_max <= RHO, "uniform stretch: density "
          "%.9g to %.9g kg/m^3, not within [rho0 (1 - 2 e), rho0]", rho_min, rho_max);
    free(f);
    free(x_prev);
    solid_model_free(m);
    test_lattice_free(p);
}

static void test_stable_dt(void)
{
    solid_particles *p = lattice();
    double dt[2];
    for (int k = 0; k < 2; k++) {
        solid_model *m = make_model(p, k ? 4.0 * E : E);
        dt[k] = solid_model_stable_dt(m, p);
        solid_model_free(m);
    }
    printf("stable step: %.4g s at E = %g Pa, %.4g s at 4 E\n", dt[0], E, dt[1]);
    CHECK(dt[0] > 0.0 && isfinite(dt[0]) && dt[1] > 0.0 && isfinite(dt[1]),
          "stable step not positive and finite: %g, %g s", dt[0], dt[1]);
    CHECK(dt[1] < dt[0], "stable step not smaller for a stiffer material: %g s at 4 E, %g s "
          "at E", dt[1], dt[0]);
    test_lattice_free(p);
}

/* Forces of a random displacement of 1e-2 dx of p (its x) with the given number of
 * threads, from a fresh model. */
static double *random_forces(int threads, solid_particles *p)
{
    omp_set_num_threads(threads);
    rng_state = 99;
    const size_t vec = (size_t)p->n * FSI_DIM * sizeof(double);
    double *f = malloc(vec), *x_prev = malloc(vec);
    memcpy(p->x, p->x0, vec);
    solid_model *m = make_model(p, E);
    memcpy(x_prev, p->x, vec);
    for (int i = 0; i < p->n * FSI_DIM; i++)
        p->x[i] = p->x0[i] + 1e-2 * DX * (unit_uniform(&rng_state) - 0.5);
    force(m, p, x_prev, f);
    solid_model_free(m);
    free(x_prev);
    omp_set_num_threads(1);
    return f;
}

/* Newton's third law: every interaction acts on both its points, so the forces sum to
 * zero to round-off, 1e-12 of the sum of their magnitudes (a few thousand terms of
 * relative error 1e-16 each); in 2D the moments too (a symmetric Cauchy stress). */
static void test_momentum(void)
{
    solid_particles *p = lattice();
    double *f = random_forces(1, p);
    double sum[FSI_DIM] = {0}, mag = 0.0, torque = 0.0, scale = 0.0;
    for (int i = 0; i < p->n; i++)
        for (int d = 0; d < FSI_DIM; d++) {
            sum[d] += f[i * FSI_DIM + d];
            mag += fabs(f[i * FSI_DIM + d]);
        }
    if (FSI_DIM == 2)
        for (int i = 0; i < p->n; i++) {
            const double *x = p->x + i * FSI_DIM, *g = f + i * FSI_DIM;
            torque += x[0] * g[1] - x[1] * g[0];
            scale += hypot(x[0], x[1]) * hypot(g[0], g[1]);
        }
    printf("random deformation: |sum f| / sum |f| = %.3g, |sum x x f| / sum |x||f| = %.3g\n",
           hypot(sum[0], sum[1]) / mag, FSI_DIM == 2 ? fabs(torque) / scale : 0.0);
    CHECK(mag > 0.0, "no forces for a random deformation");
    for (int d = 0; d < FSI_DIM; d++)
        CHECK(fabs(sum[d]) <= 1e-12 * mag, "internal forces sum to %.3g N along %d (sum |f| "
              "= %.3g N)", sum[d], d, mag);
    if (FSI_DIM == 2)
        CHECK(fabs(torque) <= 1e-12 * scale, "internal forces have a net moment %.3g N m "
              "(scale %.3g)", torque, scale);
    free(f);
    test_lattice_free(p);
}

static void test_threads(void)
{
    solid_particles *p = lattice();
    double *one = random_forces(1, p), *two = random_forces(2, p);
    int threads = 0;
    omp_set_num_threads(2);
#pragma omp parallel
#pragma omp single
    threads = omp_get_num_threads();
    omp_set_num_threads(1);
    int differ = 0;
    for (int k = 0; k < p->n * FSI_DIM; k++)
        differ += memcmp(&one[k], &two[k], sizeof one[k]) != 0;
    printf("threads: %d of %d force components differ between 1 and %d threads\n", differ,
           p->n * FSI_DIM, threads);
    CHECK(differ == 0, "internal forces depend on the thread count: %d components differ",
          differ);
    free(one);
    free(two);
    test_lattice_free(p);
}

/* Step k of a random deformation: x = x0 + k 1e-3 dx w (w fixed, uniform in
 * [-1/2, 1/2) per component), from the positions of step k - 1; the forces into f. */
static void deformation_step(solid_model *m, solid_particles *p, const double *w,
                             double *x_prev, double *f, int k)
{
    memcpy(x_prev, p->x, (size_t)p->n * FSI_DIM * sizeof(double));
    for (int i = 0; i < p->n * FSI_DIM; i++)
        p->x[i] = p->x0[i] + 1e-3 * DX * k * w[i];
    force(m, p, x_prev, f);
}

/* Steps from..to-1 (positions of step from - 1 in p), then what must match: forces,
 * strain energy, density, stable step, the saved state (into st). */
typedef struct {
    double *f, energy, dt;
    double *rho;
} step_result;

static void run_steps(solid_model *m, solid_particles *p, const double *w, double *x_prev,
                      int from, int to, step_result *r, fsi_state *st)
{
    for (int k = from; k < to; k++)
        deformation_step(m, p, w, x_prev, r->f, k);
    r->energy = solid_model_strain_energy(m, p);
    r->dt = solid_model_stable_dt(m, p);
    memcpy(r->rho, solid_model_density(m, p), (size_t)p->n * sizeof(double));
    fsi_state_clear(st);
    CHECK(solid_model_save_state(m, p, st) == 0, "save_state failed");
}

/* Entries of a that b lacks or holds with other bytes (and the other way round). */
static int state_differences(const fsi_state *a, const fsi_state *b)
{
    int differ = 0, used_a = 0, used_b = 0;
    for (int k = 0; k < a->n; k++) {
        const fsi_state_entry *e = &a->entry[k];
        if (!e->used)
            continue;
        used_a++;
        size_t bytes;
        const void *other = fsi_state_data(b, e->name, &bytes);
        if (!other || bytes != e->bytes || memcmp(other, e->data, bytes) != 0) {
            printf("  state entry %s differs\n", e->name);
            differ++;
        }
    }
    for (int k = 0; k < b->n; k++)
        used_b += b->entry[k].used;
    return differ + (used_a != used_b);
}

static int result_differences(const solid_particles *p, const step_result *a,
                              const step_result *b)
{
    int differ = memcmp(&a->energy, &b->energy, sizeof a->energy) != 0;
    differ += memcmp(&a->dt, &b->dt, sizeof a->dt) != 0;
    differ += memcmp(a->f, b->f, (size_t)p->n * FSI_DIM * sizeof(double)) != 0;
    differ += memcmp(a->rho, b->rho, (size_t)p->n * sizeof(double)) != 0;
    return differ;
}

static void test_save_restore(void)
{
    solid_particles *p = lattice();
    const size_t vec = (size_t)p->n * FSI_DIM * sizeof(double);
    double *w = malloc(vec), *x_prev = malloc(vec), *x_saved = malloc(vec);
    step_result r[3];
    for (int k = 0; k < 3; k++) {
        r[k].f = malloc(vec);
        r[k].rho = malloc((size_t)p->n * sizeof(double));
    }
    uint64_t seed = 7;
    for (int i = 0; i < p->n * FSI_DIM; i++)
        w[i] = unit_uniform(&seed) - 0.5;
    memcpy(p->x, p->x0, vec);
    fsi_state saved = {0}, after[3] = {{0}};
    solid_model *m = make_model(p, E);
    run_steps(m, p, w, x_prev, 1, 4, &r[0], &saved);     /* steps 1-3, then save */
    memcpy(x_saved, p->x, vec);
    run_steps(m, p, w, x_prev, 4, 7, &r[0], &after[0]);  /* steps 4-6 */
    /* The same model back to step 3, then steps 4-6 again. */
    CHECK(solid_model_restore_state(m, p, &saved) == 0, "restore_state failed");
    memcpy(p->x, x_saved, vec);
    run_steps(m, p, w, x_prev, 4, 7, &r[1], &after[1]);
    /* A fresh model given the state of step 3 (a restart). */
    solid_model *fresh = make_model(p, E);
    CHECK(solid_model_restore_state(fresh, p, &saved) == 0, "restore_state (fresh) failed");
    memcpy(p->x, x_saved, vec);
    run_steps(fresh, p, w, x_prev, 4, 7, &r[2], &after[2]);
    const int same = result_differences(p, &r[0], &r[1]) + state_differences(&after[0], &after[1]);
    const int fresh_differ =
        result_differences(p, &r[0], &r[2]) + state_differences(&after[0], &after[2]);
    int entries = 0;
    size_t bytes = 0;
    for (int k = 0; k < saved.n; k++) {
        entries += saved.entry[k].used;
        bytes += saved.entry[k].used ? saved.entry[k].bytes : 0;
    }
    /* An empty store: refused, and the model goes on as if nothing was asked. */
    fsi_state empty = {0};
    const int refused = solid_model_restore_state(fresh, p, &empty) == -1;
    fsi_state again = {0};
    solid_model_save_state(fresh, p, &again);
    const int unchanged = state_differences(&after[2], &again) == 0;
    printf("save and restore: %d entries, %zu bytes for %d points; after restoring step 3 "
           "and repeating steps 4-6: %d differences (same model), %d (fresh model); an "
           "empty store %s\n", entries, bytes, p->n, same, fresh_differ,
           refused && unchanged ? "refused, nothing changed" : "NOT refused cleanly");
    CHECK(entries > 0, "the model saves nothing");
    CHECK(same == 0, "restoring into the same model does not repeat the steps bit for bit");
    CHECK(fresh_differ == 0, "restoring into a fresh model does not repeat the steps bit for "
          "bit");
    CHECK(refused && unchanged, "restoring from an empty store: not refused, or it changed "
          "the model");
    fsi_state_free(&saved);
    fsi_state_free(&empty);
    fsi_state_free(&again);
    for (int k = 0; k < 3; k++) {
        fsi_state_free(&after[k]);
        free(r[k].f);
        free(r[k].rho);
    }
    solid_model_free(m);
    solid_model_free(fresh);
    free(w);
    free(x_prev);
    free(x_saved);
    test_lattice_free(p);
}

/* The reach of the interactions from their number per point, a disc (ball) of radius
 * delta holding pi (delta / dx)^2 (4/3 pi (delta / dx)^3) points; the mean over the
 * lattice, edges included, errs low, hence the margin of a spacing. */
static double interaction_reach(void)
{
    solid_particles *p = lattice();
    solid_model *m = make_model(p, E);
    const double per_point = (double)solid_model_interaction_count(m) / p->n;
    solid_model_free(m);
    test_lattice_free(p);
    const double r = FSI_DIM == 2 ? sqrt(per_point / M_PI) : cbrt(0.75 * per_point / M_PI);
    return (r + 1.0) * DX;
}

int main(int argc, char **argv)
{
    settings_path = argc > 1 && access(argv[1], R_OK) == 0 ? argv[1] : NULL;
    omp_set_num_threads(1);
    reach = interaction_reach();
    printf("solid model %s: interactions reach about %.3g dx\n", model_name, reach / DX);
    test_rigid_motion();
    test_uniform_stretch();
    test_stable_dt();
    test_momentum();
    test_threads();
    test_save_restore();
    char name[128];
    snprintf(name, sizeof name, "contract_solid_%s", model_name);
    return unit_check_report(name);
}
