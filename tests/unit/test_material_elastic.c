/* Unit test of the linear elastic model (solid_solver/materials): Hooke's stresses
 * for uniaxial-strain, pure-shear and mixed increments (000 Eq. 43), plane stress
 * (sigma_zz = 0, sigma_xx = E/(1-nu^2)(eps_xx + nu eps_yy)), the compliance, the
 * wave modulus, and reading materials from case files (keys, degrees to radians,
 * the cross-key errors of material_case_check / material_from_case).
 *
 * Expected values come from E and nu directly (not from the lambda/mu the model
 * derives), so a wrong derivation or a wrong D fails. Tolerance: relative 1e-12;
 * each stress is a handful of floating-point operations on numbers of one scale,
 * so round-off is a few 1e-16 and 1e-12 leaves room for a different but
 * equivalent operation order while any modelling error (a missing factor 2 on the
 * shear terms, nu for nu/(1-nu), ...) is of order 1e-1.
 * Exit 0 = pass; every failed check is printed. Scratch files go to
 * $FSI_TEST_TMP/material_elastic (default /tmp/fsi_test_material_elastic). */
#include "case_file.h"
#include "dim.h"
#include "material.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "unit_check.h"
#include "unit_material.h"

#define REL_TOL 1e-12

/* |a - b| <= tol * scale, scale the size of the quantities compared (so that a
 * component that should be 0 is judged against the stress level, not against 0). */
static int close_to(double a, double b, double scale)
{
    return fabs(a - b) <= REL_TOL * scale;
}

static material make_elastic(double E, double nu, material_plane plane)
{
    return unit_material(MATERIAL_LINEAR_ELASTIC, plane, E, nu);
}

static void check_stress(const double got[6], const double want[6], const char *what)
{
    double scale = 0.0;
    for (int i = 0; i < 6; i++)
        scale = fmax(scale, fabs(want[i]));
    for (int i = 0; i < 6; i++)
        CHECK(close_to(got[i], want[i], scale), "%s: stress[%d] = %.17g, expected %.17g", what,
              i, got[i], want[i]);
}

/* ---------------------------------------------------------- Hooke's law */

static void test_uniaxial_strain(void)
{
    const double E = 2.1e11, nu = 0.3, e = 1e-4;
    material m = make_elastic(E, nu, MATERIAL_PLANE_STRAIN);
    double c = E / ((1 + nu) * (1 - 2 * nu));
    double deps[6] = {e, 0, 0, 0, 0, 0};
    double s[6] = {0};
    material_state st = {{0}, 0, 7};
    material_update(&m, deps, s, &st);
    double want[6] = {c * (1 - nu) * e, c * nu * e, c * nu * e, 0, 0, 0};
    check_stress(s, want, "uniaxial strain");
    CHECK(deps[2] == 0.0, "plane strain / 3D must not touch deps_zz (got %g)", deps[2]);
    CHECK(st.yielding == 0, "elastic update clears 'yielding'");
    CHECK(st.equivalent_plastic_strain == 0.0, "elastic update has no plastic strain");

    /* The same along y and z (z only in 3D builds or as a given increment). */
    double deps_y[6] = {0, e, 0, 0, 0, 0}, sy[6] = {0};
    material_update(&m, deps_y, sy, NULL);
    double want_y[6] = {c * nu * e, c * (1 - nu) * e, c * nu * e, 0, 0, 0};
    check_stress(sy, want_y, "uniaxial strain along y");
}

static void test_pure_shear(void)
{
    const double E = 7e10, nu = 0.33, g = 2.5e-4;   /* tensor component eps_xy */
    material m = make_elastic(E, nu, MATERIAL_PLANE_STRAIN);
    double s[6] = {0};
    double deps[6] = {0, 0, 0, g, 0, 0};
    material_update(&m, deps, s, NULL);
    /* sigma_xy = 2 G eps_xy = E / (1 + nu) eps_xy (tensor shear: gamma = 2 eps). */
    double want[6] = {0, 0, 0, E / (1 + nu) * g, 0, 0};
    check_stress(s, want, "pure shear xy");
    CHECK(s[0] == 0.0 && s[1] == 0.0 && s[2] == 0.0, "pure shear: no normal stress at all");

    /* Pure shear written as principal strains (e, -e, 0): the same shear modulus. */
    double s2[6] = {0};
    double deps2[6] = {g, -g, 0, 0, 0, 0};
    material_update(&m, deps2, s2, NULL);
    double want2[6] = {E / (1 + nu) * g, -E / (1 + nu) * g, 0, 0, 0, 0};
    check_stress(s2, want2, "pure shear (e, -e, 0)");

    /* yz and zx shear (3D components; 2D callers pass 0 there). */
    double s3[6] = {0};
    double deps3[6] = {0, 0, 0, 0, g, -2 * g};
    material_update(&m, deps3, s3, NULL);
    double want3[6] = {0, 0, 0, 0, E / (1 + nu) * g, -2 * E / (1 + nu) * g};
    check_stress(s3, want3, "shear yz, zx");
}

/* Increments add: sigma after n steps is D : sum(deps), from a non-zero start. */
static void test_increments_add(void)
{
    const double E = 1e6, nu = 0.45;
    material m = make_elastic(E, nu, MATERIAL_PLANE_STRAIN);
    double s0[6] = {-3e3, 1e3, -5e2, 2e2, 0, 0};
    double s[6];
    memcpy(s, s0, sizeof s);
    double total[6] = {0};
    for (int n = 0; n < 10; n++) {
        double deps[6] = {1e-5 * (n - 3), -2e-5, 0, 3e-6 * n, 0, 0};
        for (int i = 0; i < 6; i++)
            total[i] += deps[i];
        material_update(&m, deps, s, NULL);
    }
    double c = E / ((1 + nu) * (1 - 2 * nu));
    double tr = total[0] + total[1] + total[2];
    double want[6];
    for (int i = 0; i < 3; i++)
        want[i] = s0[i] + c * nu * tr + E / (1 + nu) * total[i];
    for (int i = 3; i < 6; i++)
        want[i] = s0[i] + E / (1 + nu) * total[i];
    check_stress(s, want, "ten increments");
}

/* Uniaxial STRESS through the compliance: eps_xx = sigma / E, eps_yy = -nu sigma / E;
 * and D^-1 (D deps) = deps. */
static void test_compliance(void)
{
    const double E = 3e7, nu = 0.25, sig = 4e4;
    material m = make_elastic(E, nu, MATERIAL_PLANE_STRAIN);
    double ds[6] = {sig, 0, 0, 0, 0, 0}, de[6];
    material_compliance(&m, ds, de);
    double want[6] = {sig / E, -nu * sig / E, -nu * sig / E, 0, 0, 0};
    for (int i = 0; i < 6; i++)
        CHECK(close_to(de[i], want[i], sig / E), "uniaxial stress: eps[%d] = %.17g, expected "
              "%.17g", i, de[i], want[i]);

    double deps[6] = {1e-4, -3e-5, 2e-5, 4e-5, -1e-5, 7e-6}, s[6], back[6];
    material_hooke(&m, deps, s);
    material_compliance(&m, s, back);
    for (int i = 0; i < 6; i++)
        CHECK(close_to(back[i], deps[i], 1e-4), "D^-1 D deps: [%d] %.17g vs %.17g", i, back[i],
              deps[i]);
}

/* ---------------------------------------------------------- plane stress */

static void test_plane_stress(void)
{
#if FSI_DIM == 2
    const double E = 1.4e6, nu = 0.4;
    material m = make_elastic(E, nu, MATERIAL_PLANE_STRESS);
    double s[6] = {0};
    double exx_total = 0, eyy_total = 0, exy_total = 0, ezz_total = 0;
    for (int n = 0; n < 5; n++) {
        double deps[6] = {2e-4, -0.5e-4 * n, 12345.0 /* output, overwritten */, 1e-4, 0, 0};
        material_update(&m, deps, s, NULL);
        exx_total += deps[0];
        eyy_total += deps[1];
        exy_total += deps[3];
        ezz_total += deps[2];
        /* The thickness strain that keeps sigma_zz = 0: -nu/(1-nu)(deps_xx + deps_yy). */
        double want_ezz = -nu / (1 - nu) * (deps[0] + deps[1]);
        CHECK(close_to(deps[2], want_ezz, 2e-4), "plane stress step %d: deps_zz = %.17g, "
              "expected %.17g", n, deps[2], want_ezz);
        CHECK(s[2] == 0.0, "plane stress step %d: sigma_zz = %g, must be 0", n, s[2]);
    }
    double f = E / (1 - nu * nu);
    double want[6] = {f * (exx_total + nu * eyy_total), f * (eyy_total + nu * exx_total), 0,
                      E / (1 + nu) * exy_total, 0, 0};
    check_stress(s, want, "plane stress");
    CHECK(close_to(ezz_total, -nu / (1 - nu) * (exx_total + eyy_total), 1e-3),
          "plane stress: total eps_zz");

    /* A sigma_zz left by round-off is removed, not carried. */
    double s2[6] = {1e3, 0, 1e-9, 0, 0, 0};
    double deps2[6] = {0, 0, 0, 0, 0, 0};
    material_update(&m, deps2, s2, NULL);
    CHECK(s2[2] == 0.0 && close_to(deps2[2], -1e-9 / (E * (1 - nu) / ((1 + nu) * (1 - 2 * nu))),
                                   1e-15),
          "plane stress: residual sigma_zz removed (deps_zz = %g)", deps2[2]);
#else
    /* 3D builds ignore 'plane': the same increment gives the full 3D answer. */
    material m = make_elastic(1e6, 0.3, MATERIAL_PLANE_STRESS);
    double s[6] = {0}, deps[6] = {1e-4, 0, 0, 0, 0, 0};
    material_update(&m, deps, s, NULL);
    CHECK(deps[2] == 0.0 && s[2] != 0.0, "3D: plane is ignored");
#endif
}

static void test_wave_modulus(void)
{
    const double E = 1.4e6, nu = 0.4;
    material strain = make_elastic(E, nu, MATERIAL_PLANE_STRAIN);
    double M = E * (1 - nu) / ((1 + nu) * (1 - 2 * nu));
    CHECK(close_to(material_wave_modulus(&strain), M, M), "plane strain / 3D: lambda + 2 mu");
    material stress = make_elastic(E, nu, MATERIAL_PLANE_STRESS);
#if FSI_DIM == 2
    CHECK(close_to(material_wave_modulus(&stress), E / (1 - nu * nu), M),
          "plane stress: E / (1 - nu^2), got %g", material_wave_modulus(&stress));
#else
    CHECK(close_to(material_wave_modulus(&stress), M, M), "3D ignores plane stress");
#endif
    CHECK(close_to(strain.bulk_modulus, E / (3 * (1 - 2 * nu)), E), "bulk modulus");
    CHECK(close_to(strain.shear_modulus, E / (2 * (1 + nu)), E), "shear modulus");
}

/* ---------------------------------------------------------- case files */

static char tmp_dir[1024];

static void make_dirs(const char *path)
{
    char buf[1024];
    snprintf(buf, sizeof buf, "%s", path);
    for (char *p = buf + 1; *p; p++) {
        if (*p == '/') {
            *p = '\0';
            if (mkdir(buf, 0777) != 0 && errno != EEXIST)
                perror(buf);
            *p = '/';
        }
    }
    if (mkdir(buf, 0777) != 0 && errno != EEXIST)
        perror(buf);
}

static int material_hook(const fsi_case *c, const char *role, FILE *errors)
{
    return material_case_check(c, role, errors);
}

static const fsi_key_spec participant_keys[] = {
    {"solver", FSI_KEY_STRING, "-", NULL, 0, 0, 0, NULL, "Solver."},
};
static const fsi_key_table participant = {"participant", "Participant keys.", participant_keys,
                                          1};
static const char *const roles[] = {"solid"};
static const fsi_key_table *const tables[] = {&material_key_table};
static const fsi_solver_spec solvers[] = {
    {.name = "mat", .role = "solid", .executable = "none", .description = "Material keys only.",
     .key_tables = tables, .n_key_tables = 1, .check = material_hook},
};
static const fsi_case_schema schema = {NULL, 0, &participant, roles, 1, solvers, 1};

/* Writes a case with [solid] solver = mat and the given key lines, reads and
 * validates it; returns the case (validation errors in *errors_text). */
static fsi_case *load(const char *name, const char *lines, int *n_errors, char *errors_text,
                      size_t errors_size)
{
    char path[1200];
    snprintf(path, sizeof path, "%s/%s.ini", tmp_dir, name);
    FILE *f = fopen(path, "w");
    if (!f) {
        perror(path);
        exit(2);
    }
    fprintf(f, "[solid]\nsolver = mat\n%s", lines);
    fclose(f);
    char *buf = NULL;
    size_t len = 0;
    FILE *err = open_memstream(&buf, &len);
    fsi_case *c = fsi_case_read(path, err);
    *n_errors = c ? fsi_case_validate(c, &schema, err) : -1;
    fclose(err);
    snprintf(errors_text, errors_size, "%s", buf ? buf : "");
    free(buf);
    return c;
}

static void test_case_keys(void)
{
    CHECK(fsi_case_schema_check(&schema, stderr) == 0, "material key table is a valid schema");
    CHECK(material_key_table.keys == material_keys &&
              material_key_table.n_keys == material_n_keys,
          "material_key_table wraps material_keys");
    int has_plane = 0;
    for (int i = 0; i < material_n_keys; i++) {
        CHECK(material_keys[i].unit && material_keys[i].description &&
                  strlen(material_keys[i].description) > 20,
              "key %s has unit and description", material_keys[i].key);
        has_plane |= strcmp(material_keys[i].key, "plane") == 0;
    }
    CHECK(has_plane == (FSI_DIM == 2), "'plane' exists in 2D builds only");

    char errs[4096], msg[512];
    int n;
    material m;

    /* A valid linear elastic solid with defaults. */
    fsi_case *c = load("elastic", "density = 1100\nyoungs_modulus = 1.4e6\npoisson_ratio = 0.4\n",
                       &n, errs, sizeof errs);
    CHECK(c && n == 0, "valid elastic case: %d errors: %s", n, errs);
    if (c && n == 0) {
        CHECK(material_from_case(&m, c, "solid", msg, sizeof msg) == 0, "from_case: %s", msg);
        CHECK(m.kind == MATERIAL_LINEAR_ELASTIC && m.plane == MATERIAL_PLANE_STRAIN &&
                  m.density == 1100 && m.youngs_modulus == 1.4e6 && m.poisson_ratio == 0.4,
              "elastic values and defaults");
        CHECK(close_to(m.shear_modulus, 1.4e6 / 2.8, 1e6), "derived after from_case");
    }
    fsi_case_free(c);

    /* Drucker-Prager of 000 Table 4: degrees become radians, constants derived. */
    c = load("dp", "constitutive = drucker_prager\ndensity = 2500\nyoungs_modulus = 30e6\n"
                   "poisson_ratio = 0.25\ncohesion = 5e3\nfriction_angle = 13\n"
                   "dilation_angle = 0\n",
             &n, errs, sizeof errs);
    CHECK(c && n == 0, "valid Drucker-Prager case: %d errors: %s", n, errs);
    if (c && n == 0) {
        CHECK(material_from_case(&m, c, "solid", msg, sizeof msg) == 0, "from_case: %s", msg);
        double phi = 13.0 * acos(-1.0) / 180.0, t = tan(phi);
        CHECK(m.kind == MATERIAL_DRUCKER_PRAGER && close_to(m.friction_angle, phi, 1) &&
                  m.dilation_angle == 0.0 && m.cohesion == 5e3,
              "Drucker-Prager values, friction angle %.17g rad", m.friction_angle);
        CHECK(close_to(m.dp_alpha, t / sqrt(9 + 12 * t * t), 1) &&
                  close_to(m.dp_k, 3 * 5e3 / sqrt(9 + 12 * t * t), 5e3) && m.dp_beta == 0.0,
              "plane-strain match alpha %.17g k %.17g", m.dp_alpha, m.dp_k);
    }
    fsi_case_free(c);

    /* The hyperelastic kinds: read by name, plane stress allowed, constants derived. */
    static const struct {
        const char *word;
        material_kind kind;
    } hyper[] = {{"saint_venant_kirchhoff", MATERIAL_SAINT_VENANT_KIRCHHOFF},
                 {"neo_hookean", MATERIAL_NEO_HOOKEAN}};
    for (int i = 0; i < 2; i++) {
        char lines[512];
        snprintf(lines, sizeof lines,
                 "constitutive = %s\ndensity = 1100\nyoungs_modulus = 1.4e6\n"
                 "poisson_ratio = 0.4\n%s",
                 hyper[i].word, FSI_DIM == 2 ? "plane = stress\n" : "");
        c = load(hyper[i].word, lines, &n, errs, sizeof errs);
        CHECK(c && n == 0, "valid %s case: %d errors: %s", hyper[i].word, n, errs);
        if (c && n == 0) {
            CHECK(material_from_case(&m, c, "solid", msg, sizeof msg) == 0, "from_case: %s", msg);
            CHECK(m.kind == hyper[i].kind && material_is_hyperelastic(&m) &&
                      (FSI_DIM == 3 || m.plane == MATERIAL_PLANE_STRESS) &&
                      close_to(m.shear_modulus, 1.4e6 / 2.8, 1e6),
                  "%s: kind %d, plane %d, mu %g", hyper[i].word, (int)m.kind, (int)m.plane,
                  m.shear_modulus);
        }
        fsi_case_free(c);
    }

    /* Cross-key errors: each names its key, in validation and in from_case. */
    static const struct {
        const char *name, *lines, *key;
    } bad[] = {
#if FSI_DIM == 2
        {"dp_plane_stress", "constitutive = drucker_prager\ncohesion = 1e3\nfriction_angle = 30\n"
                            "plane = stress\n", "] plane: "},
#endif
        {"dp_dilation", "constitutive = drucker_prager\ncohesion = 1e3\nfriction_angle = 20\n"
                        "dilation_angle = 25\n", "] dilation_angle: "},
        {"dp_no_friction", "constitutive = drucker_prager\ncohesion = 1e3\n",
         "] friction_angle: required"},
        {"dp_no_cohesion", "constitutive = drucker_prager\nfriction_angle = 30\n",
         "] cohesion: required"},
        {"dp_no_strength", "constitutive = drucker_prager\ncohesion = 0\nfriction_angle = 0\n",
         "] cohesion: "},
        {"le_cohesion", "cohesion = 1e3\n", "] cohesion: only used"},
        {"svk_friction", "constitutive = saint_venant_kirchhoff\nfriction_angle = 20\n",
         "] friction_angle: only used with constitutive = drucker_prager (this material is "
         "saint_venant_kirchhoff)"},
        {"nh_dilation", "constitutive = neo_hookean\ndilation_angle = 5\n",
         "] dilation_angle: only used with constitutive = drucker_prager (this material is "
         "neo_hookean)"},
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        char lines[512];
        snprintf(lines, sizeof lines, "density = 2000\nyoungs_modulus = 1e7\npoisson_ratio = 0.3\n%s",
                 bad[i].lines);
        c = load(bad[i].name, lines, &n, errs, sizeof errs);
        CHECK(c && n == 1 && strstr(errs, bad[i].key) && strstr(errs, "[solid]"),
              "%s: expected one error naming '%s', got %d: %s", bad[i].name, bad[i].key, n, errs);
        if (c) {
            CHECK(material_from_case(&m, c, "solid", msg, sizeof msg) == -1 &&
                      strstr(msg, bad[i].key) && strstr(msg, ".ini:"),
                  "%s: from_case message '%s'", bad[i].name, msg);
        }
        fsi_case_free(c);
    }

    /* nu near 0.5 and out-of-range angles are caught by the keys' bounds. */
    c = load("nu_half", "density = 1\nyoungs_modulus = 1\npoisson_ratio = 0.4995\n", &n, errs,
             sizeof errs);
    CHECK(c && n == 1 && strstr(errs, "poisson_ratio"), "nu = 0.4995 rejected: %s", errs);
    fsi_case_free(c);
    c = load("phi_90", "constitutive = drucker_prager\ndensity = 1\nyoungs_modulus = 1\n"
                       "poisson_ratio = 0.2\ncohesion = 1\nfriction_angle = 90\n",
             &n, errs, sizeof errs);
    CHECK(c && n == 1 && strstr(errs, "friction_angle"), "phi = 90 rejected: %s", errs);
    fsi_case_free(c);
}

int main(void)
{
    const char *base = getenv("FSI_TEST_TMP");
    if (base && *base)
        snprintf(tmp_dir, sizeof tmp_dir, "%s/material_elastic", base);
    else
        snprintf(tmp_dir, sizeof tmp_dir, "/tmp/fsi_test_material_elastic");
    make_dirs(tmp_dir);

    test_uniaxial_strain();
    test_pure_shear();
    test_increments_add();
    test_compliance();
    test_plane_stress();
    test_wave_modulus();
    test_case_keys();

    if (failures) {
        fprintf(stderr, "test_material_elastic: %d of %d checks failed\n", failures, checks);
        return 1;
    }
    printf("test_material_elastic: all %d checks passed (relative tolerance %.0e)\n", checks,
           REL_TOL);
    return 0;
}
