/* Unit test of core/case_file.c: reading, --set overrides, validation against a
 * small schema built here, error messages (text and line), defaults, object
 * sections, solver checks, schema flaws, the resolved file round trip and the
 * Markdown reference. Exit 0 = pass; every failed check is printed. Scratch files go to $FSI_TEST_TMP/case_file (default /tmp/fsi_test_case). */
#include "case_file.h"
#include "dim.h"
#include "solver_registry.h"

#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "unit_check.h"

/* ------------------------------------------------------------- the schema */

#if FSI_DIM == 2
#define GRAVITY_DEFAULT "0, -9.81"
#define GRAVITY_GIVEN "1.5, -2"
#define GRAVITY_WRONG "1 2 3"
#else
#define GRAVITY_DEFAULT "0, 0, -9.81"
#define GRAVITY_GIVEN "1.5, 0 -2"
#define GRAVITY_WRONG "1 2 3 4"
#endif

static const fsi_key_spec run_keys[] = {
    { "end_time", FSI_KEY_REAL, "s", NULL, FSI_BOUND_MIN_OPEN, 0, 0, NULL,
      "Simulated time at which the run stops." },
    { "output_interval", FSI_KEY_REAL, "s", "0.1", FSI_BOUND_MIN_OPEN, 0, 0, NULL,
      "Simulated time between outputs." },
    { "gravity", FSI_KEY_VECTOR, "m/s^2", GRAVITY_DEFAULT, 0, 0, 0, NULL,
      "Gravitational acceleration." },
    { "verbose", FSI_KEY_BOOL, "-", "no", 0, 0, 0, NULL, "Print progress." },
    { "relaxation", FSI_KEY_REAL, "-", "0.5", FSI_BOUND_MIN | FSI_BOUND_MAX, 0, 1, NULL,
      "Under-relaxation factor." },
};

static const fsi_key_spec output_keys[] = {
    { "format", FSI_KEY_CHOICE, "-", "h5", 0, 0, 0, "h5|csv", "File format." },
};

static const fsi_key_table sections[] = {
    { "run", "Time span and coupling of the run.", run_keys, 5 },
    { "output", "What is written.", output_keys, 1 },
};

static const fsi_key_spec common_keys[] = {
    { "solver", FSI_KEY_STRING, "-", NULL, 0, 0, 0, NULL, "The solver of this participant." },
    { "executable", FSI_KEY_STRING, "-", "", 0, 0, 0, NULL, "Program for solver = external." },
};
static const fsi_key_table participant = { "participant", "Keys of every participant.",
                                           common_keys, 2 };

static const fsi_key_spec spring_keys[] = {
    { "stiffness", FSI_KEY_REAL, "N/m", NULL, FSI_BOUND_MIN_OPEN, 0, 0, NULL,
      "Spring stiffness." },
    { "particles", FSI_KEY_INT, "-", "10", FSI_BOUND_MIN, 1, 0, NULL, "Number of particles." },
    { "mode", FSI_KEY_CHOICE, "-", "a", 0, 0, 0, "a|b", "Oscillation mode." },
};
static const fsi_key_table spring_table = { "spring_oscillators", "Springs.", spring_keys, 3 };

static const fsi_key_spec dashpot_keys[] = {
    { "damping", FSI_KEY_REAL, "N s/m", "0", FSI_BOUND_MIN, 0, 0, NULL, "Damping coefficient." },
};
static const fsi_key_table dashpot_table = { "linear_dashpot", "Dashpot.", dashpot_keys, 1 };

static const fsi_key_table *const spring_tables[] = { &spring_table };
static const fsi_key_table *const dashpot_tables[] = { &dashpot_table };

/* A solid made of objects, its keys split over tables the way the real solid
 * solvers split them: keys of every solid and material keys in [solid], the
 * model's own in its solver section [solid.blocks]. */
#if FSI_DIM == 2
#define VEC_ZERO "0, 0"
#define VEC_MAX "1, 0.2"
#define VEC_MAX_SET "2, 0.5"
#define VEC_SMALL "-1, 0.2"
#else
#define VEC_ZERO "0, 0, 0"
#define VEC_MAX "1, 0.2, 0.1"
#define VEC_MAX_SET "2, 0.5, 0.1"
#define VEC_SMALL "-1, 0.2, 0.1"
#endif

static const fsi_key_spec solid_common_keys[] = {
    { "time_step", FSI_KEY_REAL, "s", "1e-4", FSI_BOUND_MIN_OPEN, 0, 0, NULL, "Time step." },
};
static const fsi_key_table solid_common_table = { "solid_common", "Keys of every solid.",
                                                  solid_common_keys, 1 };

static const fsi_key_spec material_keys[] = {
    { "density", FSI_KEY_REAL, "kg/m^3", NULL, FSI_BOUND_MIN_OPEN, 0, 0, NULL, "Density." },
    { "youngs_modulus", FSI_KEY_REAL, "Pa", "1e9", FSI_BOUND_MIN_OPEN, 0, 0, NULL,
      "Young's modulus." },
};
static const fsi_key_table material_table = { "materials", "Material keys.", material_keys, 2 };

static const fsi_key_spec blocks_own_keys[] = {
    { "horizon", FSI_KEY_REAL, "-", "3", FSI_BOUND_MIN_OPEN, 0, 0, NULL, "Horizon factor." },
};
static const fsi_key_table blocks_own_table = { "blocks", "Keys of the block solid.",
                                                blocks_own_keys, 1 };

static const fsi_key_table *const blocks_tables[] = { &solid_common_table, &material_table };

/* Two fluid schemes with keys of their own in [fluid.waves] and [fluid.puffs] (one
 * name in both: each section has its own table) and a common table in [fluid]. Only
 * waves has a support radius. */
static const fsi_key_spec fluid_common_keys[] = {
    { "spacing", FSI_KEY_REAL, "m", "0.01", FSI_BOUND_MIN_OPEN, 0, 0, NULL, "Spacing." },
};
static const fsi_key_table fluid_common_table = { "fluid_common", "Keys of every scheme.",
                                                  fluid_common_keys, 1 };
static const fsi_key_table *const fluid_tables[] = { &fluid_common_table };

static const fsi_key_spec waves_keys[] = {
    { "smoothing", FSI_KEY_REAL, "-", "1.5", FSI_BOUND_MIN_OPEN, 0, 0, NULL, "h / dx." },
    { "alpha", FSI_KEY_REAL, "-", "0.02", FSI_BOUND_MIN | FSI_BOUND_MAX, 0, 1, NULL,
      "Artificial viscosity." },
};
static const fsi_key_table waves_table = { "waves", "Keys of the waves scheme.", waves_keys, 2 };

static const fsi_key_spec puffs_keys[] = {
    { "smoothing", FSI_KEY_REAL, "-", "2", FSI_BOUND_MIN_OPEN, 0, 0, NULL, "h / dx." },
    { "delta", FSI_KEY_REAL, "-", "0.1", FSI_BOUND_MIN, 0, 0, NULL, "Density diffusion." },
};
static const fsi_key_table puffs_table = { "puffs", "Keys of the puffs scheme.", puffs_keys, 2 };

static double waves_support(const fsi_case *c, const char *role)
{
    return 2.0 * fsi_case_get_real(c, fsi_case_solver_section(c, role), "smoothing", -1.0) *
           fsi_case_get_real(c, role, "spacing", -1.0);
}

static const fsi_key_spec block_keys[] = {
    { "min", FSI_KEY_VECTOR, "m", NULL, 0, 0, 0, NULL, "Lower corner." },
    { "max", FSI_KEY_VECTOR, "m", NULL, 0, 0, 0, NULL, "Upper corner." },
    { "spacing", FSI_KEY_REAL, "m", "0.01", FSI_BOUND_MIN_OPEN, 0, 0, NULL, "Particle spacing." },
};
static const fsi_key_table block_table = { "block", "A box of particles.", block_keys, 3 };

static const fsi_key_spec region_keys[] = {
    { "select", FSI_KEY_CHOICE, "-", "inside", 0, 0, 0, "inside|outside", "Which particles." },
    { "fixed", FSI_KEY_BOOL, "-", "no", 0, 0, 0, NULL, "Clamp them." },
};
static const fsi_key_table region_table = { "region", "A set of particles.", region_keys, 2 };

static const fsi_key_spec probe_keys[] = {
    { "at", FSI_KEY_VECTOR, "m", NULL, 0, 0, 0, NULL, "Probe position." },
};
static const fsi_key_table probe_table = { "probe", "A recorded point.", probe_keys, 1 };

static const fsi_object_kind block_objects[] = {
    { "block", "Particles filling a box.", &block_table, 1 },
    { "region", "Particles selected by a box.", &region_table, 0 },
    { "probe", "A point whose motion is recorded.", &probe_table, 0 },
};

/* The semantic check of the block solid: every block's max lies above its min.
 * Written the way a solver's check would be, with fsi_case_origin for WHERE. */
static int check_calls;

static int check_blocks(const fsi_case *c, const char *role, FILE *errors)
{
    check_calls++;
    const char *blocks[8];
    int n = fsi_case_objects(c, role, "block", blocks, 8);
    int bad = 0;
    for (int i = 0; i < n && i < 8; i++) {
        double lo[FSI_DIM], hi[FSI_DIM];
        if (fsi_case_get_vector(c, blocks[i], "min", lo) != 0 ||
            fsi_case_get_vector(c, blocks[i], "max", hi) != 0) {
            fprintf(errors, "%s: [%s]: check called with an invalid block\n",
                    fsi_case_origin(c, blocks[i], NULL), blocks[i]);
            bad++;
            continue;
        }
        for (int d = 0; d < FSI_DIM; d++) {
            if (hi[d] <= lo[d]) {
                fprintf(errors, "%s: [%s] max: block '%s' is empty (max <= min)\n",
                        fsi_case_origin(c, blocks[i], "max"), blocks[i],
                        fsi_case_object_name(blocks[i]));
                bad++;
                break;
            }
        }
    }
    return bad;
}

static const fsi_solver_spec solvers[] = {
    { .name = "spring_oscillators", .role = "solid", .executable = "fsi_spring_solid",
      .description = "Particles on springs.", .key_tables = spring_tables, .n_key_tables = 1 },
    { .name = "linear_dashpot", .role = "fluid", .executable = "fsi_dashpot_fluid",
      .description = "A linear dashpot as fluid.", .key_tables = dashpot_tables,
      .n_key_tables = 1 },
    { .name = "blocks", .role = "solid", .executable = "fsi_blocks",
      .description = "A solid of blocks, regions and probes.", .key_tables = blocks_tables,
      .n_key_tables = 2, .own_keys = &blocks_own_table, .objects = block_objects,
      .n_objects = 3, .check = check_blocks },
    { .name = "waves", .role = "fluid", .executable = "fsi_waves",
      .description = "A particle fluid.", .key_tables = fluid_tables, .n_key_tables = 1,
      .own_keys = &waves_table, .support = waves_support },
    { .name = "puffs", .role = "fluid", .executable = "fsi_puffs",
      .description = "Another particle fluid.", .key_tables = fluid_tables, .n_key_tables = 1,
      .own_keys = &puffs_table },
};

static const char *const roles[] = { "fluid", "solid" };

static const fsi_case_schema schema = {
    sections, 2, &participant, roles, 2, solvers, 5,
};

/* ---------------------------------------------------------------- helpers */

static char tmp_dir[1024];

static void make_dirs(const char *path)
{
    char buf[1024];
    snprintf(buf, sizeof buf, "%s", path);
    for (char *p = buf + 1; *p; p++) {
        if (*p == '/') {
            *p = '\0';
            mkdir(buf, 0777);
            *p = '/';
        }
    }
    if (mkdir(buf, 0777) != 0 && errno != EEXIST) {
        fprintf(stderr, "cannot create %s: %s\n", buf, strerror(errno));
        exit(2);
    }
}

/* Writes a case file into the scratch folder; returns its path (caller frees). */
static char *write_case(const char *name, const char *text)
{
    size_t n = strlen(tmp_dir) + strlen(name) + 2;
    char *path = malloc(n);
    snprintf(path, n, "%s/%s", tmp_dir, name);
    FILE *f = fopen(path, "w");
    if (!f || fputs(text, f) < 0 || fclose(f) != 0) {
        fprintf(stderr, "cannot write %s\n", path);
        exit(2);
    }
    return path;
}

static char *read_all(FILE *f)
{
    fflush(f);
    rewind(f);
    size_t cap = 4096, len = 0;
    char *buf = malloc(cap);
    size_t got;
    while ((got = fread(buf + len, 1, cap - len - 1, f)) > 0) {
        len += got;
        if (cap - len < 2) {
            cap *= 2;
            buf = realloc(buf, cap);
        }
    }
    buf[len] = '\0';
    fclose(f);
    return buf;
}

/* Line (1-based) of the first line of 'text' that contains 'needle'; the tests
 * find lines this way so that editing a case text cannot silently shift them. */
static int line_of(const char *text, const char *needle)
{
    const char *hit = strstr(text, needle);
    if (!hit) {
        fprintf(stderr, "test bug: '%s' not in case text\n", needle);
        exit(2);
    }
    int line = 1;
    for (const char *p = text; p < hit; p++)
        line += *p == '\n';
    return line;
}

static int count_lines(const char *text)
{
    int n = 0;
    for (const char *p = text; *p; p++)
        n += *p == '\n';
    return n;
}

static int count_occurrences(const char *text, const char *needle)
{
    int n = 0;
    for (const char *p = strstr(text, needle); p; p = strstr(p + 1, needle))
        n++;
    return n;
}

static char *format(const char *fmt, ...) __attribute__((format(printf, 1, 2)));
static char *format(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    int n = vsnprintf(NULL, 0, fmt, ap);
    va_end(ap);
    char *s = malloc((size_t)n + 1);
    va_start(ap, fmt);
    vsnprintf(s, (size_t)n + 1, fmt, ap);
    va_end(ap);
    return s;
}

/* Checks that 'messages' contains "PATH:LINE: " + tail, where LINE is the line
 * of 'text' holding 'anchor'. */
static void expect_at(const char *messages, const char *path, const char *text,
                      const char *anchor, const char *tail, int src_line)
{
    char *want = format("%s:%d: %s", path, line_of(text, anchor), tail);
    if (!strstr(messages, want)) {
        failures++;
        fprintf(stderr, "FAIL %s:%d: expected message\n  %s\ngot:\n%s\n", __FILE__, src_line,
                want, messages);
    }
    checks++;
    free(want);
}
#define EXPECT_AT(msgs, path, text, anchor, tail) \
    expect_at(msgs, path, text, anchor, tail, __LINE__)

/* Reads and validates; returns the case (or NULL) and the messages of both. */
static fsi_case *load(const char *path, char **messages, int *n_errors)
{
    FILE *err = tmpfile();
    fsi_case *c = fsi_case_read(path, err);
    *n_errors = c ? fsi_case_validate(c, &schema, err) : -1;
    *messages = read_all(err);
    return c;
}

/* ------------------------------------------------------------------ tests */

static const char valid_text[] =
    "# A valid case\n"
    "; with both comment styles\n"
    "[run]\n"
    "end_time = 2.5\n"
    "gravity = " GRAVITY_GIVEN "\n"
    "verbose = Yes\n"
    "relaxation = 1\n"
    "\n"
    "[solid]   ; the particles\n"
    "solver = spring_oscillators\n"
    "stiffness = 1e3   ; N/m\n"
    "   particles = 4\n"
    "\n"
    "[fluid]\n"
    "solver: linear_dashpot\n";

static void test_valid(void)
{
    char *path = write_case("valid.ini", valid_text);
    char *msgs;
    int n;
    fsi_case *c = load(path, &msgs, &n);
    CHECK(c != NULL, "valid case not read: %s", msgs);
    CHECK(n == 0, "valid case gave %d errors:\n%s", n, msgs);
    CHECK(msgs[0] == '\0', "valid case printed messages:\n%s", msgs);
    if (c) {
        CHECK(strcmp(fsi_case_path(c), path) == 0, "path %s", fsi_case_path(c));
        CHECK(fsi_case_get_real(c, "run", "end_time", -1) == 2.5, "end_time");
        CHECK(fsi_case_get_real(c, "run", "output_interval", -1) == 0.1, "default output_interval");
        CHECK(fsi_case_get_real(c, "run", "relaxation", -1) == 1.0, "relaxation");
        CHECK(fsi_case_get_bool(c, "run", "verbose", 0) == 1, "verbose = Yes");
        double g[FSI_DIM];
        CHECK(fsi_case_get_vector(c, "run", "gravity", g) == 0, "gravity absent");
        CHECK(g[0] == 1.5 && g[FSI_DIM - 1] == -2.0, "gravity = %g .. %g", g[0], g[FSI_DIM - 1]);
        CHECK(fsi_case_get_real(c, "solid", "stiffness", -1) == 1000.0, "stiffness 1e3");
        CHECK(fsi_case_get_int(c, "solid", "particles", -1) == 4, "indented particles");
        const char *mode = fsi_case_get(c, "solid", "mode");
        CHECK(mode && strcmp(mode, "a") == 0, "default mode: %s", mode ? mode : "(null)");
        const char *solver = fsi_case_get(c, "solid", "solver");
        CHECK(solver && strcmp(solver, "spring_oscillators") == 0, "solver");
        const char *fluid_solver = fsi_case_get(c, "fluid", "solver");
        CHECK(fluid_solver && strcmp(fluid_solver, "linear_dashpot") == 0, "key: value syntax");
        CHECK(fsi_case_get_real(c, "fluid", "damping", -1) == 0.0, "default damping");
        const char *exe = fsi_case_get(c, "fluid", "executable");
        CHECK(exe && exe[0] == '\0', "default executable should be empty");
        CHECK(fsi_case_has_section(c, "output"), "absent [output] should exist with defaults");
        const char *fmt = fsi_case_get(c, "output", "format");
        CHECK(fmt && strcmp(fmt, "h5") == 0, "output.format default");
        CHECK(!fsi_case_has_section(c, "nothing"), "has_section of an absent section");
        CHECK(fsi_case_get(c, "solid", "nothing") == NULL, "absent key");
        CHECK(fsi_case_get(c, "Solid", "solver") == NULL, "section names are case-sensitive");
        CHECK(fsi_case_get_real(c, "solid", "nothing", 7.5) == 7.5, "real fallback");
        CHECK(fsi_case_get_int(c, "solid", "nothing", 3) == 3, "int fallback");
        CHECK(fsi_case_get_bool(c, "solid", "nothing", 1) == 1, "bool fallback");
        CHECK(fsi_case_get_vector(c, "solid", "nothing", g) == -1, "vector absent");
        CHECK(fsi_case_get_real(c, "solid", "solver", 4.0) == 4.0, "unparsable real -> fallback");
    }
    fsi_case_free(c);
    free(msgs);
    free(path);
}

/* Windows line ends and a UTF-8 byte-order mark are accepted. */
static void test_crlf_bom(void)
{
    char *path = write_case("crlf.ini", "\xEF\xBB\xBF[run]\r\nend_time = 3\r\n"
                                        "[solid]\r\nsolver = spring_oscillators\r\n"
                                        "stiffness = 2\r\n");
    char *msgs;
    int n;
    fsi_case *c = load(path, &msgs, &n);
    CHECK(c && n == 0, "CRLF/BOM case: %s", msgs);
    if (c) {
        CHECK(fsi_case_get_real(c, "run", "end_time", -1) == 3.0, "end_time with CRLF");
        CHECK(fsi_case_get_real(c, "solid", "stiffness", -1) == 2.0, "stiffness with CRLF");
    }
    fsi_case_free(c);
    free(msgs);
    free(path);
}

static void test_typo(void)
{
    static const char text[] =
        "[run]\nend_time = 1\n[solid]\nsolver = spring_oscillators\nstiffnes = 5\n";
    char *path = write_case("typo.ini", text);
    char *msgs;
    int n;
    fsi_case *c = load(path, &msgs, &n);
    CHECK(c != NULL, "typo case should read");
    CHECK(n == 1, "typo: %d errors (want 1):\n%s", n, msgs);
    CHECK(count_lines(msgs) == 1, "typo: one line of messages:\n%s", msgs);
    EXPECT_AT(msgs, path, text, "stiffnes =",
              "[solid] stiffnes: unknown key 'stiffnes' (did you mean 'stiffness'?)");
    fsi_case_free(c);
    free(msgs);
    free(path);

    /* A key that is nothing like a known one lists the known keys instead. */
    static const char text2[] =
        "[run]\nend_time = 1\nzzzzzz = 1\n[solid]\nsolver = spring_oscillators\n"
        "stiffness = 5\nPARTICLES = 3\n";
    path = write_case("typo2.ini", text2);
    c = load(path, &msgs, &n);
    CHECK(n == 2, "typo2: %d errors:\n%s", n, msgs);
    EXPECT_AT(msgs, path, text2, "zzzzzz", "[run] zzzzzz: unknown key 'zzzzzz' (known keys: "
                                            "end_time, output_interval, gravity, verbose, "
                                            "relaxation)");
    EXPECT_AT(msgs, path, text2, "PARTICLES",
              "[solid] PARTICLES: unknown key 'PARTICLES' (did you mean 'particles'?)");
    CHECK(strstr(msgs, "zzzzzz") < strstr(msgs, "PARTICLES"), "messages in line order");
    fsi_case_free(c);
    free(msgs);
    free(path);
}

static void test_missing_required(void)
{
    static const char text[] =
        "[run]\nend_time = 1\n\n# the solid\n[solid]\nsolver = spring_oscillators\n";
    char *path = write_case("missing.ini", text);
    char *msgs;
    int n;
    fsi_case *c = load(path, &msgs, &n);
    CHECK(n == 1, "missing: %d errors:\n%s", n, msgs);
    EXPECT_AT(msgs, path, text, "[solid]", "[solid] stiffness: required key missing");
    fsi_case_free(c);
    free(msgs);
    free(path);

    /* A missing fixed section with required keys, and a participant without solver. */
    static const char text2[] = "[solid]\nstiffness = 1\n";
    path = write_case("missing2.ini", text2);
    c = load(path, &msgs, &n);
    CHECK(n == 2, "missing2: %d errors:\n%s", n, msgs);
    char *want = format("%s: [run]: section missing (required keys: end_time)\n", path);
    CHECK(strstr(msgs, want) != NULL, "missing section message, want %s got:\n%s", want, msgs);
    free(want);
    EXPECT_AT(msgs, path, text2, "[solid]", "[solid] solver: required key missing");
    CHECK(c && !fsi_case_has_section(c, "run"), "[run] with required keys is not invented");
    fsi_case_free(c);
    free(msgs);
    free(path);
}

static void test_bad_values(void)
{
    static const char text[] =
        "[run]\n"
        "end_time = abc\n"
        "output_interval = -0.01\n"
        "gravity = " GRAVITY_WRONG "\n"
        "verbose = maybe\n"
        "relaxation = 1.5\n"
        "[solid]\n"
        "solver = spring_oscillators\n"
        "stiffness = 1e999\n"
        "particles = 2.5\n"
        "mode = c\n"
        "[fluid]\n"
        "solver = linear_dashpot\n"
        "damping =\n"
        "[output]\n"
        "format = nan\n";
    char *path = write_case("bad.ini", text);
    char *msgs;
    int n;
    fsi_case *c = load(path, &msgs, &n);
    CHECK(n == 10, "bad values: %d errors (want 10):\n%s", n, msgs);
    EXPECT_AT(msgs, path, text, "end_time", "[run] end_time: 'abc' is not a number");
    EXPECT_AT(msgs, path, text, "output_interval", "[run] output_interval: -0.01 must be > 0");
    EXPECT_AT(msgs, path, text, "gravity", "[run] gravity: '" GRAVITY_WRONG "' has");
    EXPECT_AT(msgs, path, text, "verbose", "[run] verbose: 'maybe' is not a boolean");
    EXPECT_AT(msgs, path, text, "relaxation", "[run] relaxation: 1.5 must be <= 1");
    EXPECT_AT(msgs, path, text, "stiffness", "[solid] stiffness: '1e999' is out of range");
    EXPECT_AT(msgs, path, text, "particles", "[solid] particles: '2.5' is not a whole number");
    EXPECT_AT(msgs, path, text, "mode", "[solid] mode: 'c' is not one of: a, b\n");
    EXPECT_AT(msgs, path, text, "damping", "[fluid] damping: value is empty");
    EXPECT_AT(msgs, path, text, "format", "[output] format: 'nan' is not one of: h5, csv");
    fsi_case_free(c);
    free(msgs);
    free(path);

    static const char text2[] =
        "[run]\nend_time = inf\noutput_interval = nan\nrelaxation = -0\n"
        "[solid]\nsolver = spring_oscillators\nstiffness = -0.01\nparticles = 0\nmode = A\n"
        "[fluid]\nsolver = linear_dashpot\ndamping = 1,5\n";
    path = write_case("bad2.ini", text2);
    c = load(path, &msgs, &n);
    CHECK(n == 6, "bad2: %d errors (want 6):\n%s", n, msgs);
    EXPECT_AT(msgs, path, text2, "mode",
              "[solid] mode: 'A' is not one of: a, b (did you mean 'a'?)\n");
    EXPECT_AT(msgs, path, text2, "end_time", "[run] end_time: 'inf' is not a finite number");
    EXPECT_AT(msgs, path, text2, "output_interval",
              "[run] output_interval: 'nan' is not a finite number");
    EXPECT_AT(msgs, path, text2, "stiffness", "[solid] stiffness: -0.01 must be > 0");
    EXPECT_AT(msgs, path, text2, "particles", "[solid] particles: 0 must be >= 1");
    EXPECT_AT(msgs, path, text2, "damping", "[fluid] damping: '1,5' is not a number");
    CHECK(!strstr(msgs, "relaxation"), "-0 is within 0 .. 1:\n%s", msgs);
    fsi_case_free(c);
    free(msgs);
    free(path);
}

static void test_solvers(void)
{
    static const char text[] =
        "[run]\nend_time = 1\n"
        "[solid]\nsolver = sprng_oscillators\nstiffness = 1\n"
        "[fluid]\nsolver = spring_oscillators\n";
    char *path = write_case("solver.ini", text);
    char *msgs;
    int n;
    fsi_case *c = load(path, &msgs, &n);
    CHECK(n == 2, "solvers: %d errors:\n%s", n, msgs);
    EXPECT_AT(msgs, path, text, "sprng",
              "[solid] solver: unknown solver 'sprng_oscillators' (did you mean "
              "'spring_oscillators'?); solid solvers: spring_oscillators, blocks, external");
    EXPECT_AT(msgs, path, text, "solver = spring_oscillators",
              "[fluid] solver: 'spring_oscillators' is a solid solver, not a fluid solver "
              "(fluid solvers: linear_dashpot, waves, puffs, external)");
    fsi_case_free(c);
    free(msgs);
    free(path);

    /* External solvers take any keys but need a program. */
    static const char text2[] =
        "[run]\nend_time = 1\n"
        "[fluid]\nsolver = external\nexecutable = /bin/true\nmesh_file = a.msh\n"
        "[solid]\nsolver = external\nparticles = -4\n";
    path = write_case("external.ini", text2);
    c = load(path, &msgs, &n);
    CHECK(n == 1, "external: %d errors:\n%s", n, msgs);
    EXPECT_AT(msgs, path, text2, "[solid]", "[solid] executable: required key missing");
    if (c) {
        const char *mesh = fsi_case_get(c, "fluid", "mesh_file");
        CHECK(mesh && strcmp(mesh, "a.msh") == 0, "pass-through key");
        const char *p = fsi_case_get(c, "solid", "particles");
        CHECK(p && strcmp(p, "-4") == 0, "pass-through keys are not checked");
    }
    fsi_case_free(c);
    free(msgs);
    free(path);

    static const char text3[] = "[run]\nend_time = 1\n[rn]\nx = 1\n[sovler]\n";
    path = write_case("sections.ini", text3);
    c = load(path, &msgs, &n);
    CHECK(n == 2, "unknown sections: %d errors:\n%s", n, msgs);
    EXPECT_AT(msgs, path, text3, "[rn]",
              "unknown section [rn] (did you mean [run]? known: run, output, fluid, solid)");
    EXPECT_AT(msgs, path, text3, "[sovler]",
              "unknown section [sovler] (known: run, output, fluid, solid)");
    fsi_case_free(c);
    free(msgs);
    free(path);
}

/* Errors found while reading: the case is not returned. */
static void expect_read_error(const char *name, const char *text, const char *anchor,
                              const char *tail, int want_lines, int src_line)
{
    char *path = write_case(name, text);
    FILE *err = tmpfile();
    fsi_case *c = fsi_case_read(path, err);
    char *msgs = read_all(err);
    checks++;
    if (c) {
        failures++;
        fprintf(stderr, "FAIL %s:%d: %s should not read\n", __FILE__, src_line, name);
    }
    expect_at(msgs, path, text, anchor, tail, src_line);
    checks++;
    if (count_lines(msgs) != want_lines) {
        failures++;
        fprintf(stderr, "FAIL %s:%d: %s: want %d messages, got:\n%s", __FILE__, src_line, name,
                want_lines, msgs);
    }
    fsi_case_free(c);
    free(msgs);
    free(path);
}
#define EXPECT_READ_ERROR(name, text, anchor, tail, lines) \
    expect_read_error(name, text, anchor, tail, lines, __LINE__)

static const char syntax[] = "syntax error: expected 'key = value', '[section]' or a comment";

static void test_syntax(void)
{
    EXPECT_READ_ERROR("syntax1.ini", "[run]\nend_time = 1\nthis line has no equals\n",
                      "this line", syntax, 1);
    /* Every syntax error is reported, not only the first one. */
    static const char two[] = "[run]\nfirst bad\nend_time = 1\n  second bad\n";
    EXPECT_READ_ERROR("syntax2.ini", two, "first bad", syntax, 2);
    EXPECT_READ_ERROR("syntax2b.ini", two, "second bad", syntax, 2);
    EXPECT_READ_ERROR("before.ini", "# header\nend_time = 1\n[run]\n", "end_time",
                      "key 'end_time' comes before any [section] line", 1);
    static const char dup[] = "[run]\nend_time = 1\n\nend_time = 2\n";
    char *tail = format("[run] end_time: given twice (first at %s/dup.ini:2)", tmp_dir);
    EXPECT_READ_ERROR("dup.ini", dup, "end_time = 2", tail, 1);
    free(tail);
    tail = format("section [run] given twice (first at %s/dupsec.ini:1)", tmp_dir);
    EXPECT_READ_ERROR("dupsec.ini", "[run]\nend_time = 1\n[run]\nend_time = 2\n",
                      "[run]\nend_time = 2", tail, 1);
    free(tail);
    EXPECT_READ_ERROR("bracket.ini", "[run\nend_time = 1\n", "[run",
                      "syntax error: '[' without a closing ']'", 1);
    EXPECT_READ_ERROR("after.ini", "[run] x\nend_time = 1\n", "[run]",
                      "syntax error: unexpected text after ']': 'x'", 1);
    EXPECT_READ_ERROR("empty.ini", "[ ]\nend_time = 1\n", "[ ]",
                      "syntax error: empty section name", 1);
    EXPECT_READ_ERROR("noname.ini", "[run]\n = 1\n", " = 1",
                      "syntax error: key name missing before '='", 1);

    /* Lines longer than inih's buffer are refused, not cut in two. */
    char longline[400];
    memset(longline, 'x', sizeof longline);
    memcpy(longline, "[solid]\nlong = ", 15);
    strcpy(longline + 15 + 250, "\nafter = 1\n");
    EXPECT_READ_ERROR("long.ini", longline, "long =",
                      "line too long: 257 characters, at most 199 are allowed", 1);

    /* ... but a long line that fits is read whole. */
    char fits[300];
    memset(fits, 'y', sizeof fits);
    memcpy(fits, "[solid]\nfits = ", 15);
    strcpy(fits + 15 + 180, "\n");
    char *path = write_case("fits.ini", fits);
    FILE *err = tmpfile();
    fsi_case *c = fsi_case_read(path, err);
    char *msgs = read_all(err);
    CHECK(c != NULL, "a 187-character line should read: %s", msgs);
    const char *v = c ? fsi_case_get(c, "solid", "fits") : NULL;
    CHECK(v && strlen(v) == 180, "long value length %zu", v ? strlen(v) : 0);
    fsi_case_free(c);
    free(msgs);
    free(path);

    /* Long comment and section lines are ours to parse, so they have no limit. */
    char comment[600];
    memset(comment, 'c', sizeof comment);
    comment[0] = '#';
    strcpy(comment + 500, "\n[run]\nend_time = 1\n");
    path = write_case("comment.ini", comment);
    err = tmpfile();
    c = fsi_case_read(path, err);
    msgs = read_all(err);
    CHECK(c != NULL, "a long comment should be fine: %s", msgs);
    fsi_case_free(c);
    free(msgs);
    free(path);

    err = tmpfile();
    c = fsi_case_read("/nonexistent/dir/case.ini", err);
    msgs = read_all(err);
    CHECK(c == NULL, "nonexistent file");
    CHECK(strstr(msgs, "/nonexistent/dir/case.ini: cannot open case file:") != NULL,
          "open error message: %s", msgs);
    free(msgs);
}

static void test_override(void)
{
    char *path = write_case("override.ini", valid_text);
    FILE *err = tmpfile();
    fsi_case *c = fsi_case_read(path, err);
    CHECK(c != NULL, "override case");
    if (!c) {
        fclose(err);
        free(path);
        return;
    }
    CHECK(fsi_case_override(c, "solid.stiffness=5", err) == 0, "good --set");
    CHECK(fsi_case_override(c, "solid.mode=c", err) == 0, "bad choice is for validate");
    CHECK(fsi_case_override(c, "fluid.damping = 0.25", err) == 0, "--set with blanks");
    CHECK(fsi_case_override(c, "run.output_interval=-1", err) == 0, "bad value is for validate");
    CHECK(fsi_case_override(c, "output.format=csv", err) == 0, "--set into an absent section");
    CHECK(fsi_case_override(c, "nonsense", err) == -1, "--set without '='");
    CHECK(fsi_case_override(c, "novalue=3", err) == -1, "--set without '.'");
    CHECK(fsi_case_override(c, ".x=3", err) == -1, "--set without section");
    CHECK(fsi_case_override(c, "run.a b=3", err) == -1, "--set key with a blank");
    CHECK(fsi_case_override(c, "run.x=1 ; 2", err) == -1, "--set value with a comment");
    int n = fsi_case_validate(c, &schema, err);
    char *msgs = read_all(err);
    CHECK(n == 2, "override: %d errors:\n%s", n, msgs);
    const char *mode_msg = strstr(msgs, "--set solid.mode=c: [solid] mode: 'c' is not one of");
    const char *interval_msg = strstr(msgs, "--set run.output_interval=-1:");
    CHECK(mode_msg && interval_msg && mode_msg < interval_msg,
          "--set messages in command-line order:\n%s", msgs);
    CHECK(strstr(msgs, "--set nonsense: expected section.key=value\n") != NULL, "form: %s", msgs);
    CHECK(strstr(msgs, "--set novalue=3: expected section.key=value\n") != NULL, "dot: %s", msgs);
    CHECK(strstr(msgs, "--set run.a b=3: key 'a b' may not contain") != NULL, "key: %s", msgs);
    CHECK(strstr(msgs, "--set run.x=1 ; 2: value may not contain ';'") != NULL, "value: %s",
          msgs);
    CHECK(strstr(msgs, "--set run.output_interval=-1: [run] output_interval: -1 must be > 0\n")
              != NULL, "bad --set origin:\n%s", msgs);
    CHECK(fsi_case_get_real(c, "solid", "stiffness", -1) == 5.0, "--set wins over the file");
    CHECK(fsi_case_get_real(c, "fluid", "damping", -1) == 0.25, "--set adds a key");
    const char *fmt = fsi_case_get(c, "output", "format");
    CHECK(fmt && strcmp(fmt, "csv") == 0, "--set section");
    fsi_case_free(c);
    free(msgs);
    free(path);
}

static const char *const roundtrip_keys[][2] = {
    { "run", "end_time" },        { "run", "output_interval" }, { "run", "gravity" },
    { "run", "verbose" },         { "run", "relaxation" },      { "solid", "solver" },
    { "solid", "executable" },    { "solid", "stiffness" },     { "solid", "particles" },
    { "solid", "mode" },          { "fluid", "solver" },        { "fluid", "executable" },
    { "fluid", "args" },          { "fluid", "mesh_file" },     { "output", "format" },
};

static void test_round_trip(void)
{
    static const char text[] =
        "[run]\nend_time = 2.5\ngravity = " GRAVITY_GIVEN "\n"
        "[solid]\nsolver = spring_oscillators\nstiffness = 1e3\n"
        "[fluid]\nsolver = external\nexecutable = /bin/true\nmesh_file = a b;c\n";
    char *path = write_case("round.ini", text);
    FILE *err = tmpfile();
    fsi_case *c = fsi_case_read(path, err);
    CHECK(c != NULL, "round trip case");
    if (!c) {
        fclose(err);
        free(path);
        return;
    }
    /* Long enough that the origin comment does not fit on the key's line. */
    char set[200];
    memset(set, 'v', sizeof set);
    memcpy(set, "fluid.args=", 11);
    set[160] = '\0';
    CHECK(fsi_case_override(c, set, err) == 0, "long --set");
    CHECK(fsi_case_override(c, "solid.particles=7", err) == 0, "--set particles");
    int n = fsi_case_validate(c, &schema, err);
    char *msgs = read_all(err);
    CHECK(n == 0, "round trip validate: %s", msgs);
    free(msgs);

    char *out_path = format("%s/resolved.ini", tmp_dir);
    FILE *out = fopen(out_path, "w");
    fsi_case_write_resolved(c, out);
    fclose(out);
    out = fopen(out_path, "r");
    char *resolved = read_all(out);
    char *origin = format("# %s:%d", path, line_of(text, "end_time"));
    CHECK(strstr(resolved, origin) != NULL, "file origin %s in:\n%s", origin, resolved);
    free(origin);
    CHECK(strstr(resolved, "output_interval = 0.1") != NULL, "default written:\n%s", resolved);
    CHECK(strstr(resolved, "# default") != NULL, "default origin:\n%s", resolved);
    CHECK(strstr(resolved, "# --set solid.particles=7") != NULL, "--set origin:\n%s", resolved);
    CHECK(count_occurrences(resolved, "[output]") == 1, "absent section written:\n%s", resolved);

    err = tmpfile();
    fsi_case *back = fsi_case_read(out_path, err);
    n = back ? fsi_case_validate(back, &schema, err) : -1;
    msgs = read_all(err);
    CHECK(back && n == 0, "resolved file does not validate (%d):\n%s\n--- file:\n%s", n, msgs,
          resolved);
    for (size_t i = 0; back && i < sizeof roundtrip_keys / sizeof roundtrip_keys[0]; i++) {
        const char *sec = roundtrip_keys[i][0], *key = roundtrip_keys[i][1];
        const char *a = fsi_case_get(c, sec, key), *b = fsi_case_get(back, sec, key);
        CHECK(a && b && strcmp(a, b) == 0, "round trip [%s] %s: '%s' vs '%s'", sec, key,
              a ? a : "(null)", b ? b : "(null)");
    }
    const char *args = back ? fsi_case_get(back, "fluid", "args") : NULL;
    CHECK(args && strlen(args) == 149, "long value survives");
    /* Defaults stay defaults (a solver reading the resolved file must not take them
     * for keys the user gave); keys from the file do not. */
    const char *o_default = back ? fsi_case_origin(back, "run", "output_interval") : NULL;
    CHECK(o_default && strcmp(o_default, "default") == 0, "default origin read back: %s",
          o_default ? o_default : "(null)");
    const char *o_given = back ? fsi_case_origin(back, "run", "end_time") : NULL;
    CHECK(o_given && strcmp(o_given, "default") != 0, "given key read back as given: %s",
          o_given ? o_given : "(null)");
    fsi_case_free(back);
    fsi_case_free(c);
    free(msgs);
    free(resolved);
    free(out_path);
    free(path);
}

static void test_markdown(void)
{
    FILE *f = tmpfile();
    fsi_case_schema_markdown(&schema, f);
    char *md = read_all(f);
    static const char *const wanted[] = {
        "## [run]", "## [output]", "## Participant sections [fluid] and [solid]",
        "### solver = spring_oscillators (solid)", "### solver = linear_dashpot (fluid)",
        "| key | type | unit | default | allowed | meaning |",
        "| `end_time` | real | s | required | > 0 | Simulated time at which the run stops. |",
        "| `particles` | integer | - | `10` | >= 1 |", "| `relaxation` | real | - | `0.5` | 0 .. 1 |",
        "| `mode` | choice | - | `a` | a, b |", "| `damping` | real | N s/m | `0` | >= 0 |",
        "Time span and coupling of the run.", "Particles on springs.",
    };
    for (size_t i = 0; i < sizeof wanted / sizeof wanted[0]; i++)
        CHECK(strstr(md, wanted[i]) != NULL, "markdown lacks '%s'", wanted[i]);
    const fsi_key_table *tables[] = { &sections[0], &sections[1], &participant, &spring_table,
                                      &dashpot_table };
    for (size_t t = 0; t < sizeof tables / sizeof tables[0]; t++)
        for (int k = 0; k < tables[t]->n_keys; k++) {
            char *cell = format("| `%s` |", tables[t]->keys[k].key);
            CHECK(strstr(md, cell) != NULL, "markdown lacks key %s", tables[t]->keys[k].key);
            free(cell);
        }
    free(md);
}

/* ---------------------------------------------------------- object sections */

static const char objects_text[] =
    "[run]\nend_time = 1\n"
    "[solid]\nsolver = blocks\ndensity = 1000\n"
    "[solid.block beam]\nmin = " VEC_ZERO "\nmax = " VEC_MAX "\n"
    "[solid.region clamp]   ; the left end\nfixed = yes\n"
    "[solid.block   base_2]\nmin = " VEC_ZERO "\nmax = " VEC_MAX "\nspacing = 0.02\n"
    "[solid.probe tip-1]\nat = " VEC_MAX "\n"
    "[fluid]\nsolver = external\nexecutable = /bin/true\n"
    "[fluid.wall tank]\nanything = goes\n";

static void test_objects(void)
{
    char *path = write_case("objects.ini", objects_text);
    char *msgs;
    int n;
    int calls = check_calls;
    fsi_case *c = load(path, &msgs, &n);
    CHECK(c && n == 0, "objects case: %d errors:\n%s", n, msgs);
    CHECK(check_calls == calls + 1, "check hook called %d times", check_calls - calls);
    if (!c)
        goto done;
    const char *blocks[4] = { NULL, NULL, NULL, NULL };
    CHECK(fsi_case_objects(c, "solid", "block", blocks, 4) == 2, "two blocks");
    CHECK(blocks[0] && strcmp(blocks[0], "solid.block beam") == 0, "first block %s", blocks[0]);
    CHECK(blocks[1] && strcmp(blocks[1], "solid.block base_2") == 0,
          "second block, blanks cut to one: %s", blocks[1]);
    CHECK(blocks[2] == NULL, "only two names filled");
    const char *first = NULL;
    CHECK(fsi_case_objects(c, "solid", "block", &first, 1) == 2, "count beyond max_sections");
    CHECK(first && strcmp(first, "solid.block beam") == 0, "file order");
    CHECK(fsi_case_objects(c, "solid", "block", NULL, 0) == 2, "count only");
    CHECK(fsi_case_objects(c, "solid", "region", NULL, 0) == 1, "one region");
    CHECK(fsi_case_objects(c, "solid", "blo", NULL, 0) == 0, "kind prefix is not a kind");
    CHECK(fsi_case_objects(c, "fluid", "wall", NULL, 0) == 1, "external objects are kept");
    CHECK(fsi_case_objects(c, "fluid", "block", NULL, 0) == 0, "no fluid blocks");

    CHECK(fsi_case_get_real(c, "solid.block beam", "spacing", -1) == 0.01, "default spacing");
    CHECK(fsi_case_get_real(c, "solid.block base_2", "spacing", -1) == 0.02, "given spacing");
    double v[FSI_DIM];
    CHECK(fsi_case_get_vector(c, "solid.block beam", "max", v) == 0 && v[0] == 1.0, "block max");
    CHECK(fsi_case_get_bool(c, "solid.region clamp", "fixed", 0) == 1, "region fixed");
    const char *sel = fsi_case_get(c, "solid.region clamp", "select");
    CHECK(sel && strcmp(sel, "inside") == 0, "region default select");
    CHECK(fsi_case_get_real(c, "solid", "youngs_modulus", -1) == 1e9, "material table default");
    CHECK(fsi_case_get_real(c, "solid.blocks", "horizon", -1) == 3.0,
          "own table default in the chosen solver's section");
    CHECK(fsi_case_get(c, "solid", "horizon") == NULL, "own key in [solid]");
    CHECK(fsi_case_get_real(c, "solid", "time_step", -1) == 1e-4, "common table default");
    const char *any = fsi_case_get(c, "fluid.wall tank", "anything");
    CHECK(any && strcmp(any, "goes") == 0, "external object key passes through");

    const char *name = fsi_case_object_name("solid.block beam");
    CHECK(name && strcmp(name, "beam") == 0, "object name %s", name ? name : "(null)");
    CHECK(fsi_case_object_name("solid") == NULL, "a participant is no object");
    CHECK(fsi_case_object_name("solid.block") == NULL, "no name");
    CHECK(fsi_case_object_name("solid beam") == NULL, "no kind");
    CHECK(fsi_case_object_name(".block beam") == NULL, "no role");

    char *want = format("%s:%d", path, line_of(objects_text, "[solid.block beam]"));
    const char *o = fsi_case_origin(c, "solid.block beam", NULL);
    CHECK(o && strcmp(o, want) == 0, "header origin %s, want %s", o ? o : "(null)", want);
    free(want);
    want = format("%s:%d", path, line_of(objects_text, "max = " VEC_MAX "\n[solid.region"));
    o = fsi_case_origin(c, "solid.block beam", "max");
    CHECK(o && strcmp(o, want) == 0, "key origin %s, want %s", o ? o : "(null)", want);
    free(want);
    o = fsi_case_origin(c, "solid.block beam", "spacing");
    CHECK(o && strcmp(o, "default") == 0, "default origin %s", o ? o : "(null)");
    o = fsi_case_origin(c, "output", NULL);
    CHECK(o && strcmp(o, "default") == 0, "absent fixed section origin %s", o ? o : "(null)");
    CHECK(fsi_case_origin(c, "solid.block beam", "nothing") == NULL, "absent key origin");
    CHECK(fsi_case_origin(c, "solid.block nothing", NULL) == NULL, "absent section origin");
done:
    fsi_case_free(c);
    free(msgs);
    free(path);
}

static void test_object_errors(void)
{
    static const char text[] =
        "[run]\nend_time = 1\n"
        "[solid]\nsolver = blocks\ndensity = 1000\n"
        "[solid.block beam]\nmin = " VEC_ZERO "\nmax = " VEC_MAX "\n"
        "[solid.blok a]\nmin = 1\n"
        "[solid.block bad.name]\nmin = " VEC_ZERO "\nmax = " VEC_MAX "\n"
        "[solid.block]\n"
        "[solid.probe p]\n"
        "[solid.region q]\nselec = inside\n"
        "[solid.region r]\nselect = outsid\n"
        "[fluidd.wall w]\n"
        "[fluid.wall w]\n"
        "[solid block]\n";
    char *path = write_case("object_errors.ini", text);
    char *msgs;
    int n;
    int calls = check_calls;
    fsi_case *c = load(path, &msgs, &n);
    CHECK(c != NULL, "object errors case should read:\n%s", msgs);
    CHECK(n == 9, "object errors: %d errors (want 9):\n%s", n, msgs);
    EXPECT_AT(msgs, path, text, "[solid.blok a]",
              "[solid.blok a]: unknown object kind 'blok' for solver blocks (did you mean "
              "'block'? kinds: block, region, probe)\n");
    EXPECT_AT(msgs, path, text, "[solid.block bad.name]",
              "[solid.block bad.name]: object name 'bad.name' must be one word of letters, "
              "digits, '_' and '-'\n");
    EXPECT_AT(msgs, path, text, "[solid.block]\n",
              "[solid.block]: object name missing (object sections are written "
              "[solid.block NAME])\n");
    EXPECT_AT(msgs, path, text, "[solid.probe p]", "[solid.probe p] at: required key missing\n");
    EXPECT_AT(msgs, path, text, "selec =",
              "[solid.region q] selec: unknown key 'selec' (did you mean 'select'?)\n");
    EXPECT_AT(msgs, path, text, "select = outsid",
              "[solid.region r] select: 'outsid' is not one of: inside, outside (did you mean "
              "'outside'?)\n");
    EXPECT_AT(msgs, path, text, "[fluidd.wall w]",
              "[fluidd.wall w]: unknown participant 'fluidd' (did you mean 'fluid'?); object "
              "sections are written [ROLE.KIND NAME] with ROLE one of: fluid, solid\n");
    EXPECT_AT(msgs, path, text, "[fluid.wall w]",
              "[fluid.wall w]: no [fluid] section (the participant this object belongs to)\n");
    EXPECT_AT(msgs, path, text, "[solid block]",
              "unknown section [solid block] (did you mean [solid]? known: run, output, fluid, "
              "solid); object sections are written [ROLE.KIND NAME]\n");
    CHECK(!strstr(msgs, "[solid.block] min"), "keys of a nameless object are not checked:\n%s",
          msgs);
    CHECK(!strstr(msgs, "[solid.blok a] min"), "keys of an unknown kind are not checked:\n%s",
          msgs);
    CHECK(check_calls == calls, "check hook must not run after key errors");
    fsi_case_free(c);
    free(msgs);
    free(path);

    /* Too few objects: reported at the participant's header. A solver without
     * object kinds says so. */
    static const char text2[] =
        "[run]\nend_time = 1\n\n[solid]\nsolver = blocks\ndensity = 1\n";
    path = write_case("too_few.ini", text2);
    c = load(path, &msgs, &n);
    CHECK(n == 1, "too few: %d errors:\n%s", n, msgs);
    EXPECT_AT(msgs, path, text2, "[solid]",
              "[solid]: solver blocks needs at least 1 [solid.block NAME] section, found 0\n");
    CHECK(check_calls == calls, "check hook must not run with too few objects");
    fsi_case_free(c);
    free(msgs);
    free(path);

    static const char text3[] =
        "[run]\nend_time = 1\n[solid]\nsolver = spring_oscillators\nstiffness = 1\n"
        "[solid.block beam]\nmin = 0\n";
    path = write_case("no_kinds.ini", text3);
    c = load(path, &msgs, &n);
    CHECK(n == 1, "no kinds: %d errors:\n%s", n, msgs);
    EXPECT_AT(msgs, path, text3, "[solid.block beam]",
              "[solid.block beam]: unknown object kind 'block' for solver spring_oscillators "
              "(it takes no object sections)\n");
    fsi_case_free(c);
    free(msgs);
    free(path);

    /* A wrong solver is the one error: its objects cannot be judged. */
    static const char text4[] =
        "[run]\nend_time = 1\n[solid]\nsolver = blokcs\n[solid.block beam]\nmin = 0\n";
    path = write_case("bad_solver_objects.ini", text4);
    c = load(path, &msgs, &n);
    CHECK(n == 1, "bad solver with objects: %d errors:\n%s", n, msgs);
    EXPECT_AT(msgs, path, text4, "solver = blokcs", "[solid] solver: unknown solver 'blokcs'");
    fsi_case_free(c);
    free(msgs);
    free(path);
}

static void test_duplicate_object(void)
{
    static const char text[] =
        "[solid]\nsolver = blocks\n[solid.block beam]\nmin = 0\n"
        "[solid.region beam]\n"         /* another kind may reuse the name */
        "[solid.block  beam]\nmax = 1\n";
    char *tail = format("section [solid.block beam] given twice (first at %s/dupobj.ini:%d)",
                        tmp_dir, line_of(text, "[solid.block beam]"));
    EXPECT_READ_ERROR("dupobj.ini", text, "[solid.block  beam]", tail, 1);
    free(tail);
}

static void test_object_override(void)
{
    char *path = write_case("object_set.ini", objects_text);
    FILE *err = tmpfile();
    fsi_case *c = fsi_case_read(path, err);
    CHECK(c != NULL, "object --set case");
    if (!c) {
        fclose(err);
        free(path);
        return;
    }
    CHECK(fsi_case_override(c, "solid.block beam.max=" VEC_MAX_SET, err) == 0, "--set object");
    CHECK(fsi_case_override(c, "solid.block   base_2 .spacing = 0.5", err) == 0,
          "--set object, blanks in the section");
    CHECK(fsi_case_override(c, "solid.probe new.at=" VEC_ZERO, err) == 0, "--set new object");
    CHECK(fsi_case_override(c, "solid.block beam max=1", err) == -1,
          "no '.' before the key: 'block beam max' would be the key");
    CHECK(fsi_case_override(c, "solid.block beam.=1", err) == -1, "empty key");
    int calls = check_calls;
    int n = fsi_case_validate(c, &schema, err);
    char *msgs = read_all(err);
    CHECK(n == 0, "object --set: %d errors:\n%s", n, msgs);
    CHECK(strstr(msgs, "--set solid.block beam max=1: key 'block beam max' may not contain "
                       "blanks") != NULL, "--set split message:\n%s", msgs);
    CHECK(check_calls == calls + 1, "check hook after --set");
    double v[FSI_DIM];
    CHECK(fsi_case_get_vector(c, "solid.block beam", "max", v) == 0 && v[0] == 2.0,
          "--set wins in an object section");
    CHECK(fsi_case_get_real(c, "solid.block base_2", "spacing", -1) == 0.5,
          "--set section name with blanks");
    const char *o = fsi_case_origin(c, "solid.block beam", "max");
    CHECK(o && strcmp(o, "--set solid.block beam.max=" VEC_MAX_SET) == 0, "--set origin %s",
          o ? o : "(null)");
    const char *probes[2] = { NULL, NULL };
    CHECK(fsi_case_objects(c, "solid", "probe", probes, 2) == 2, "--set adds an object");
    CHECK(probes[1] && strcmp(probes[1], "solid.probe new") == 0, "added object comes last");
    o = fsi_case_origin(c, "solid.probe new", NULL);
    CHECK(o && strcmp(o, "--set solid.probe new.at=" VEC_ZERO) == 0, "new object origin %s",
          o ? o : "(null)");
    fsi_case_free(c);
    free(msgs);

    /* Errors in an object made by --set are reported at the --set. */
    err = tmpfile();
    c = fsi_case_read(path, err);
    CHECK(fsi_case_override(c, "solid.block extra.min=" VEC_ZERO, err) == 0, "--set new block");
    CHECK(fsi_case_override(c, "solid.blok beam.min=1", err) == 0, "--set unknown kind");
    n = fsi_case_validate(c, &schema, err);
    msgs = read_all(err);
    CHECK(n == 2, "object --set errors: %d:\n%s", n, msgs);
    CHECK(strstr(msgs, "--set solid.block extra.min=" VEC_ZERO ": [solid.block extra] max: "
                       "required key missing\n") != NULL, "missing key of a --set object:\n%s",
          msgs);
    CHECK(strstr(msgs, "--set solid.blok beam.min=1: [solid.blok beam]: unknown object kind "
                       "'blok'") != NULL, "unknown kind by --set:\n%s", msgs);
    fsi_case_free(c);
    free(msgs);
    free(path);
}

/* The check hook runs when the keys are fine, and its errors count. */
static void test_check_hook(void)
{
    static const char text[] =
        "[run]\nend_time = 1\n"
        "[solid]\nsolver = blocks\ndensity = 1000\n"
        "[solid.block ok]\nmin = " VEC_ZERO "\nmax = " VEC_MAX "\n"
        "[solid.block flat]\nmin = " VEC_ZERO "\nmax = " VEC_SMALL "\n"
        "[fluid]\nsolver = linear_dashpot\ndamping = -1\n";
    char *path = write_case("hook.ini", text);
    char *msgs;
    int n;
    int calls = check_calls;
    fsi_case *c = load(path, &msgs, &n);
    CHECK(check_calls == calls + 1, "hook runs although [fluid] has an error");
    CHECK(n == 2, "hook: %d errors (want 2):\n%s", n, msgs);
    EXPECT_AT(msgs, path, text, "max = " VEC_SMALL,
              "[solid.block flat] max: block 'flat' is empty (max <= min)\n");
    EXPECT_AT(msgs, path, text, "damping", "[fluid] damping: -1 must be >= 0\n");
    fsi_case_free(c);
    free(msgs);

    /* With a NULL stream the hook still runs and its errors still count. */
    FILE *err = tmpfile();
    c = fsi_case_read(path, err);
    n = c ? fsi_case_validate(c, &schema, NULL) : -1;
    CHECK(n == 2, "hook without an error stream: %d", n);
    CHECK(check_calls == calls + 2, "hook runs without an error stream");
    fclose(err);
    fsi_case_free(c);
    free(path);
}

/* A key defined in two tables of one solver is a flaw of the schema. */
static const fsi_key_spec dup_keys[] = {
    { "density", FSI_KEY_REAL, "kg/m^3", "1", FSI_BOUND_MIN_OPEN, 0, 0, NULL, "Again." },
    { "bad_default", FSI_KEY_INT, "-", "0", FSI_BOUND_MIN, 1, 0, NULL, "Breaks its rule." },
};
static const fsi_key_table dup_table = { "dup_own", "Clashes with materials.", dup_keys, 2 };
static const fsi_key_table *const dup_tables[] = { &material_table, &dup_table };
static const fsi_object_kind dup_objects[] = {
    { "block", "First.", &block_table, 0 },
    { "block", "Second.", &region_table, 0 },
};
static const fsi_solver_spec dup_solvers[] = {
    { .name = "clash", .role = "solid", .executable = "fsi_clash", .description = "Bad.",
      .key_tables = dup_tables, .n_key_tables = 2, .objects = dup_objects, .n_objects = 2 },
};
static const fsi_case_schema dup_schema = { sections, 2, &participant, roles, 2, dup_solvers, 1 };

/* One place per key across [ROLE] and [ROLE.SOLVER]; the derived key in no table; a
 * solver named like an object kind of its role. */
static const fsi_key_spec own_dup_keys[] = {
    { "density", FSI_KEY_REAL, "kg/m^3", "1", FSI_BOUND_MIN_OPEN, 0, 0, NULL, "Again." },
    { "support", FSI_KEY_REAL, "m", "1", FSI_BOUND_MIN_OPEN, 0, 0, NULL, "Derived." },
};
static const fsi_key_table own_dup_table = { "own_dup", "Clashes.", own_dup_keys, 2 };
static const fsi_key_table *const own_dup_tables[] = { &material_table };
static const fsi_solver_spec own_dup_solvers[] = {
    { .name = "clash2", .role = "solid", .executable = "x", .description = "Bad.",
      .key_tables = own_dup_tables, .n_key_tables = 1, .own_keys = &own_dup_table },
    { .name = "region", .role = "solid", .executable = "x", .description = "Bad.",
      .objects = block_objects, .n_objects = 3 },
};
static const fsi_case_schema own_dup_schema = { sections, 2, &participant, roles, 2,
                                                own_dup_solvers, 2 };

static void test_schema_check(void)
{
    FILE *own_err = tmpfile();
    int own_n = fsi_case_schema_check(&own_dup_schema, own_err);
    char *own_msgs = read_all(own_err);
    CHECK(own_n == 3, "own-key schema flaws: %d:\n%s", own_n, own_msgs);
    CHECK(strstr(own_msgs, "solver clash2: key 'density' is defined in table 'materials' and "
                           "again in table 'own_dup'\n") != NULL,
          "a key in [solid] and [solid.clash2]:\n%s", own_msgs);
    CHECK(strstr(own_msgs, "solver clash2: table 'own_dup' defines 'support', which validation "
                           "derives\n") != NULL, "derived key in a table:\n%s", own_msgs);
    CHECK(strstr(own_msgs, "solver region: solver region of role solid has an object kind of "
                           "this name\n") != NULL, "solver named like a kind:\n%s", own_msgs);
    free(own_msgs);

    FILE *err = tmpfile();
    CHECK(fsi_case_schema_check(&schema, err) == 0, "test schema is sound");
    int n = fsi_case_schema_check(&dup_schema, err);
    char *msgs = read_all(err);
    CHECK(n == 3, "flawed schema: %d flaws:\n%s", n, msgs);
    CHECK(strstr(msgs, "internal error in the case schema: solver clash: key 'density' is "
                       "defined in table 'materials' and again in table 'dup_own'\n") != NULL,
          "duplicate key message:\n%s", msgs);
    CHECK(strstr(msgs, "solver clash: default of key 'bad_default' in table 'dup_own': 0 must "
                       "be >= 1\n") != NULL, "bad default message:\n%s", msgs);
    CHECK(strstr(msgs, "solver clash, [solid.block NAME]: object kind declared twice\n") != NULL,
          "duplicate kind message:\n%s", msgs);
    free(msgs);

    /* validate reports them too, so that a schema bug cannot pass unnoticed. */
    static const char text[] = "[run]\nend_time = 1\n[solid]\nsolver = clash\ndensity = 1\n";
    char *path = write_case("clash.ini", text);
    err = tmpfile();
    fsi_case *c = fsi_case_read(path, err);
    n = c ? fsi_case_validate(c, &dup_schema, err) : -1;
    msgs = read_all(err);
    CHECK(n == 3, "validate with a flawed schema: %d:\n%s", n, msgs);
    CHECK(strstr(msgs, "internal error in the case schema: solver clash: key 'density'") != NULL,
          "validate reports the duplicate key:\n%s", msgs);
    fsi_case_free(c);
    free(msgs);
    free(path);

    /* The project's own schema (launch/solver_registry.c). */
    err = tmpfile();
    n = fsi_case_schema_check(fsi_project_schema(), err);
    msgs = read_all(err);
    CHECK(n == 0, "the project schema has %d flaws:\n%s", n, msgs);
    free(msgs);
}

static const char *const object_roundtrip_keys[][2] = {
    { "solid", "solver" },          { "solid", "density" },
    { "solid", "youngs_modulus" },  { "solid.block beam", "min" },
    { "solid.block beam", "max" },  { "solid.block beam", "spacing" },
    { "solid.block base_2", "spacing" }, { "solid.region clamp", "fixed" },
    { "solid.region clamp", "select" },  { "solid.probe tip-1", "at" },
    { "solid.probe new", "at" },    { "fluid.wall tank", "anything" },
};

static void test_round_trip_objects(void)
{
    char *path = write_case("round_objects.ini", objects_text);
    FILE *err = tmpfile();
    fsi_case *c = fsi_case_read(path, err);
    CHECK(c != NULL, "object round trip case");
    if (!c) {
        fclose(err);
        free(path);
        return;
    }
    CHECK(fsi_case_override(c, "solid.block beam.max=" VEC_MAX_SET, err) == 0, "--set max");
    CHECK(fsi_case_override(c, "solid.probe new.at=" VEC_ZERO, err) == 0, "--set new probe");
    int n = fsi_case_validate(c, &schema, err);
    char *msgs = read_all(err);
    CHECK(n == 0, "object round trip validate: %s", msgs);
    free(msgs);

    char *out_path = format("%s/resolved_objects.ini", tmp_dir);
    FILE *out = fopen(out_path, "w");
    fsi_case_write_resolved(c, out);
    fclose(out);
    out = fopen(out_path, "r");
    char *resolved = read_all(out);
    CHECK(strstr(resolved, "\n[solid.block base_2] ") != NULL, "object header written:\n%s",
          resolved);
    char *origin = format("; # %s:%d\n", path, line_of(objects_text, "[solid.block   base_2]"));
    CHECK(strstr(resolved, origin) != NULL, "header origin %s in:\n%s", origin, resolved);
    free(origin);
    CHECK(strstr(resolved, "; # --set solid.probe new.at=" VEC_ZERO) != NULL,
          "origin of a --set object:\n%s", resolved);

    err = tmpfile();
    fsi_case *back = fsi_case_read(out_path, err);
    n = back ? fsi_case_validate(back, &schema, err) : -1;
    msgs = read_all(err);
    CHECK(back && n == 0, "resolved objects do not validate (%d):\n%s\n--- file:\n%s", n, msgs,
          resolved);
    for (size_t i = 0; back && i < sizeof object_roundtrip_keys / sizeof object_roundtrip_keys[0];
         i++) {
        const char *sec = object_roundtrip_keys[i][0], *key = object_roundtrip_keys[i][1];
        const char *a = fsi_case_get(c, sec, key), *b = fsi_case_get(back, sec, key);
        CHECK(a && b && strcmp(a, b) == 0, "round trip [%s] %s: '%s' vs '%s'", sec, key,
              a ? a : "(null)", b ? b : "(null)");
    }
    const char *want[4], *got[4];
    int n_want = fsi_case_objects(c, "solid", "probe", want, 4);
    int n_got = back ? fsi_case_objects(back, "solid", "probe", got, 4) : -1;
    CHECK(n_want == 2 && n_got == 2 && strcmp(want[1], got[1]) == 0,
          "objects read back in the same order");
    fsi_case_free(back);
    fsi_case_free(c);
    free(msgs);
    free(resolved);
    free(out_path);
    free(path);
}

static void test_markdown_objects(void)
{
    FILE *f = tmpfile();
    fsi_case_schema_markdown(&schema, f);
    char *md = read_all(f);
    static const char *const wanted[] = {
        "### solver = blocks (solid)",
        "#### Keys in [solid]: solid_common\n\nKeys of every solid.\n\n| key |",
        "#### Keys in [solid]: materials\n\nMaterial keys.\n\n| key |",
        "#### [solid.blocks]: the keys of solver blocks\n\nKeys of the block solid.\n\n| key |",
        "#### [fluid.waves]: the keys of solver waves\n",
        "Derived: `[fluid] support` (m)",
        "#### [solid.block NAME] sections (at least one)\n\nParticles filling a box.\n\n| key |",
        "#### [solid.region NAME] sections (any number)\n\nParticles selected by a box.\n",
        "| `select` | choice | - | `inside` | inside, outside |",
        "| `density` | real | kg/m^3 | required | > 0 |",
        "`--set \"solid.block beam.max=1,0.2\"`",
    };
    for (size_t i = 0; i < sizeof wanted / sizeof wanted[0]; i++)
        CHECK(strstr(md, wanted[i]) != NULL, "markdown lacks '%s'", wanted[i]);
    CHECK(strstr(md, "#### [solid.block NAME]") > strstr(md, "#### [solid.blocks]"),
          "object kinds come after the solver's key tables");
    CHECK(count_occurrences(md, "Derived: `[fluid] support`") == 1,
          "only the solver with a support radius derives one");
    free(md);
}

/* ---------------------------------------------------------- solver sections */

/* A case with settings for two fluid schemes: each solver section is checked against
 * its own scheme's keys, chosen or not, and gets its defaults; the chosen one's is
 * created when absent; an own key in [fluid] names its section; an unknown
 * [fluid.xyz] names the known ones. */
static void test_solver_sections(void)
{
    static const char text[] =
        "[run]\nend_time = 1\n"
        "[fluid]\nsolver = waves\nspacing = 0.02\n"
        "[fluid.waves]\nalpha = 0.1\n"
        "[fluid.puffs]\ndelta = 0.2\n";
    char *path = write_case("sections_ok.ini", text);
    char *msgs;
    int n;
    fsi_case *c = load(path, &msgs, &n);
    CHECK(c && n == 0, "two scheme sections: %d errors:\n%s", n, msgs);
    if (c) {
        const char *own = fsi_case_solver_section(c, "fluid");
        CHECK(own && strcmp(own, "fluid.waves") == 0, "solver section %s", own ? own : "(null)");
        CHECK(fsi_case_get_real(c, "fluid.waves", "alpha", -1) == 0.1, "given own key");
        CHECK(fsi_case_get_real(c, "fluid.waves", "smoothing", -1) == 1.5,
              "default in the chosen section");
        CHECK(fsi_case_get_real(c, "fluid.puffs", "smoothing", -1) == 2.0,
              "default in a section not chosen");
        CHECK(fsi_case_get_real(c, "fluid.puffs", "delta", -1) == 0.2, "unchosen given key");
        CHECK(fsi_case_solver_section(c, "solid") == NULL, "no [solid]: no solver section");
    }
    fsi_case_free(c);
    free(msgs);
    free(path);

    /* The chosen solver's section is created with its defaults, right after [solid],
     * and a solver without own keys has no section. */
    static const char text2[] =
        "[run]\nend_time = 1\n"
        "[solid]\nsolver = blocks\ndensity = 1\n"
        "[solid.block b]\nmin = " VEC_ZERO "\nmax = " VEC_MAX "\n"
        "[fluid]\nsolver = linear_dashpot\n";
    path = write_case("sections_absent.ini", text2);
    c = load(path, &msgs, &n);
    CHECK(c && n == 0, "absent solver section: %d errors:\n%s", n, msgs);
    if (c) {
        CHECK(fsi_case_get_real(c, "solid.blocks", "horizon", -1) == 3.0,
              "absent chosen section created with its defaults");
        const char *o = fsi_case_origin(c, "solid.blocks", NULL);
        CHECK(o && strcmp(o, "default") == 0, "created section's origin %s", o ? o : "(null)");
        CHECK(!fsi_case_has_section(c, "fluid.linear_dashpot"), "no section without own keys");
        CHECK(!fsi_case_has_section(c, "fluid.waves"), "sections of unchosen solvers not made");
        FILE *f = tmpfile();
        fsi_case_write_resolved(c, f);
        char *resolved = read_all(f);
        const char *solid = strstr(resolved, "\n[solid] ");
        const char *blocks = strstr(resolved, "\n[solid.blocks] ");
        const char *beam = strstr(resolved, "\n[solid.block b] ");
        CHECK(solid && blocks && beam && solid < blocks && blocks < beam,
              "[solid.blocks] written right after [solid]:\n%s", resolved);
        free(resolved);
    }
    fsi_case_free(c);
    free(msgs);
    free(path);

    static const char bad[] =
        "[run]\nend_time = 1\n"
        "[fluid]\nsolver = waves\nspacing = 0.02\nalpha = 0.1\ndelta = 0.3\n"
        "[fluid.waves]\nalpa = 0.1\nspacing = 0.01\n"
        "[fluid.puffs]\ndelat = 0.2\nsmoothing = -1\n"
        "[fluid.xyz]\n"
        "[fluid.puffs p]\n"
        "[solid]\nsolver = spring_oscillators\nstiffness = 1\n"
        "[solid.linear_dashpot]\n";
    path = write_case("sections_bad.ini", bad);
    c = load(path, &msgs, &n);
    CHECK(n == 9, "bad solver sections: %d errors (want 9):\n%s", n, msgs);
    EXPECT_AT(msgs, path, bad, "alpha = 0.1\ndelta",
              "[fluid] alpha: a key of solver waves; write it in [fluid.waves]\n");
    EXPECT_AT(msgs, path, bad, "delta = 0.3",
              "[fluid] delta: a key of solver puffs; write it in [fluid.puffs]\n");
    EXPECT_AT(msgs, path, bad, "alpa",
              "[fluid.waves] alpa: unknown key 'alpa' (did you mean 'alpha'?)\n");
    EXPECT_AT(msgs, path, bad, "spacing = 0.01",
              "[fluid.waves] spacing: a key of [fluid], not of its solver section; write it "
              "there\n");
    EXPECT_AT(msgs, path, bad, "delat",
              "[fluid.puffs] delat: unknown key 'delat' (did you mean 'delta'?)\n");
    EXPECT_AT(msgs, path, bad, "smoothing = -1", "[fluid.puffs] smoothing: -1 must be > 0\n");
    EXPECT_AT(msgs, path, bad, "[fluid.xyz]",
              "[fluid.xyz]: unknown section: 'xyz' is no fluid solver (solver sections: "
              "[fluid.linear_dashpot], [fluid.waves], [fluid.puffs]), and solver waves takes "
              "no object sections\n");
    EXPECT_AT(msgs, path, bad, "[fluid.puffs p]",
              "[fluid.puffs p]: a solver section has no name: write [fluid.puffs]\n");
    EXPECT_AT(msgs, path, bad, "[solid.linear_dashpot]",
              "[solid.linear_dashpot]: unknown section: 'linear_dashpot' is no solid solver "
              "(solver sections: [solid.spring_oscillators], [solid.blocks]), and solver "
              "spring_oscillators takes no object sections\n");
    CHECK(strstr(msgs, "[fluid.waves] smoothing") == NULL, "defaults are not errors:\n%s", msgs);
    fsi_case_free(c);
    free(msgs);
    free(path);

    /* With the blocks solid the list names its object kinds too, with a guess; a
     * solver section of a solver without own keys says where its keys go. */
    static const char bad2[] =
        "[run]\nend_time = 1\n"
        "[solid]\nsolver = blocks\ndensity = 1\n"
        "[solid.block b]\nmin = " VEC_ZERO "\nmax = " VEC_MAX "\n"
        "[solid.blcks]\n"
        "[solid.spring_oscillators]\nstiffness = 1\n";
    path = write_case("sections_bad2.ini", bad2);
    c = load(path, &msgs, &n);
    CHECK(n == 2, "bad solid sections: %d errors (want 2):\n%s", n, msgs);
    EXPECT_AT(msgs, path, bad2, "[solid.blcks]",
              "[solid.blcks]: unknown section: 'blcks' (did you mean 'blocks'?) is neither a "
              "solid solver (solver sections: [solid.spring_oscillators], [solid.blocks]) nor "
              "an object kind of solver blocks (object sections: [solid.block NAME], "
              "[solid.region NAME], [solid.probe NAME])\n");
    EXPECT_AT(msgs, path, bad2, "[solid.spring_oscillators]",
              "[solid.spring_oscillators]: solver spring_oscillators has no solver section: its "
              "keys are written in [solid]\n");
    fsi_case_free(c);
    free(msgs);
    free(path);

    /* --set reaches a solver section: the key is after the last '.'. */
    static const char text3[] = "[run]\nend_time = 1\n[fluid]\nsolver = waves\n";
    path = write_case("sections_set.ini", text3);
    FILE *err = tmpfile();
    c = fsi_case_read(path, err);
    CHECK(c && fsi_case_override(c, "fluid.waves.alpha=0.3", err) == 0 &&
              fsi_case_override(c, "fluid.puffs.delta=-1", err) == 0 &&
              fsi_case_override(c, "fluid.alpha=0.2", err) == 0, "--set into solver sections");
    n = c ? fsi_case_validate(c, &schema, err) : -1;
    msgs = read_all(err);
    CHECK(n == 2, "--set solver sections: %d errors (want 2):\n%s", n, msgs);
    CHECK(strstr(msgs, "--set fluid.puffs.delta=-1: [fluid.puffs] delta: -1 must be >= 0\n"),
          "--set into an unchosen section is checked:\n%s", msgs);
    CHECK(strstr(msgs, "--set fluid.alpha=0.2: [fluid] alpha: a key of solver waves; write it "
                       "in [fluid.waves]\n"), "--set of an own key into [fluid]:\n%s", msgs);
    CHECK(c && fsi_case_get_real(c, "fluid.waves", "alpha", -1) == 0.3,
          "--set fluid.waves.alpha");
    fsi_case_free(c);
    free(msgs);
    free(path);
}

/* The support radius: derived into [fluid] support before the solvers' checks, written
 * to the resolved case as derived and derived anew when that is read back (after a
 * --set of the key it comes from), refused when the user writes it, absent for a
 * solver without one. */
static void test_derived_support(void)
{
    static const char text[] =
        "[run]\nend_time = 1\n[fluid]\nsolver = waves\nspacing = 0.02\n"
        "[fluid.waves]\nsmoothing = 1.2\n";
    char *path = write_case("support.ini", text);
    char *msgs;
    int n;
    fsi_case *c = load(path, &msgs, &n);
    CHECK(c && n == 0, "support case: %d errors:\n%s", n, msgs);
    free(msgs);
    if (!c) {
        free(path);
        return;
    }
    const double want = 2.0 * 1.2 * 0.02;
    CHECK(fsi_case_get_real(c, "fluid", "support", -1) == want, "support %s, want %.17g",
          fsi_case_get(c, "fluid", "support"), want);
    const char *o = fsi_case_origin(c, "fluid", "support");
    CHECK(o && strcmp(o, "derived") == 0, "support origin %s", o ? o : "(null)");
    char *out_path = format("%s/support_resolved.ini", tmp_dir);
    FILE *out = fopen(out_path, "w");
    fsi_case_write_resolved(c, out);
    fclose(out);
    out = fopen(out_path, "r");
    char *resolved = read_all(out);
    CHECK(strstr(resolved, "\nsupport = 0.048 ") && strstr(resolved, "; # derived\n"),
          "derived support in the resolved case:\n%s", resolved);
    fsi_case_free(c);

    /* Read back and validated again (fsi replay does): no error, derived anew. */
    FILE *err = tmpfile();
    c = fsi_case_read(out_path, err);
    CHECK(c && fsi_case_override(c, "fluid.waves.smoothing=2", err) == 0, "read back");
    n = c ? fsi_case_validate(c, &schema, err) : -1;
    msgs = read_all(err);
    CHECK(n == 0, "resolved case with a derived support: %d errors:\n%s", n, msgs);
    CHECK(c && fsi_case_get_real(c, "fluid", "support", -1) == 2.0 * 2.0 * 0.02,
          "support derived anew after --set: %s", c ? fsi_case_get(c, "fluid", "support") : "");
    free(msgs);
    /* Another solver without a support: the derived value read back goes. */
    CHECK(c && fsi_case_override(c, "fluid.solver=puffs", stderr) == 0, "--set solver");
    err = tmpfile();
    n = c ? fsi_case_validate(c, &schema, err) : -1;
    msgs = read_all(err);
    CHECK(n == 0, "swapped to puffs: %d errors:\n%s", n, msgs);
    CHECK(c && fsi_case_get(c, "fluid", "support") == NULL, "stale support kept: %s",
          c ? fsi_case_get(c, "fluid", "support") : "");
    fsi_case_free(c);
    free(msgs);
    free(resolved);
    free(out_path);
    free(path);

    /* Written by the user, in the file or with --set: refused, for any solver. */
    static const char bad[] =
        "[run]\nend_time = 1\n[fluid]\nsolver = waves\nsupport = 0.05\n"
        "[solid]\nsolver = external\nexecutable = /bin/true\nsupport = 1\n";
    path = write_case("support_bad.ini", bad);
    c = load(path, &msgs, &n);
    CHECK(n == 2, "user-written support: %d errors (want 2):\n%s", n, msgs);
    EXPECT_AT(msgs, path, bad, "support = 0.05",
              "[fluid] support: a derived value, not a setting: validation writes the fluid "
              "solver's support radius (from its own keys and spacing) into the resolved "
              "case; remove it\n");
    EXPECT_AT(msgs, path, bad, "support = 1", "[solid] support: a derived value, not a setting");
    CHECK(c && strcmp(fsi_case_get(c, "fluid", "support"), "0.05") == 0,
          "a refused value is not replaced");
    fsi_case_free(c);
    free(msgs);
    free(path);
    static const char typo[] = "[run]\nend_time = 1\n[fluid]\nsolver = puffs\nsuport = 1\n";
    path = write_case("support_typo.ini", typo);
    c = load(path, &msgs, &n);
    CHECK(n == 1 && !strstr(msgs, "did you mean 'support'"),
          "the derived key is never suggested:\n%s", msgs);
    fsi_case_free(c);
    free(msgs);
    free(path);
}

int main(void)
{
    /* $FSI_TEST_TMP is shared by all unit tests: use a folder of our own in it. */
    const char *base = getenv("FSI_TEST_TMP");
    if (base && *base)
        snprintf(tmp_dir, sizeof tmp_dir, "%s/case_file", base);
    else
        snprintf(tmp_dir, sizeof tmp_dir, "/tmp/fsi_test_case");
    make_dirs(tmp_dir);

    test_valid();
    test_crlf_bom();
    test_typo();
    test_missing_required();
    test_bad_values();
    test_solvers();
    test_syntax();
    test_override();
    test_round_trip();
    test_markdown();
    test_objects();
    test_object_errors();
    test_duplicate_object();
    test_object_override();
    test_check_hook();
    test_schema_check();
    test_round_trip_objects();
    test_markdown_objects();
    test_solver_sections();
    test_derived_support();

    if (failures) {
        fprintf(stderr, "test_case_file: %d of %d checks failed\n", failures, checks);
        return 1;
    }
    printf("test_case_file: all %d checks passed\n", checks);
    return 0;
}
