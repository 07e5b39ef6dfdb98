/* Unit test of core/case_file.c: reading, --set overrides, validation against a
 * small schema built here, error messages (text and line), defaults, the resolved
 * file round trip and the Markdown reference. Exit 0 = pass; every failed check
 * is printed. Scratch files go to $FSI_TEST_TMP/case_file (default /tmp/fsi_test_case). */
#include "case_file.h"
#include "dim.h"

#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

static int failures;
static int checks;

#define CHECK(cond, ...)                                                    \
    do {                                                                    \
        checks++;                                                           \
        if (!(cond)) {                                                      \
            failures++;                                                     \
            fprintf(stderr, "FAIL %s:%d: ", __FILE__, __LINE__);            \
            fprintf(stderr, __VA_ARGS__);                                   \
            fputc('\n', stderr);                                            \
        }                                                                   \
    } while (0)

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

static const fsi_solver_spec solvers[] = {
    { "spring_oscillators", "solid", "fsi_spring_solid", "Particles on springs.", &spring_table },
    { "linear_dashpot", "fluid", "fsi_dashpot_fluid", "A linear dashpot as fluid.",
      &dashpot_table },
};

static const char *const roles[] = { "fluid", "solid" };

static const fsi_case_schema schema = {
    sections, 2, &participant, roles, 2, solvers, 2,
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
              "'spring_oscillators'?); solid solvers: spring_oscillators, external");
    EXPECT_AT(msgs, path, text, "solver = spring_oscillators",
              "[fluid] solver: 'spring_oscillators' is a solid solver, not a fluid solver "
              "(fluid solvers: linear_dashpot, external)");
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

    if (failures) {
        fprintf(stderr, "test_case_file: %d of %d checks failed\n", failures, checks);
        return 1;
    }
    printf("test_case_file: all %d checks passed\n", checks);
    return 0;
}
