/* Unit test of the solid main loop's model-free parts (solid_solver/): the lattice of
 * a block, removed notches, region selection and flags, probes' nearest particle,
 * prescribed load ramps, the cantilever-mode initial velocity (benchmarks S2), the
 * semantic check of a case's geometry (through fsi_case_validate with a schema
 * assembled here from the solid's key tables), velocity Verlet with gravity, damping
 * and clamps (000 Eq. 55), and the interface load take. Exit 0 = pass; every failed
 * check is printed. Scratch files go to $FSI_TEST_TMP/solid_geometry (default
 * /tmp/fsi_test_solid_geometry). */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "case_file.h"
#include "dim.h"
#include "geometry.h"
#include "initial_velocity.h"
#include "solid_integrate.h"
#include "solid_interface.h"
#include "solid_keys.h"
#include "solid_loads.h"

#include "unit_check.h"

/* Vectors in case text: the z component only in 3D builds. */
#if FSI_DIM == 2
#define Z(v) ""
#else
#define Z(v) ", " #v
#endif

/* Number of z layers of the test blocks (z from 0 to 0.03 in 3D at dx = 0.01). */
#if FSI_DIM == 2
#define LAYERS 1
#else
#define LAYERS 3
#endif

static char scratch[512];

static void make_scratch(void)
{
    const char *base = getenv("FSI_TEST_TMP");
    snprintf(scratch, sizeof scratch, "%s/solid_geometry",
             base && *base ? base : "/tmp/fsi_test_solid_geometry");
    char path[512];
    snprintf(path, sizeof path, "%s", scratch);
    for (char *p = path + 1; *p; p++)
        if (*p == '/') {
            *p = '\0';
            mkdir(path, 0755);
            *p = '/';
        }
    if (mkdir(path, 0755) != 0 && errno != EEXIST) {
        fprintf(stderr, "cannot create %s\n", path);
        exit(1);
    }
}

static const char *write_case(const char *name, const char *text)
{
    static char path[600];
    snprintf(path, sizeof path, "%s/%s", scratch, name);
    FILE *f = fopen(path, "w");
    if (!f) {
        fprintf(stderr, "cannot write %s\n", path);
        exit(1);
    }
    fputs(text, f);
    fclose(f);
    return path;
}

/* ------------------------------------------------------------- the schema */

static const fsi_key_spec run_keys[] = {
    {"end_time", FSI_KEY_REAL, "s", NULL, FSI_BOUND_MIN_OPEN, 0, 0, NULL, "End."},
};
static const fsi_key_table run_table = {"run", "Run.", run_keys, 1};

static const fsi_key_spec participant_keys[] = {
    {"solver", FSI_KEY_STRING, "-", NULL, 0, 0, 0, NULL, "Solver."},
    {"executable", FSI_KEY_STRING, "-", "", 0, 0, 0, NULL, "Program."},
};
static const fsi_key_table participant_table = {"participant", "Every participant.",
                                                participant_keys, 2};

/* Stands in for the material keys (solid_solver/materials), which this test does
 * not need. */
static const fsi_key_spec material_keys_here[] = {
    {"density", FSI_KEY_REAL, "kg/m^3", NULL, FSI_BOUND_MIN_OPEN, 0, 0, NULL, "rho0."},
};
static const fsi_key_table material_table = {"material", "Material.", material_keys_here, 1};

static const fsi_key_table *const solid_tables[] = {&fsi_solid_common_keys, &material_table};
static const char *const roles[] = {"fluid", "solid"};

static fsi_case_schema test_schema(fsi_solver_spec *solver)
{
    *solver = (fsi_solver_spec){.name = "testsolid", .role = "solid",
                                .executable = "fsi-solid-test",
                                .description = "Solid for the geometry test.",
                                .key_tables = solid_tables, .n_key_tables = 2,
                                .objects = fsi_solid_object_kinds,
                                .n_objects = fsi_solid_n_object_kinds,
                                .check = solid_geometry_check};
    fsi_case_schema s = {&run_table, 1, &participant_table, roles, 2, solver, 1};
    return s;
}

/* Reads and validates; messages go to 'messages' (NUL-terminated). Returns the
 * error count, -1 when the file could not be read; *out gets the case (or NULL). */
static int load_case(const char *path, char *messages, size_t size, fsi_case **out)
{
    fsi_solver_spec solver;
    fsi_case_schema schema = test_schema(&solver);
    FILE *err = fmemopen(messages, size, "w");
    fsi_case *c = fsi_case_read(path, err);
    int n = -1;
    if (c)
        n = fsi_case_validate(c, &schema, err);
    fclose(err);
    messages[size - 1] = '\0';
    if (out)
        *out = c;
    else if (c)
        fsi_case_free(c);
    return n;
}

/* ------------------------------------------------------------- geometry */

static solid_block test_block(const char *section, double x0, double x1, double y0, double y1,
                              double dx)
{
    solid_block b;
    memset(&b, 0, sizeof b);
    b.section = section;
    double lo[3] = {x0, y0, 0.0}, hi[3] = {x1, y1, 0.03};
    for (int d = 0; d < FSI_DIM; d++) {
        b.shape.min[d] = lo[d];
        b.shape.max[d] = hi[d];
        b.shape.count[d] = lround((hi[d] - lo[d]) / dx);
    }
    return b;
}

/* Lattice point j of a block, in the order the particles are built in. */
static void block_point(const solid_block *b, double dx, long j, double *x)
{
    fsi_shape_walk w;
    fsi_shape_walk_begin(&w, &b->shape, dx);
    for (long i = 0; i <= j; i++)
        fsi_shape_walk_next(&w, x);
}

static solid_region test_region(const char *section, solid_region_action action, double x0,
                                double x1, double y0, double y1)
{
    solid_region r = {section, action, {0}, {0}, {0}, 0.0, -1};
    double lo[3] = {x0, y0, -1.0}, hi[3] = {x1, y1, 1.0};
    for (int d = 0; d < FSI_DIM; d++) {
        r.min[d] = lo[d];
        r.max[d] = hi[d];
    }
    return r;
}

static void test_lattice(void)
{
    const double dx = 0.01;
    solid_block b = test_block("solid.block beam", 0.0, 1.0, 0.0, 0.2, dx);
    CHECK(b.shape.count[0] == 100 && b.shape.count[1] == 20, "counts %ld x %ld, want 100 x 20",
          b.shape.count[0], b.shape.count[1]);
    CHECK(solid_block_points(&b) == 2000L * LAYERS, "points %ld", solid_block_points(&b));
    double x[FSI_DIM];
    block_point(&b, dx, 0, x);
    CHECK(fabs(x[0] - 0.005) < 1e-15 && fabs(x[1] - 0.005) < 1e-15,
          "first point (%g, %g), want (0.005, 0.005)", x[0], x[1]);
    block_point(&b, dx, 99, x);
    CHECK(fabs(x[0] - 0.995) < 1e-14 && fabs(x[1] - 0.005) < 1e-15,
          "point 99 (%g, %g), want (0.995, 0.005): x varies fastest", x[0], x[1]);
    block_point(&b, dx, 100, x);
    CHECK(fabs(x[0] - 0.005) < 1e-15 && fabs(x[1] - 0.015) < 1e-15,
          "point 100 (%g, %g), want (0.005, 0.015)", x[0], x[1]);
    block_point(&b, dx, 1999, x);
    CHECK(fabs(x[0] - 0.995) < 1e-14 && fabs(x[1] - 0.195) < 1e-14,
          "point 1999 (%g, %g), want (0.995, 0.195)", x[0], x[1]);
    CHECK(fabs(solid_block_spacings(&b, dx, 0) - 100.0) < 1e-9, "block length in spacings");

    /* Total volume equals the block's: L / dx points of dx^DIM each. */
    solid_geometry g = {.spacing = dx, .n_blocks = 1, .blocks = &b};
    solid_particles p;
    char msg[256];
    CHECK(solid_geometry_build(&g, 2400.0, &p, NULL, msg, sizeof msg) == 0, "build: %s", msg);
    double volume = 0.0;
    for (int i = 0; i < p.n; i++)
        volume += p.volume[i];
    double want = 0.2 * (FSI_DIM == 3 ? 0.03 : 1.0);
    CHECK(fabs(volume - want) < 1e-12, "volume %.15g, want %.15g", volume, want);
    CHECK(p.density[7] == 2400.0 && p.block[7] == 0 && p.id[7] == 7, "density, block, id");
    CHECK(p.x[3] == p.x0[3] && p.v[3] == 0.0 && p.a[3] == 0.0, "x = x0, at rest");
    solid_particles_free(&p);

    /* Overlap: touching blocks do not overlap, intersecting ones do. */
    solid_block right = test_block("solid.block right", 1.0, 1.5, 0.0, 0.2, dx);
    solid_block cross = test_block("solid.block cross", 0.9, 1.2, 0.1, 0.3, dx);
    CHECK(!solid_blocks_overlap(&b, &right, dx), "touching blocks overlap");
    CHECK(solid_blocks_overlap(&b, &cross, dx), "intersecting blocks do not overlap");
}

static void test_regions(void)
{
    const double dx = 0.01;
    solid_block b = test_block("solid.block beam", 0.0, 1.0, 0.0, 0.2, dx);
    solid_region r[5] = {
        /* a notch: two columns (x = 0.495, 0.505), five rows (y < 0.05) */
        test_region("solid.region notch", SOLID_REGION_REMOVE, 0.49, 0.51, 0.0, 0.05),
        /* clamp: the two leftmost columns; its face x = 0.02 lies between points */
        test_region("solid.region clamp", SOLID_REGION_CLAMP, -1.0, 0.02, -1.0, 1.0),
        /* load: the last column, selected by a box whose faces lie on the lattice */
        test_region("solid.region tip", SOLID_REGION_LOAD, 0.99, 1.0, 0.0, 0.2),
        /* a load box drawn exactly through a column of points: closed box selects it */
        test_region("solid.region line", SOLID_REGION_LOAD, 0.505, 0.505, 0.0, 0.2),
        /* no failure: five columns, x = 0.905 .. 0.945 */
        test_region("solid.region keep", SOLID_REGION_NO_FAILURE, 0.9, 0.95, -1.0, 1.0),
    };
    r[2].force[1] = -100.0;
    r[2].ramp_time = 0.5;
    r[3].force[0] = 30.0;
    solid_geometry g = {.spacing = dx, .n_blocks = 1, .n_regions = 5, .blocks = &b, .regions = r};
    solid_particles p;
    char msg[256];
    CHECK(solid_geometry_build(&g, 1000.0, &p, NULL, msg, sizeof msg) == 0, "build: %s", msg);
    CHECK(p.n == (2000 - 10) * LAYERS, "notched beam has %d points, want %d", p.n,
          (2000 - 10) * LAYERS);
    int in_notch = 0, clamped = 0, loaded = 0, unbreakable = 0, only_unbreakable = 1, ids_ok = 1;
    for (int i = 0; i < p.n; i++) {
        in_notch += solid_region_contains(&r[0], dx, &p.x0[i * FSI_DIM]);
        clamped += (p.flags[i] & SOLID_CLAMPED) != 0;
        loaded += (p.flags[i] & SOLID_LOADED) != 0;
        if (p.flags[i] & SOLID_UNBREAKABLE) {
            unbreakable++;
            only_unbreakable &= p.flags[i] == SOLID_UNBREAKABLE;
        }
        ids_ok &= p.id[i] == i;
    }
    CHECK(unbreakable == 100 * LAYERS && only_unbreakable,
          "%d unbreakable points (want %d), %s", unbreakable, 100 * LAYERS,
          only_unbreakable ? "none also clamped or loaded" : "some also clamped or loaded");
    CHECK(in_notch == 0, "%d points created inside the removed notch", in_notch);
    CHECK(ids_ok, "ids are not the indices 0..n-1");
    CHECK(clamped == 40 * LAYERS, "%d clamped, want %d", clamped, 40 * LAYERS);
    CHECK(solid_region_select(&g, 1, &p, NULL) == 40 * LAYERS, "clamp selects %d",
          solid_region_select(&g, 1, &p, NULL));
    CHECK(solid_region_select(&g, 2, &p, NULL) == 20 * LAYERS, "tip selects %d",
          solid_region_select(&g, 2, &p, NULL));
    /* the line at x = 0.505 lost its 5 notch points */
    CHECK(solid_region_select(&g, 3, &p, NULL) == 15 * LAYERS, "line selects %d, want %d",
          solid_region_select(&g, 3, &p, NULL), 15 * LAYERS);
    CHECK(loaded == 35 * LAYERS, "%d loaded, want %d", loaded, 35 * LAYERS);

    /* Loads: equal shares, linear ramp, then hold. */
    solid_loads l;
    CHECK(solid_loads_init(&l, &g, &p, msg, sizeof msg) == 0, "loads: %s", msg);
    CHECK(l.n_regions == 2 && l.regions[0].n == 20 * LAYERS, "load regions %d", l.n_regions);
    double total[FSI_DIM];
    solid_loads_total(&l, 0.25, total);
    CHECK(fabs(total[1] + 50.0) < 1e-12 && fabs(total[0] - 30.0) < 1e-12,
          "total at half ramp (%g, %g), want (30, -50)", total[0], total[1]);
    solid_loads_total(&l, 2.0, total);
    CHECK(fabs(total[1] + 100.0) < 1e-12, "total after the ramp %g, want -100", total[1]);
    CHECK(solid_load_ramp(-1.0, 0.5) == 0.0 && solid_load_ramp(0.1, 0.0) == 1.0,
          "ramp before 0 and without ramp");
    double *force = calloc((size_t)p.n * FSI_DIM, sizeof *force);
    solid_loads_add(&l, 1.0, force);
    double sum = 0.0;
    for (int i = 0; i < p.n; i++)
        sum += force[i * FSI_DIM + 1];
    CHECK(fabs(sum + 100.0) < 1e-10, "spread load sums to %g, want -100", sum);
    free(force);
    solid_loads_free(&l);

    /* Probes: the nearest particle. */
    double tip[FSI_DIM] = {1.0, 0.097};
    double dist;
    int i = solid_nearest_particle(&p, tip, &dist);
    CHECK(i >= 0 && fabs(p.x0[i * FSI_DIM] - 0.995) < 1e-12 &&
              fabs(p.x0[i * FSI_DIM + 1] - 0.095) < 1e-12,
          "nearest to (1, 0.097) is (%g, %g), want (0.995, 0.095)", p.x0[i * FSI_DIM],
          p.x0[i * FSI_DIM + 1]);
    double want_dist = sqrt(0.005 * 0.005 * (FSI_DIM - 1) + 0.002 * 0.002);
    CHECK(fabs(dist - want_dist) < 1e-12, "distance %g, want %g", dist, want_dist);
    solid_particles_free(&p);
}

/* ------------------------------------------------------------- mode shape */

/* 004 Eq. 25's form of the same first mode, normalised to 1 at x = L. */
static double mode_004(double x, double length)
{
    double kl = SOLID_MODE_KL, k = kl / length;
    double m = sin(kl) + sinh(kl), n = cos(kl) + cosh(kl);
    double q = 2.0 * (cos(kl) * sinh(kl) - sin(kl) * cosh(kl));
    return (m * (cos(k * x) - cosh(k * x)) - n * (sin(k * x) - sinh(k * x))) / q;
}

static void test_mode_shape(void)
{
    const double length = 0.2;
    CHECK(fabs(solid_cantilever_mode(length, length) - 1.0) < 1e-15, "f(L)/f(L) = %.17g",
          solid_cantilever_mode(length, length));
    CHECK(solid_cantilever_mode(0.0, length) == 0.0 && solid_cantilever_mode(-0.01, length) == 0.0,
          "at rest at and behind the clamp");
    double worst = 0.0;
    for (int j = 0; j <= 100; j++) {
        double x = length * j / 100.0;
        worst = fmax(worst, fabs(solid_cantilever_mode(x, length) - mode_004(x, length)));
    }
    /* Gray's and 004's forms agree exactly at the root kL = 1.8751; at the rounded
     * 1.875 they differ by O(1e-4). */
    CHECK(worst < 1e-3, "Gray's and 004's first mode differ by %g", worst);

    /* The field from a case: S2's plate, a point placed exactly at x = L. */
    char messages[4096];
    const char *path = write_case(
        "mode.ini",
        "[run]\nend_time = 1\n"
        "[solid]\nsolver = testsolid\nspacing = 0.001\ndensity = 1000\n"
        "initial_velocity = cantilever_mode\nmode_amplitude = 0.01\nmode_length = 0.2\n"
        "mode_origin = 0\n"
        "[solid.block plate]\nmin = -0.003, 0" Z(0) "\nmax = 0.2, 0.02" Z(0.001) "\n");
    fsi_case *c = NULL;
    int n = load_case(path, messages, sizeof messages, &c);
    CHECK(n == 0, "mode case: %d errors:\n%s", n, messages);
    if (!c)
        return;
    double x0[4 * FSI_DIM] = {0};
    double v[4 * FSI_DIM] = {0};
    double xs[4] = {0.2, 0.1, -0.002, 0.05};
    uint8_t flags[4] = {0, 0, 0, SOLID_CLAMPED};
    for (int i = 0; i < 4; i++)
        x0[i * FSI_DIM] = xs[i];
    solid_particles p = {0};
    p.n = 4;
    p.x0 = x0;
    p.v = v;
    p.flags = flags;
    const double c0 = sqrt(3.25e6 / 1000.0);   /* S2: sqrt(K / rho) */
    char msg[256];
    CHECK(solid_initial_velocity(c, "solid", c0, &p, msg, sizeof msg) == 0, "%s", msg);
    CHECK(fabs(v[1] - 0.01 * c0) <= 4 * 2.2e-16 * 0.01 * c0,
          "vy(L) = %.17g, want V0 c0 = %.17g", v[1], 0.01 * c0);
    CHECK(v[FSI_DIM + 1] > 0.0 && v[FSI_DIM + 1] < v[1], "vy(L/2) = %g", v[FSI_DIM + 1]);
    CHECK(v[2 * FSI_DIM + 1] == 0.0 && v[3 * FSI_DIM + 1] == 0.0,
          "clamp layer and clamped points start at rest");
    CHECK(v[0] == 0.0, "no velocity along x");
    fsi_case_free(c);
}

/* ------------------------------------------------------------- the check */

static int contains(const char *text, const char *part)
{
    return strstr(text, part) != NULL;
}

static void test_check(void)
{
    char messages[8192];
    const char *good = write_case(
        "good.ini",
        "[run]\nend_time = 1\n"
        "[solid]\nsolver = testsolid\nspacing = 0.01\ndensity = 2400\n"
        "[solid.block clamp]\nmin = -0.03, 0" Z(0) "\nmax = 0, 0.2" Z(0.03) "\n"
        "[solid.block beam]\nmin = 0, 0" Z(0) "\nmax = 1, 0.2" Z(0.03) "\n"
        "[solid.region fixed]\nmin = -1, -1" Z(-1) "\nmax = 0, 1" Z(1) "\naction = clamp\n"
        "[solid.region notch]\nmin = 0.49, 0" Z(-1) "\nmax = 0.51, 0.05" Z(1) "\n"
        "action = remove\n"
        "[solid.region tip]\nmin = 0.99, 0" Z(-1) "\nmax = 1, 0.2" Z(1) "\naction = load\n"
        "force = 0, -85000" Z(0) "\nramp_time = 0.03\n"
        "[solid.probe tip]\npoint = 1, 0.1" Z(0.015) "\n");
    int n = load_case(good, messages, sizeof messages, NULL);
    CHECK(n == 0, "valid case: %d errors:\n%s", n, messages);

    const char *bad = write_case(
        "bad.ini",
        "[run]\nend_time = 1\n"                                               /* 1-2 */
        "[solid]\nsolver = testsolid\nspacing = 0.01\ndensity = 2400\n"       /* 3-6 */
        "initial_velocity = cantilever_mode\n"                                /* 7 */
        "[solid.block beam]\nmin = 0, 0" Z(0) "\nmax = 1, 0.2" Z(0.03) "\n"  /* 8-10 */
        "[solid.block cross]\nmin = 0.9, 0.1" Z(0) "\n"                      /* 11-12 */
        "max = 1.2, 0.3" Z(0.03) "\n"                                         /* 13 */
        "[solid.block odd]\nmin = 2, 0" Z(0) "\nmax = 2.5, 0.0833" Z(0.03) "\n" /* 14-16 */
        "[solid.block thin]\nmin = 3, 0" Z(0) "\nmax = 4, 0.005" Z(0.03) "\n" /* 17-19 */
        "[solid.region nowhere]\nmin = 5, 5" Z(-1) "\nmax = 6, 6" Z(1) "\n"  /* 20-22 */
        "action = clamp\nforce = 1, 1" Z(0) "\n"                              /* 23-24 */
        "[solid.region push]\nmin = 0.99, 0" Z(-1) "\nmax = 1, 0.2" Z(1) "\n" /* 25-27 */
        "action = load\n"                                                     /* 28 */
        "[solid.probe far]\npoint = 1.5, 0.1" Z(0.015) "\n");                 /* 29-30 */
    n = load_case(bad, messages, sizeof messages, NULL);
    /* cross overlaps beam; odd is 8.33 spacings high; thin is thinner than a spacing;
     * nowhere carries a force; push has none; mode without mode_length. Counting
     * (nowhere selects nothing, far is off the solid) waits for these to be fixed. */
    CHECK(n == 6, "bad case: %d errors, want 6:\n%s", n, messages);
    CHECK(contains(messages, "bad.ini:11: [solid.block cross]: overlaps [solid.block beam] "),
          "overlap not reported at the block's header:\n%s", messages);
    CHECK(contains(messages, "bad.ini:16: [solid.block odd] max: the block is 8.33 spacings "
                             "long along y"),
          "odd block not reported:\n%s", messages);
    CHECK(contains(messages, "use max = 0.08 or 0.09 along y, or spacing = "),
          "odd block: no fitting sizes proposed:\n%s", messages);
    CHECK(contains(messages, "bad.ini:19: [solid.block thin] max: ") &&
              contains(messages, "thinner than one spacing"),
          "thin block not reported:\n%s", messages);
    CHECK(contains(messages, "bad.ini:24: [solid.region nowhere] force: only a region with "
                             "action = load"),
          "force on a clamp not reported:\n%s", messages);
    CHECK(contains(messages, "bad.ini:25: [solid.region push] force: action = load needs"),
          "load without force not reported at the header:\n%s", messages);
    CHECK(contains(messages, "bad.ini:3: [solid] mode_length: "),
          "missing mode_length not reported:\n%s", messages);

    const char *empty = write_case(
        "empty.ini",
        "[run]\nend_time = 1\n"                                               /* 1-2 */
        "[solid]\nsolver = testsolid\nspacing = 0.01\ndensity = 2400\n"       /* 3-6 */
        "[solid.block beam]\nmin = 0, 0" Z(0) "\nmax = 1, 0.2" Z(0.03) "\n"  /* 7-9 */
        "[solid.region nowhere]\nmin = 5, 5" Z(-1) "\nmax = 6, 6" Z(1) "\n"  /* 10-12 */
        "action = clamp\n"                                                    /* 13 */
        "[solid.region between]\nmin = 0.306, 0" Z(-1) "\n"                   /* 14-15 */
        "max = 0.314, 0.2" Z(1) "\naction = remove\n"                         /* 16-17 */
        "[solid.probe far]\npoint = 1.5, 0.1" Z(0.015) "\n");                 /* 18-19 */
    n = load_case(empty, messages, sizeof messages, NULL);
    CHECK(n == 3, "empty selections: %d errors, want 3:\n%s", n, messages);
    CHECK(contains(messages, "empty.ini:10: [solid.region nowhere]: selects no particle"),
          "empty region not reported:\n%s", messages);
    CHECK(contains(messages, "empty.ini:14: [solid.region between]: removes no particle"),
          "remove region between the points not reported:\n%s", messages);
    CHECK(contains(messages, "empty.ini:19: [solid.probe far] point: is 0.505"),
          "probe off the solid not reported:\n%s", messages);

    /* Cracks (2D only): one that separates points, one along a lattice row, one
     * outside the body, one of no length. */
    if (FSI_DIM == 2) {
        const char *cracks = write_case(
            "cracks.ini",
            "[run]\nend_time = 1\n"                                           /* 1-2 */
            "[solid]\nsolver = testsolid\nspacing = 0.01\ndensity = 2400\n"   /* 3-6 */
            "[solid.block beam]\nmin = 0, 0\nmax = 1, 0.2\n"                   /* 7-9 */
            "[solid.crack notch]\nfrom = 0, 0.1\nto = 0.032, 0.1\n"           /* 10-12 */
            "[solid.crack on_row]\nfrom = 0.2, 0.105\nto = 0.3, 0.105\n"      /* 13-15 */
            "[solid.crack outside]\nfrom = 2, 0.1\nto = 3, 0.1\n"             /* 16-18 */
            "[solid.crack point]\nfrom = 0.5, 0.1\nto = 0.5, 0.1\n");         /* 19-21 */
        n = load_case(cracks, messages, sizeof messages, NULL);
        CHECK(n == 3, "cracks: %d errors, want 3:\n%s", n, messages);
        CHECK(!contains(messages, "[solid.crack notch]"), "a good crack refused:\n%s", messages);
        CHECK(contains(messages, "cracks.ini:13: [solid.crack on_row]: separates no two "
                                 "neighbouring particles"),
              "crack along a row not reported:\n%s", messages);
        CHECK(contains(messages, "cracks.ini:16: [solid.crack outside]: separates no two "),
              "crack outside the body not reported:\n%s", messages);
        CHECK(contains(messages, "cracks.ini:21: [solid.crack point] to: equals 'from'"),
              "crack of no length not reported:\n%s", messages);
    }

    /* Too fine a lattice is refused before anything walks it. */
    const char *huge = write_case(
        "huge.ini",
        "[run]\nend_time = 1\n"
        "[solid]\nsolver = testsolid\nspacing = 1e-6\ndensity = 2400\n"      /* 3-6 */
        "[solid.block beam]\nmin = 0, 0" Z(0) "\nmax = 1, 0.2" Z(0.03) "\n");
    n = load_case(huge, messages, sizeof messages, NULL);
    CHECK(n == 1 && contains(messages, "huge.ini:5: [solid] spacing: the blocks would hold "),
          "too many points: %d errors:\n%s", n, messages);
}

/* ------------------------------------------------------------- integration */

static void test_integration(void)
{
    /* Two points: 0 free, 1 clamped; no internal force. */
    double x0[2 * FSI_DIM] = {0}, x[2 * FSI_DIM] = {0}, v[2 * FSI_DIM] = {0},
           a[2 * FSI_DIM] = {0}, xp[2 * FSI_DIM] = {0};
    double vol[2] = {1e-4, 1e-4}, rho[2] = {1000.0, 1000.0};
    int32_t id[2] = {0, 1}, blk[2] = {0, 0};
    uint8_t flags[2] = {0, SOLID_CLAMPED};
    x0[FSI_DIM] = 1.0;
    memcpy(x, x0, sizeof x);
    solid_particles p = {2, 0.01, id, x0, x, v, a, vol, rho, flags, blk, NULL};
    double zero[2 * FSI_DIM] = {0};
    solid_forces f = {zero, zero, zero};
    solid_integrator in = {.damping = 0.0, .gravity = {0.0, -9.81}, .max_step = 0.01};

    /* Free fall: Verlet is exact for constant acceleration. */
    solid_acceleration(&p, &f, &in);
    const double h = 1e-3;
    double work = 0.0;
    solid_fault fault;
    int rc = 0;
    for (int s = 0; s < 40; s++) {
        solid_verlet_drift(&p, h, xp);
        rc |= solid_verlet_kick(&p, &f, h, &in, xp, &work, &fault);
    }
    double t = 40 * h, want = -0.5 * 9.81 * t * t;
    CHECK(rc == 0, "free fall reported a fault: %s", fault.what);
    CHECK(fabs(x[1] - want) < 1e-15, "free fall y = %.17g, want %.17g", x[1], want);
    CHECK(fabs(v[1] + 9.81 * t) < 1e-14, "free fall vy = %g", v[1]);
    CHECK(x[FSI_DIM] == 1.0 && x[FSI_DIM + 1] == 0.0 && v[FSI_DIM + 1] == 0.0 &&
              a[FSI_DIM + 1] == 0.0,
          "clamped point moved");
    /* Work of gravity = m g h = kinetic energy gained. */
    double m = 0.1;
    CHECK(fabs(work - m * 9.81 * (-want)) < 1e-12, "gravity work %.15g, want %.15g", work,
          m * 9.81 * (-want));
    CHECK(fabs(solid_kinetic_energy(&p) - work) < 1e-12, "kinetic %.15g != work %.15g",
          solid_kinetic_energy(&p), work);

    /* Damping: the implicit update tends to the terminal velocity g / c even for c h > 2. */
    in.damping = 5000.0;
    for (int s = 0; s < 200; s++) {
        solid_verlet_drift(&p, h, xp);
        solid_verlet_kick(&p, &f, h, &in, xp, &work, &fault);
    }
    CHECK(fabs(v[1] + 9.81 / 5000.0) < 1e-12, "terminal vy = %.15g, want %.15g", v[1],
          -9.81 / 5000.0);

    /* Health: a non-finite force and a jump farther than max_step. */
    double bad[2 * FSI_DIM] = {0};
    bad[0] = NAN;
    solid_forces fb = {bad, zero, zero};
    solid_verlet_drift(&p, h, xp);
    CHECK(solid_verlet_kick(&p, &fb, h, &in, xp, &work, &fault) == -1 && fault.particle == 0 &&
              contains(fault.what, "not finite"),
          "NaN force not caught: %d %s", fault.particle, fault.what);
    x[0] = x[1] = 0.0;
    v[0] = v[1] = a[0] = a[1] = 0.0;
    in.damping = 0.0;
    v[0] = 20.0;    /* 0.02 m in one 1e-3 s step, two spacings */
    solid_verlet_drift(&p, h, xp);
    CHECK(solid_verlet_kick(&p, &f, h, &in, xp, &work, &fault) == -1 && fault.particle == 0 &&
              contains(fault.what, "moved"),
          "jump not caught: %d %s", fault.particle, fault.what);
}

/* ------------------------------------------------------------- interface */

static void test_interface(void)
{
    double x0[3 * FSI_DIM] = {0}, x[3 * FSI_DIM] = {0}, v[3 * FSI_DIM] = {0},
           a[3 * FSI_DIM] = {0};
    double vol[3] = {1, 2, 3}, rho[3] = {1, 1, 1};
    int32_t id[3] = {0, 1, 2}, blk[3] = {0, 0, 0};
    uint8_t flags[3] = {0};
    for (int i = 0; i < 3; i++)
        x[i * FSI_DIM] = i;
    solid_particles p = {3, 1.0, id, x0, x, v, a, vol, rho, flags, blk, NULL};
    solid_interface_buffers b;
    CHECK(solid_interface_init(&b, 3) == 0, "init");
    b.surface[0] = b.surface[2] = 1;
    /* The density sent is the one given (a model's current one), not p's reference. */
    const double current[3] = {7.0, 8.0, 9.0};
    CHECK(solid_interface_gather(&b, &p, current, 0.0) == 2 && b.state.id[1] == 2 &&
              b.state.position[FSI_DIM] == 2.0 && b.state.volume[1] == 3.0 &&
              b.state.density[0] == 7.0 && b.state.density[1] == 9.0,
          "gather");
    double force[3 * FSI_DIM], pressure[3];
    int32_t ids[2] = {2, 0};
    double f[2 * FSI_DIM] = {0}, pr[2] = {5.0, 6.0};
    f[1] = -1.0;
    f[FSI_DIM + 1] = -2.0;
    fsi_interface in = {.n = 2, .id = ids, .pressure = pr, .force = f};
    char msg[256] = "";
    CHECK(solid_interface_take(&b, &in, &p, force, pressure, msg, sizeof msg) == 0, "%s", msg);
    CHECK(force[2 * FSI_DIM + 1] == -1.0 && force[1] == -2.0 && force[FSI_DIM + 1] == 0.0 &&
              pressure[2] == 5.0,
          "loads by id");
    ids[1] = 1;   /* not sent */
    CHECK(solid_interface_take(&b, &in, &p, force, pressure, msg, sizeof msg) == -1 &&
              contains(msg, "id 1, which was not sent"),
          "load for an unsent id: %s", msg);
    ids[1] = 7;   /* unknown */
    CHECK(solid_interface_take(&b, &in, &p, force, pressure, msg, sizeof msg) == -1 &&
              contains(msg, "id 7, which does not exist"),
          "load for an unknown id: %s", msg);
    ids[1] = 2;   /* duplicate */
    CHECK(solid_interface_take(&b, &in, &p, force, pressure, msg, sizeof msg) == -1 &&
              contains(msg, "two loads for particle id 2"),
          "duplicate load: %s", msg);
    solid_interface_free(&b);
}

/* The band of points within the interface depth D of the body's surface
 * (solid_interface_band), on a solid four times finer than the fluid: a block on a
 * mirror clamp (which fills its sites: no surface below the block) marks exactly the
 * points whose distance to the nearest free face is at most D, here D = 1.2 * 3 * dx_f
 * - dx_f / 2 = 0.031 m, 12 layers of dx = 2.5 mm (the horizon-cut set of a 3 dx
 * horizon is 3 of them). They are sent (gather), their loads are taken, and each
 * gets the impedance area dx^(dim-1) dx / dx_f. */
static void test_interface_band(void)
{
    const double dx = 0.0025, dx_f = 0.01;
    /* Only the first FSI_DIM of x, y (and z 0 .. 0.03) are used. */
    /* The clamp is as deep as the band's radius D + dx/2 (13 layers): a thinner one
     * would leave empty sites below it within reach of the lowest body points. */
    solid_block blocks[2] = {test_block("solid.block clamp", 0.0, 0.1, -0.0325, 0.0, dx),
                             test_block("solid.block body", 0.0, 0.1, 0.0, 0.1, dx)};
    solid_region r = test_region("solid.region foot", SOLID_REGION_CLAMP, -1.0, 1.0, -0.0325, 0.0);
    r.clamp_face = solid_clamp_face_parse("y_max");
    solid_geometry g = {.spacing = dx, .n_blocks = 2, .n_regions = 1, .blocks = blocks,
                        .regions = &r};
    solid_particles p;
    char msg[256];
    int unpaired = -1;
    CHECK(solid_geometry_build(&g, 1000.0, &p, &unpaired, msg, sizeof msg) == 0 &&
              unpaired == 0, "build: %s", msg);

    char text[512];
    /* support: the fluid's support radius as validation derives it (here ULPH's
     * default 1.2 * 3 * dx_f); the solid reads it whatever the fluid's solver. */
    snprintf(text, sizeof text, "[solid]\nspacing = %g\n\n[fluid]\nspacing = %g\nsupport = %.17g\n",
             dx, dx_f, 1.2 * 3.0 * dx_f);
    fsi_case *c = fsi_case_read(write_case("band.ini", text), stderr);
    CHECK(c != NULL, "cannot read band.ini");
    double spacing_f = 0.0;
    const double reach = c ? solid_interface_fluid_reach(c, &spacing_f) : 0.0;
    const double depth = c ? solid_interface_depth(c) : 0.0;
    CHECK(fabs(reach - 0.031) < 1e-15 && depth == reach && spacing_f == dx_f,
          "reach %.17g (want 0.031), depth %.17g, fluid spacing %g", reach, depth, spacing_f);
    fsi_case_free(c);

    solid_interface_buffers b;
    CHECK(solid_interface_init(&b, p.n) == 0, "init");
    const int marked = solid_interface_band(&b, &p, depth);
    const double hi[3] = {0.1, 0.1, 0.03};
    int expected = 0, wrong = 0, clamp_marked = 0;
    for (int i = 0; i < p.n; i++) {
        const double *x = &p.x0[i * FSI_DIM];
        if (p.flags[i] & SOLID_MIRRORED) {
            clamp_marked += b.band[i];
            continue;
        }
        /* Free faces: x = 0, x = 0.1, y = 0.1 (and z = 0, 0.03); the floor is the clamp. */
        double d = fmin(x[0], fmin(hi[0] - x[0], hi[1] - x[1]));
        for (int k = 2; k < FSI_DIM; k++)
            d = fmin(d, fmin(x[k], hi[k] - x[k]));
        const int in = d <= depth + 1e-9;
        expected += in;
        wrong += in != b.band[i];
    }
    CHECK(marked == expected && wrong == 0 && clamp_marked == 0,
          "band: %d marked, %d expected, %d points wrong, %d clamp points marked", marked,
          expected, wrong, clamp_marked);
    if (FSI_DIM == 2)   /* 12 columns each side, 12 rows over the 16 between them */
        CHECK(marked == 40 * 24 + 12 * 16, "band of %d points, want %d", marked, 40 * 24 + 12 * 16);
    /* At equal spacings the default depth 3.1 dx is the 3 layers of a 3 dx horizon. */
    CHECK(solid_interface_band(&b, &p, 3.1 * dx) == (FSI_DIM == 2 ? 40 * 6 + 3 * 34 : marked) ||
              FSI_DIM != 2,
          "band at equal spacings: %d points, want %d", solid_interface_band(&b, &p, 3.1 * dx),
          40 * 6 + 3 * 34);
    CHECK(solid_interface_band(&b, &p, 0.0) == 0, "depth 0 marks points");

    /* Sent, loaded and damped: the point deepest in the band, in the middle of the left
     * side, with no horizon-cut mark. */
    solid_interface_band(&b, &p, depth);
    int deep = -1;
    for (int i = 0; i < p.n && deep < 0; i++)
        if (b.band[i] && fabs(p.x0[i * FSI_DIM] - 11.5 * dx) < 1e-12 &&
            fabs(p.x0[i * FSI_DIM + 1] - 20.5 * dx) < 1e-12)
            deep = i;
    CHECK(deep >= 0, "no band point at depth 11.5 dx");
    if (deep >= 0) {
        CHECK(solid_interface_gather(&b, &p, p.density, 0.0) == marked,
              "gather sends %d, want %d", b.state.n, marked);
        int32_t ids[1] = {deep};
        double f[FSI_DIM] = {0}, pr[1] = {1.0};
        f[0] = 2.0;
        fsi_interface in = {.n = 1, .id = ids, .pressure = pr, .force = f};
        double *force = calloc((size_t)p.n * FSI_DIM, sizeof *force);
        double *pressure = calloc((size_t)p.n, sizeof *pressure);
        double *damping = calloc((size_t)p.n, sizeof *damping);
        CHECK(solid_interface_take(&b, &in, &p, force, pressure, msg, sizeof msg) == 0, "%s", msg);
        const double z = 1000.0 * 34.3;
        b.fluid_spacing = dx_f;
        solid_interface_damping(&b, &p, force, z, damping);
        const double want = z * pow(dx, FSI_DIM - 1) * (dx / dx_f) /
                            (p.density[deep] * p.volume[deep]);
        CHECK(fabs(damping[deep] - want) <= 1e-14 * want,
              "impedance damping %.17g, want %.17g (area dx^(dim-1) dx / dx_f)", damping[deep],
              want);
        b.fluid_spacing = 0.0;   /* unknown fluid spacing: the solid's face */
        solid_interface_damping(&b, &p, force, z, damping);
        CHECK(damping[deep] == z * pow(dx, FSI_DIM - 1) / (p.density[deep] * p.volume[deep]),
              "impedance damping without a fluid spacing %.17g", damping[deep]);
        free(force);
        free(pressure);
        free(damping);
    }
    solid_interface_free(&b);
    solid_particles_free(&p);
}

/* The window means the solid sends (solid_interface_gather): for a body moving as
 * x(t) = x0 + v0 t + a t^2 / 2 over windows of different lengths, the mean velocity of
 * the last window is exact, (x_k - x_{k-1}) / dt = v0 + a (t_{k-1} + t_k) / 2, and so is
 * the acceleration from the last two means (their difference over the time between
 * their midpoints). The first gathers send the instants, then a zero acceleration. */
static void test_interface_window_means(void)
{
    double x0[FSI_DIM] = {0}, x[FSI_DIM] = {0}, v[FSI_DIM] = {0}, a[FSI_DIM] = {0};
    double vol[1] = {1}, rho[1] = {1};
    int32_t id[1] = {0}, blk[1] = {0};
    uint8_t flags[1] = {0};
    solid_particles p = {1, 1.0, id, x0, x, v, a, vol, rho, flags, blk, NULL};
    solid_interface_buffers b;
    CHECK(solid_interface_init(&b, 1) == 0, "init");
    b.surface[0] = 1;
    /* Window k starts at t_k = sum of the lengths before it; window 0 has length 0. */
    const double v0 = 0.3, acc = -9.81, length[] = {0.0, 2e-3, 1e-3, 3e-3, 1.5e-3};
    double t = 0.0;
    for (int k = 0; k < 5; k++) {
        const double dt_last = k > 0 ? length[k - 1] : 0.0;
        t += dt_last;
        x[0] = v0 * t + 0.5 * acc * t * t;
        v[0] = v0 + acc * t;
        a[0] = acc;
        solid_interface_gather(&b, &p, p.density, dt_last);
        const double sent_v = b.state.velocity[0], sent_a = b.state.acceleration[0];
        if (k <= 1) {
            CHECK(sent_v == v[0] && sent_a == a[0], "window %d: the instants (%g, %g)", k,
                  sent_v, sent_a);
        } else {
            const double mean_v = v0 + acc * (t - 0.5 * dt_last);
            CHECK(fabs(sent_v - mean_v) < 1e-12, "window %d: mean velocity %.15g, exact %.15g",
                  k, sent_v, mean_v);
            CHECK(k == 2 ? sent_a == 0.0 : fabs(sent_a - acc) < 1e-9,
                  "window %d: mean acceleration %.15g", k, sent_a);
        }
    }
    solid_interface_free(&b);
}

/* A clamp region with clamp_face = x_max left of a beam: every clamp point pairs with
 * its image across x = 0 (a beam point), is flagged SOLID_MIRRORED, follows it with
 * the opposite displacement and velocity after a drift, hands its internal force to
 * it with the opposite sign, and counts for neither mass nor kinetic energy. */
static void test_mirror_clamp(void)
{
    const double dx = 0.01;
    solid_block blocks[2] = {test_block("solid.block clamp", -0.03, 0.0, 0.0, 0.05, dx),
                             test_block("solid.block beam", 0.0, 0.2, 0.0, 0.05, dx)};
    solid_region r = test_region("solid.region fixed", SOLID_REGION_CLAMP, -0.03, 0.0, -1.0, 1.0);
    r.clamp_face = solid_clamp_face_parse("x_max");
    CHECK(r.clamp_face == 1, "x_max parses to %d", r.clamp_face);
    CHECK(solid_clamp_face_parse("none") == -1 && solid_clamp_face_parse("w_max") == -2,
          "clamp_face words");
    solid_geometry g = {.spacing = dx, .n_blocks = 2, .n_regions = 1, .blocks = blocks,
                        .regions = &r};
    solid_particles p;
    char msg[256];
    int unpaired = -1;
    CHECK(solid_geometry_build(&g, 1000.0, &p, &unpaired, msg, sizeof msg) == 0, "build: %s",
          msg);
    CHECK(unpaired == 0, "%d clamp points without an image", unpaired);
    int mirrored = 0, images_ok = 1;
    for (int i = 0; i < p.n; i++) {
        if (!(p.flags[i] & SOLID_MIRRORED))
            continue;
        mirrored++;
        const int m = p.mirror ? p.mirror[i] : -1;
        images_ok &= m >= 0 && !(p.flags[m] & SOLID_CLAMPED) &&
                     fabs(p.x0[m * FSI_DIM] + p.x0[i * FSI_DIM]) < 1e-12 &&
                     fabs(p.x0[m * FSI_DIM + 1] - p.x0[i * FSI_DIM + 1]) < 1e-12;
    }
    CHECK(mirrored == 15 * LAYERS, "%d mirrored points, want %d", mirrored, 15 * LAYERS);
    CHECK(images_ok, "a mirrored point's partner is not its image across x = 0");
    const double beam_mass = 1000.0 * 0.2 * 0.05 * (FSI_DIM == 3 ? 0.03 : 1.0);
    CHECK(fabs(solid_total_mass(&p) - beam_mass) < 1e-9 * beam_mass,
          "mass %g counts the mirrored points (beam alone %g)", solid_total_mass(&p), beam_mass);

    /* Move every beam point by a velocity field; a drift must carry the images. */
    for (int i = 0; i < p.n; i++)
        if (!(p.flags[i] & SOLID_CLAMPED))
            for (int d = 0; d < FSI_DIM; d++)
                p.v[i * FSI_DIM + d] = 0.1 * (d + 1) * p.x0[i * FSI_DIM];
    double *x_prev = malloc((size_t)p.n * FSI_DIM * sizeof *x_prev);
    double *force = calloc((size_t)p.n * FSI_DIM, sizeof *force);
    solid_verlet_drift(&p, 0.5, x_prev);
    double worst = 0.0;
    for (int i = 0; i < p.n; i++) {
        const int m = p.mirror[i];
        if (m < 0)
            continue;
        for (int d = 0; d < FSI_DIM; d++) {
            const double ug = p.x[i * FSI_DIM + d] - p.x0[i * FSI_DIM + d];
            const double um = p.x[m * FSI_DIM + d] - p.x0[m * FSI_DIM + d];
            worst = fmax(worst, fmax(fabs(ug + um), fabs(p.v[i * FSI_DIM + d] + p.v[m * FSI_DIM + d])));
        }
        force[i * FSI_DIM] = 2.0;
        force[m * FSI_DIM] = 5.0;
    }
    CHECK(worst < 1e-15, "mirrored points do not follow their partners (off by %g)", worst);
    const double ke = solid_kinetic_energy(&p);
    double ke_beam = 0.0;
    for (int i = 0; i < p.n; i++)
        if (!(p.flags[i] & SOLID_CLAMPED))
            for (int d = 0; d < FSI_DIM; d++)
                ke_beam += 0.5 * p.density[i] * p.volume[i] * p.v[i * FSI_DIM + d] * p.v[i * FSI_DIM + d];
    CHECK(fabs(ke - ke_beam) <= 1e-12 * ke_beam, "kinetic energy %g counts mirrored points "
          "(beam %g)", ke, ke_beam);
    solid_mirror_forces(&p, force);
    int moved = 1;
    for (int i = 0; i < p.n; i++) {
        const int m = p.mirror[i];
        if (m >= 0)
            moved &= force[i * FSI_DIM] == 0.0 && force[m * FSI_DIM] == 3.0;
    }
    CHECK(moved, "the force on a mirrored point does not go to its partner as f_m - f_g");
    free(x_prev);
    free(force);
    solid_particles_free(&p);
}

/* clamp_face belongs to clamp regions only, and names an axis of this build. */
static void test_clamp_face_check(void)
{
    char messages[4096];
    const char *bad = write_case(
        "bad_face.ini",
        "[run]\nend_time = 1\n"                                               /* 1-2 */
        "[solid]\nsolver = testsolid\nspacing = 0.01\ndensity = 2400\n"       /* 3-6 */
        "[solid.block beam]\nmin = 0, 0" Z(0) "\nmax = 1, 0.2" Z(0.03) "\n"  /* 7-9 */
        "[solid.region tip]\nmin = 0.99, 0" Z(-1) "\nmax = 1, 0.2" Z(1) "\n" /* 10-12 */
        "action = load\nforce = 0, -1" Z(0) "\nclamp_face = x_max\n");       /* 13-15 */
    int n = load_case(bad, messages, sizeof messages, NULL);
    CHECK(n == 1, "clamp_face on a load region: %d errors, want 1:\n%s", n, messages);
    CHECK(contains(messages, "bad_face.ini:15: [solid.region tip] clamp_face: only a region "
                             "with action = clamp takes a clamp_face"),
          "clamp_face on a load region not reported at its line:\n%s", messages);
#if FSI_DIM == 2
    const char *z = write_case(
        "z_face.ini",
        "[run]\nend_time = 1\n"
        "[solid]\nsolver = testsolid\nspacing = 0.01\ndensity = 2400\n"
        "[solid.block beam]\nmin = 0, 0\nmax = 1, 0.2\n"
        "[solid.region fixed]\nmin = -1, -1\nmax = 0.01, 1\naction = clamp\n"
        "clamp_face = z_max\n");
    n = load_case(z, messages, sizeof messages, NULL);
    CHECK(n == 1 && contains(messages, "clamp_face: 'z_max' names an axis this 2D build does "
                                       "not have"),
          "z face in 2D: %d errors:\n%s", n, messages);
#endif
}

int main(void)
{
    make_scratch();
    test_lattice();
    test_regions();
    test_mirror_clamp();
    test_mode_shape();
    test_check();
    test_clamp_face_check();
    test_integration();
    test_interface();
    test_interface_window_means();
    test_interface_band();
    if (failures) {
        fprintf(stderr, "test_solid_geometry: %d of %d checks failed\n", failures, checks);
        return 1;
    }
    printf("test_solid_geometry: all %d checks passed\n", checks);
    return 0;
}
