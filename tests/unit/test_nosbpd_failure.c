/* NOSB-PD bond failure (000 Eqs. 47-49) and what depends on it:
 *  - under a uniform stretch exactly the bonds whose analytic stretch exceeds s0
 *    break (the lattice directions are chosen at least 1e-6 away from s0, so
 *    round-off cannot decide), both halves of each pair together; unloading heals
 *    nothing; K is recomputed over the intact bonds only;
 *  - damage stays within 0..1 and is the volume fraction of broken bonds;
 *  - a point left with collinear bonds (or born with them) produces no NaN, is
 *    flagged and counted, and carries no stress;
 *  - crack faces become surface points;
 *  - a [solid.crack] breaks exactly the bonds that cross it, with failure off too;
 *  - no bond with an end point in a no_failure region (SOLID_UNBREAKABLE) breaks,
 *    and the others break as without the region;
 *  - s0 from the fracture energy (the 2D forms of nosbpd_failure.h), and
 *    critical_stretch winning over fracture_energy; failure without either is an
 *    error. */
#include "test_nosbpd_common.h"

static const char *CASE_BASE = "[solid]\n"
                               "solver = nosbpd\n"
                               "density = 1000\n"
                               "youngs_modulus = 1e6\n"
                               "poisson_ratio = 0.25\n";

/* Stretch of lattice direction xi under x = diag(1 + e, 1, 1) X. */
static double analytic_stretch(const double *xi, double e)
{
    double a = 0.0, b = 0.0;
    for (int d = 0; d < FSI_DIM; d++) {
        const double y = (d == 0 ? 1.0 + e : 1.0) * xi[d];
        a += y * y;
        b += xi[d] * xi[d];
    }
    return sqrt(a) / sqrt(b) - 1.0;
}

static void stretch_to(solid_particles *p, double e, double *x_prev)
{
    memcpy(x_prev, p->x, (size_t)p->n * FSI_DIM * sizeof *x_prev);
    for (int i = 0; i < p->n; i++)
        for (int d = 0; d < FSI_DIM; d++)
            p->x[i * FSI_DIM + d] = (d == 0 ? 1.0 + e : 1.0) * p->x0[i * FSI_DIM + d];
}

static int all_finite(const double *a, int n)
{
    for (int k = 0; k < n; k++)
        if (!isfinite(a[k]))
            return 0;
    return 1;
}

static void check_breaking(void)
{
    const double s0 = 0.01;
    solid_particles *p = test_lattice(30, 8, 5, 0.01, 1000.0);
    char text[512];
    snprintf(text, sizeof text, "%s[solid.nosbpd]\n"
                                "failure = true\ncritical_stretch = %g\n", CASE_BASE, s0);
    solid_model *m = test_model(text, p);
    CHECK(nosbpd_critical_stretch(m) == s0, "critical stretch %g", nosbpd_critical_stretch(m));
    const nosbpd_bonds *b = nosbpd_model_bonds(m);
    double *x_prev = malloc((size_t)p->n * FSI_DIM * sizeof *x_prev);
    double *force = malloc((size_t)p->n * FSI_DIM * sizeof *force);

    /* Just below s0 along x: nothing breaks. */
    stretch_to(p, 0.0099, x_prev);
    CHECK(test_force(m, p, x_prev, force) == 0, "stretch 0.0099 failed");
    CHECK(nosbpd_broken_bond_count(m) == 0, "%ld bonds broke below s0",
          (long)nosbpd_broken_bond_count(m));

    /* e = 0.0125: the bonds near the x axis break, exactly those with s > s0. */
    const double e = 0.0125;
    stretch_to(p, e, x_prev);
    CHECK(test_force(m, p, x_prev, force) == 0, "stretch %g failed", e);
    int64_t expected = 0, wrong = 0, close = 0;
    for (int64_t q = 0; q < b->n_bonds; q++) {
        const double s = analytic_stretch(b->xi + q * FSI_DIM, e);
        close += fabs(s - s0) < 1e-6;
        const int should_break = s > s0;
        expected += should_break;
        wrong += should_break == b->intact[q];
    }
    CHECK(close == 0, "%ld bonds within 1e-6 of s0: the test would depend on round-off",
          (long)close);
    CHECK(expected > 0 && expected < b->n_bonds, "stretch %g should break some bonds", e);
    CHECK(wrong == 0, "%ld bonds in the wrong state after stretch %g", (long)wrong, e);
    CHECK(nosbpd_broken_bond_count(m) == expected, "%ld broken, %ld expected",
          (long)nosbpd_broken_bond_count(m), (long)expected);
    /* Both halves of every pair agree. */
    int64_t asym = 0;
    for (int i = 0; i < p->n; i++)
        for (int64_t q = b->offset[i]; q < b->offset[i + 1]; q++) {
            const int j = b->neighbour[q];
            for (int64_t r = b->offset[j]; r < b->offset[j + 1]; r++)
                if (b->neighbour[r] == i)
                    asym += b->intact[r] != b->intact[q];
        }
    CHECK(asym == 0, "%ld bond halves disagree with their partner", (long)asym);

    /* Damage: the volume fraction of broken bonds, within 0..1. */
    const double *damage = nosbpd_damage(m);
    int bad_damage = 0;
    for (int i = 0; i < p->n; i++) {
        double all = 0.0, lost = 0.0;
        for (int64_t q = b->offset[i]; q < b->offset[i + 1]; q++) {
            all += p->volume[b->neighbour[q]];
            lost += b->intact[q] ? 0.0 : p->volume[b->neighbour[q]];
        }
        bad_damage += !(damage[i] >= 0.0 && damage[i] <= 1.0) ||
                      fabs(damage[i] - lost / all) > 1e-14;
    }
    CHECK(bad_damage == 0, "%d points with a wrong damage", bad_damage);

    /* K^-1 of a middle point equals the inverse of the sum over its intact bonds. */
    const int i = 15 + 30 * 4 + (FSI_DIM == 3 ? 30 * 8 * 2 : 0);
    double k[FSI_MAT_SIZE], k_inv[FSI_MAT_SIZE];
    fsi_mat_zero(k);
    for (int64_t q = b->offset[i]; q < b->offset[i + 1]; q++)
        if (b->intact[q])
            fsi_mat_add_outer(k, b->weight[q], b->xi + q * FSI_DIM, b->xi + q * FSI_DIM);
    CHECK(fsi_mat_inverse(k, k_inv, 1e8) == 0, "intact K singular");
    double err = 0.0;
    for (int c = 0; c < FSI_MAT_SIZE; c++)
        err = fmax(err, fabs(k_inv[c] - nosbpd_shape_tensor_inverse(m)[i * FSI_MAT_SIZE + c]));
    CHECK(err < 1e-12 * fsi_mat_norm(k_inv), "K^-1 after failure off by %g", err);

    /* Unloading heals nothing. */
    const int64_t before = nosbpd_broken_bond_count(m);
    uint8_t *state = malloc((size_t)b->n_bonds);
    memcpy(state, b->intact, (size_t)b->n_bonds);
    stretch_to(p, 0.0, x_prev);
    CHECK(test_force(m, p, x_prev, force) == 0, "unloading failed");
    CHECK(nosbpd_broken_bond_count(m) == before && memcmp(state, b->intact, (size_t)b->n_bonds) == 0,
          "bonds changed on unloading");
    free(state);

    /* Pull hard: only bonds perpendicular to x survive, every family is a line (a
     * plane in 3D): K is singular everywhere. No NaN, every point flagged. */
    stretch_to(p, 0.5, x_prev);
    const int rc = test_force(m, p, x_prev, force);
    CHECK(rc == 0, "pulling apart failed");
    CHECK(all_finite(force, p->n * FSI_DIM), "non-finite forces after fragmentation");
    if (FSI_DIM == 2) {
        CHECK(nosbpd_points_without_force_state(m) == p->n,
              "%d of %d points flagged after fragmentation into columns",
              nosbpd_points_without_force_state(m), p->n);
        int flagged = 0, stressed = 0;
        for (int j = 0; j < p->n; j++) {
            flagged += (nosbpd_point_flags(m)[j] & NOSBPD_POINT_SINGULAR_SHAPE) != 0;
            for (int c = 0; c < 6; c++)
                stressed += nosbpd_stress(m)[j * 6 + c] != 0.0;
        }
        CHECK(flagged == p->n, "%d points with the singular-shape flag", flagged);
        CHECK(stressed == 0, "%d stress components left on points without force state",
              stressed);
    }
    for (int j = 0; j < p->n; j++)
        CHECK(damage[j] > 0.0 && damage[j] < 1.0, "damage %g of a column point", damage[j]);
    /* Keep moving the fragments: still finite. */
    memcpy(x_prev, p->x, (size_t)p->n * FSI_DIM * sizeof *x_prev);
    for (int j = 0; j < p->n * FSI_DIM; j++)
        p->x[j] += 1e-3 * (test_uniform() - 0.5);
    CHECK(test_force(m, p, x_prev, force) == 0, "moving fragments failed");
    CHECK(all_finite(force, p->n * FSI_DIM), "non-finite forces on moving fragments");

    free(x_prev);
    free(force);
    solid_model_free(m);
    test_lattice_free(p);
}

/* The stretch of check_breaking with the left third of the block unbreakable: the
 * bonds that would break and touch it stay, all others break as before. */
static void check_no_failure_region(void)
{
    const double s0 = 0.01, e = 0.0125;
    solid_particles *p = test_lattice(30, 8, 5, 0.01, 1000.0);
    int unbreakable = 0;
    for (int i = 0; i < p->n; i++)
        if (p->x0[i * FSI_DIM] < 0.095) {
            p->flags[i] |= SOLID_UNBREAKABLE;
            unbreakable++;
        }
    char text[512];
    snprintf(text, sizeof text, "%s[solid.nosbpd]\n"
                                "failure = true\ncritical_stretch = %g\n", CASE_BASE, s0);
    solid_model *m = test_model(text, p);
    const nosbpd_bonds *b = nosbpd_model_bonds(m);
    double *x_prev = malloc((size_t)p->n * FSI_DIM * sizeof *x_prev);
    double *force = malloc((size_t)p->n * FSI_DIM * sizeof *force);
    stretch_to(p, e, x_prev);
    CHECK(test_force(m, p, x_prev, force) == 0, "stretch %g failed", e);
    int64_t kept = 0, broken = 0, wrong = 0;
    for (int i = 0; i < p->n; i++)
        for (int64_t q = b->offset[i]; q < b->offset[i + 1]; q++) {
            const int j = b->neighbour[q];
            const int protected = ((p->flags[i] | p->flags[j]) & SOLID_UNBREAKABLE) != 0;
            const int over = analytic_stretch(b->xi + q * FSI_DIM, e) > s0;
            kept += over && protected;
            broken += over && !protected;
            wrong += (over && !protected) == b->intact[q];
        }
    CHECK(unbreakable > 0 && unbreakable < p->n, "%d unbreakable points", unbreakable);
    CHECK(kept > 0 && broken > 0, "%ld bonds over s0 kept, %ld broken: the region should "
          "split them", (long)kept, (long)broken);
    CHECK(wrong == 0, "%ld bonds in the wrong state with a no_failure region", (long)wrong);
    CHECK(nosbpd_broken_bond_count(m) == broken, "%ld broken, %ld expected",
          (long)nosbpd_broken_bond_count(m), (long)broken);
    free(x_prev);
    free(force);
    solid_model_free(m);
    test_lattice_free(p);
}

/* A crack through the middle of a block: the points next to it become surface. */
static void check_crack_surface(void)
{
    const int n_axis[3] = {20, 10, 8};
    solid_particles *p = test_lattice(n_axis[0], n_axis[1], n_axis[2], 0.01, 1000.0);
    char text[512];
    snprintf(text, sizeof text, "%s[solid.nosbpd]\n"
                                "failure = true\ncritical_stretch = 0.01\n", CASE_BASE);
    solid_model *m = test_model(text, p);
    uint8_t *surface = malloc((size_t)p->n);
    int count = solid_model_surface(m, p, surface);
    int wrong = 0, expected = 0;
    for (int i = 0; i < p->n; i++) {
        const int should = test_depth(p, i, n_axis) < 3;
        expected += should;
        wrong += surface[i] != should;
    }
    CHECK(wrong == 0 && count == expected, "intact block: %d points wrongly (not) surface, "
          "count %d, expected %d", wrong, count, expected);

    double *x_prev = malloc((size_t)p->n * FSI_DIM * sizeof *x_prev);
    double *force = malloc((size_t)p->n * FSI_DIM * sizeof *force);
    memcpy(x_prev, p->x, (size_t)p->n * FSI_DIM * sizeof *x_prev);
    for (int i = 0; i < p->n; i++)
        if (test_index(p, i, 0) >= 10)
            p->x[i * FSI_DIM] += 0.3 * p->spacing;
    CHECK(test_force(m, p, x_prev, force) == 0, "crack step failed");
    count = solid_model_surface(m, p, surface);
    wrong = expected = 0;
    for (int i = 0; i < p->n; i++) {
        const int col = test_index(p, i, 0);
        const int should = test_depth(p, i, n_axis) < 3 || (col >= 7 && col <= 12);
        expected += should;
        wrong += surface[i] != should;
    }
    CHECK(wrong == 0 && count == expected, "cracked block: %d points wrongly (not) surface, "
          "count %d, expected %d", wrong, count, expected);
    free(surface);
    free(x_prev);
    free(force);
    solid_model_free(m);
    test_lattice_free(p);
}

static void check_critical_stretch(void)
{
    solid_particles *p = test_lattice(6, 6, 6, 0.01, 1000.0);
    const double pi = 3.14159265358979323846, g0 = 50.0, e = 1e6, delta = 0.03;
    char text[512];
    snprintf(text, sizeof text, "%splane = strain\n[solid.nosbpd]\n"
                                "failure = true\nfracture_energy = %g\n",
             CASE_BASE, g0);
    solid_model *m = test_model(text, p);
    double expected = FSI_DIM == 2 ? sqrt(5 * pi * g0 / (12 * e * delta))
                                   : sqrt(5 * g0 / (9 * (e / (3 * (1 - 0.5))) * delta));
    CHECK(fabs(nosbpd_critical_stretch(m) - expected) < 1e-14,
          "plane strain s0 = %.15g, expected %.15g", nosbpd_critical_stretch(m), expected);
    solid_model_free(m);
    if (FSI_DIM == 2) {
        snprintf(text, sizeof text, "%splane = stress\n[solid.nosbpd]\n"
                                    "failure = true\nfracture_energy = %g\n",
                 CASE_BASE, g0);
        m = test_model(text, p);
        expected = sqrt(4 * pi * g0 / (9 * e * delta));
        CHECK(fabs(nosbpd_critical_stretch(m) - expected) < 1e-14,
              "plane stress s0 = %.15g, expected %.15g", nosbpd_critical_stretch(m), expected);
        solid_model_free(m);
    }
    snprintf(text, sizeof text,
             "%s[solid.nosbpd]\n"
             "failure = true\nfracture_energy = %g\ncritical_stretch = 0.05\n", CASE_BASE, g0);
    m = test_model(text, p);
    CHECK(nosbpd_critical_stretch(m) == 0.05, "critical_stretch did not win: %g",
          nosbpd_critical_stretch(m));
    solid_model_free(m);

    /* failure = true with neither key: an error naming the keys. */
    snprintf(text, sizeof text, "%s[solid.nosbpd]\nfailure = true\n", CASE_BASE);
    fsi_case *c = test_case(text);
    char msg[512] = "";
    m = solid_model_create(c, p, msg, sizeof msg);
    CHECK(m == NULL && strstr(msg, "critical_stretch") && strstr(msg, "fracture_energy"),
          "failure without s0 or G0: model %p, message '%s'", (void *)m, msg);
    solid_model_free(m);
    fsi_case_free(c);
    test_lattice_free(p);
}

/* A strip one point thick: every family is a line from the start. */
static void check_singular_at_creation(void)
{
    solid_particles *p = test_lattice(12, 1, 1, 0.01, 1000.0);
    solid_model *m = test_model(CASE_BASE, p);
    CHECK(nosbpd_points_without_force_state(m) == p->n, "%d of %d points of a line flagged",
          nosbpd_points_without_force_state(m), p->n);
    double *x_prev = malloc((size_t)p->n * FSI_DIM * sizeof *x_prev);
    double *force = malloc((size_t)p->n * FSI_DIM * sizeof *force);
    memcpy(x_prev, p->x, (size_t)p->n * FSI_DIM * sizeof *x_prev);
    for (int j = 0; j < p->n * FSI_DIM; j++)
        p->x[j] += 1e-4 * (test_uniform() - 0.5);
    CHECK(test_force(m, p, x_prev, force) == 0, "line step failed");
    CHECK(all_finite(force, p->n * FSI_DIM), "non-finite forces on a line of points");
    CHECK(isfinite(solid_model_strain_energy(m, p)), "non-finite energy on a line");
    solid_model_free(m);

    /* Two points thick is fine. */
    test_lattice_free(p);
    p = test_lattice(12, 2, 2, 0.01, 1000.0);
    m = test_model(CASE_BASE, p);
    CHECK(nosbpd_points_without_force_state(m) == 0, "%d points of a 2-thick strip flagged",
          nosbpd_points_without_force_state(m));
    solid_model_free(m);
    test_lattice_free(p);
    free(x_prev);
    free(force);
}

/* A pre-crack from the left edge along y = 0.05 (between rows 4 and 5), 0.082 m
 * long: exactly the bonds whose segment crosses that line within 0 <= x <= 0.082
 * break at creation, with failure off; damage is the broken volume fraction. */
static void check_precrack(void)
{
    if (FSI_DIM != 2)
        return;
    const double y_crack = 0.05, x_end = 0.082;
    solid_particles *p = test_lattice(20, 10, 1, 0.01, 1000.0);
    char text[512];
    snprintf(text, sizeof text, "%s[solid.crack notch]\nfrom = 0, %g\nto = %g, %g\n",
             CASE_BASE, y_crack, x_end, y_crack);
    solid_model *m = test_model(text, p);
    const nosbpd_bonds *b = nosbpd_model_bonds(m);
    const double *damage = nosbpd_damage(m);
    int64_t expected = 0, wrong = 0;
    int bad_damage = 0, damaged = 0;
    for (int i = 0; i < p->n; i++) {
        double all = 0.0, lost = 0.0;   /* the analytic cut, volume-weighted (Eq. 49) */
        for (int64_t q = b->offset[i]; q < b->offset[i + 1]; q++) {
            const double *xi = p->x0 + i * FSI_DIM, *xj = p->x0 + b->neighbour[q] * FSI_DIM;
            int cut = 0;
            if ((xi[1] - y_crack) * (xj[1] - y_crack) < 0.0) {
                const double x = xi[0] + (y_crack - xi[1]) / (xj[1] - xi[1]) * (xj[0] - xi[0]);
                cut = x >= 0.0 && x <= x_end;
            }
            expected += cut;
            wrong += cut == b->intact[q];
            all += p->volume[b->neighbour[q]];
            lost += cut ? p->volume[b->neighbour[q]] : 0.0;
        }
        bad_damage += fabs(damage[i] - lost / all) > 1e-14;
        damaged += lost > 0.0;
    }
    CHECK(expected > 0, "the crack should cut bonds");
    CHECK(wrong == 0, "%ld bonds in the wrong state next to a pre-crack (%ld cut expected)",
          (long)wrong, (long)expected);
    CHECK(bad_damage == 0 && damaged > 0,
          "%d points whose damage is not the share of their family across the crack "
          "(%d points next to it)", bad_damage, damaged);
    CHECK(nosbpd_broken_bond_count(m) == 0, "pre-cut bonds counted as broken by failure: %ld",
          (long)nosbpd_broken_bond_count(m));
    solid_model_free(m);
    test_lattice_free(p);
}

int main(void)
{
    check_breaking();
    check_no_failure_region();
    check_crack_surface();
    check_precrack();
    check_critical_stretch();
    check_singular_at_creation();
    return unit_check_report("nosbpd failure");
}
