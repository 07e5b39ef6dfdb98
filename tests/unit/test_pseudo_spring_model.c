/* Unit tests of the pseudo-spring SPH solid (solid_solver/pseudo_spring,
 * docs/pseudo_spring.md). What solid_model.h asks of every model (rigid motions,
 * momentum, thread independence) is the contract's (tests/contract); here:
 *  - the links are the immediate lattice neighbours: 8 inside, 5 on an edge, 3 at a
 *    corner (2D; 26 inside in 3D), fixed at creation;
 *  - the reference configuration gives exactly zero force;
 *  - a uniform stretch gives the Hooke stress at every point, edges and corners
 *    included (the corrected gradient is exact for a linear field), and the density
 *    of 004 Eq. 14 (solid_model_density: what the fluid is sent);
 *  - a rigid rotation leaves an unstressed body unstressed and rotates a pre-stress
 *    with the body (the Jaumann rate, 004 Eq. 17);
 *  - a link stretched beyond the failure strain breaks and stays broken when the
 *    point comes back, the damage is broken / initial links; no link of a
 *    no_failure point breaks; with failure off none breaks; the stable step shrinks
 *    by sqrt(intact / initial links) of the worst point, and not without a break;
 *  - a [solid.crack] breaks exactly the links that cross it, at creation;
 *  - the zero-energy mode of the immediate-neighbour stencil (u_y = a (-1)^i along x)
 *    leaves every interior point unstrained (Eq. 19 cannot see it), and the hourglass
 *    control stores G V0 (2 a / dx)^2 / 2 per interior point for it, nothing for an
 *    affine field (stretch plus a large rotation), little (O(dx^2)) for bending, and
 *    its force is minus the gradient of the energy it reports;
 *  - mirrored clamp points (SOLID_MIRRORED) are images, not material: after a step
 *    they carry no stress and store no energy, the others exactly what they would;
 *  - a hyperelastic material (a stress of F) is refused at creation, naming the key:
 *    the model has no deformation gradient. */
#include "pseudo_spring.h"
#include "unit_solid_model.h"

static const double DX = 0.01, RHO = 1000.0, E = 1e6, NU = 0.25;

static const char *CASE_BASE = "[solid]\n"
                               "solver = pseudo_spring\n"
                               "density = 1000\n"
                               "youngs_modulus = 1e6\n"
                               "poisson_ratio = 0.25\n"
                               "plane = strain\n";

static solid_model *model(const solid_particles *p, const char *extra)
{
    char text[1024];
    snprintf(text, sizeof text, "%s%s", CASE_BASE, extra ? extra : "");
    return test_model(text, p);
}

static void check_link_counts(void)
{
    const int n_axis[3] = {6, 5, 4};
    solid_particles *p = test_lattice(n_axis[0], n_axis[1], n_axis[2], DX, RHO);
    solid_model *m = model(p, NULL);
    const int32_t *count = pseudo_spring_initial_count(m);
    int wrong = 0, corners = 0, edges = 0, inside = 0;
    for (int i = 0; i < p->n; i++) {
        /* How many axes the point lies on the boundary of: 0 inside, 1 edge (face),
         * 2 corner (edge in 3D), 3 corner in 3D. Expected count prod (2 or 3) - 1. */
        int expected = 1, on = 0;
        for (int d = 0; d < FSI_DIM; d++) {
            const int a = test_index(p, i, d);
            const int boundary = a == 0 || a == n_axis[d] - 1;
            expected *= boundary ? 2 : 3;
            on += boundary;
        }
        expected -= 1;
        wrong += count[i] != expected || pseudo_spring_intact_count(m)[i] != expected;
        corners += on == FSI_DIM && count[i] == (FSI_DIM == 2 ? 3 : 7);
        edges += on == 1 && count[i] == (FSI_DIM == 2 ? 5 : 17);
        inside += on == 0 && count[i] == (FSI_DIM == 2 ? 8 : 26);
    }
    printf("links: %d corner, %d edge, %d inner points with the expected count; %d wrong\n",
           corners, edges, inside, wrong);
    CHECK(wrong == 0, "%d points with a link count other than the immediate neighbours'",
          wrong);
    CHECK(corners == (FSI_DIM == 2 ? 4 : 8), "corner points with 3 (7) links: %d", corners);
    CHECK(pseudo_spring_full_count(m) == (FSI_DIM == 2 ? 8 : 26), "full count %d",
          pseudo_spring_full_count(m));
    CHECK(inside > 0 && edges > 0, "no inner or edge points checked");
    solid_model_free(m);
    test_lattice_free(p);
}

static void check_reference_force(void)
{
    solid_particles *p = test_lattice(12, 8, 4, DX, RHO);
    solid_model *m = model(p, NULL);
    const size_t vec = (size_t)p->n * FSI_DIM * sizeof(double);
    double *f = malloc(vec), *x_prev = malloc(vec);
    memcpy(x_prev, p->x0, vec);
    for (int k = 0; k < p->n * FSI_DIM; k++)
        f[k] = 1.0;     /* must be overwritten */
    CHECK(test_force(m, p, x_prev, f) == 0, "reference step failed");
    int nonzero = 0;
    for (int k = 0; k < p->n * FSI_DIM; k++)
        nonzero += f[k] != 0.0;
    /* No stress, no relative velocity, no tension: every term is exactly zero. */
    CHECK(nonzero == 0, "%d force components are not exactly zero in the reference "
          "configuration", nonzero);
    free(f);
    free(x_prev);
    solid_model_free(m);
    test_lattice_free(p);
}

/* x = x0 + e x0_x e_x in one step. The mid-point gradient of du is e' = e / (1 + e/2)
 * along x (solid_objective.h), exactly for the corrected gradient at every point, so
 * sigma_xx = (lambda + 2 mu) e', sigma_yy = sigma_zz = lambda e' (plane strain) and
 * rho = rho0 (2 - e') / (2 + e'). Tolerance 1e-8 relative: du differences between
 * neighbours are e dx = 1e-6 m from positions of 0.1 m, round-off 1e-17 m, i.e. 1e-11
 * relative, with room for the sums. */
static void check_uniform_stretch(void)
{
    const double e = 1e-4, ep = e / (1.0 + 0.5 * e);
    solid_particles *p = test_lattice(10, 7, 4, DX, RHO);
    solid_model *m = model(p, NULL);
    const size_t vec = (size_t)p->n * FSI_DIM * sizeof(double);
    double *f = malloc(vec), *x_prev = malloc(vec);
    memcpy(x_prev, p->x0, vec);
    for (int i = 0; i < p->n; i++)
        p->x[i * FSI_DIM] = (1.0 + e) * p->x0[i * FSI_DIM];
    CHECK(test_force(m, p, x_prev, f) == 0, "stretch step failed");
    const double lambda = E * NU / ((1.0 + NU) * (1.0 - 2.0 * NU)), mu = E / (2.0 * (1.0 + NU));
    const double sxx = (lambda + 2.0 * mu) * ep, syy = lambda * ep;
    const double rho = RHO * (2.0 - ep) / (2.0 + ep);
    const double *s = pseudo_spring_stress(m), *density = solid_model_density(m, p);
    double worst = 0.0, worst_rho = 0.0;
    for (int i = 0; i < p->n; i++) {
        const double *si = s + i * 6;
        const double expect[6] = {sxx, syy, syy, 0, 0, 0};
        for (int k = 0; k < 6; k++)
            worst = fmax(worst, fabs(si[k] - expect[k]) / sxx);
        worst_rho = fmax(worst_rho, fabs(density[i] / rho - 1.0));
    }
    printf("uniform stretch: sigma_xx = %.9g Pa expected, largest relative stress error %.3g, "
           "density error %.3g\n", sxx, worst, worst_rho);
    CHECK(worst < 1e-8, "uniform stretch: stress off Hooke's by %.3g of sigma_xx", worst);
    CHECK(worst_rho < 1e-12, "uniform stretch: density off Eq. 14 by %.3g", worst_rho);
    free(f);
    free(x_prev);
    solid_model_free(m);
    test_lattice_free(p);
}

/* 90 degrees about the lattice centre in 30 steps; first unstressed (the stress must
 * stay zero: below 1e-9 of the pre-stress scale E * 1e-3, round-off of strains of
 * 1e-14 per step), then pre-stressed with sigma_xx = s0: sigma must end as
 * R sigma R^T, i.e. sigma_yy = s0 and sigma_xx = sigma_xy = 0. The Hughes-Winget
 * rotation of a rigid step is the exact rotation (solid_objective.h), so 1e-9 s0. */
static void check_rigid_rotation(void)
{
    if (FSI_DIM != 2)
        return;
    const double s0 = 1e3, angle = M_PI / 2.0;
    const int steps = 30;
    for (int pre = 0; pre < 2; pre++) {
        solid_particles *p = test_lattice(8, 6, 1, DX, RHO);
        solid_model *m = model(p, NULL);
        double *s = pseudo_spring_stress(m);
        if (pre)
            for (int i = 0; i < p->n; i++)
                s[i * 6] = s0;
        const size_t vec = (size_t)p->n * FSI_DIM * sizeof(double);
        double *f = malloc(vec), *x_prev = malloc(vec);
        const double cx = 0.04, cy = 0.03;
        int ok = 1;
        for (int k = 1; k <= steps && ok; k++) {
            memcpy(x_prev, p->x, vec);
            const double a = angle * k / steps, ca = cos(a), sa = sin(a);
            for (int i = 0; i < p->n; i++) {
                const double rx = p->x0[i * 2] - cx, ry = p->x0[i * 2 + 1] - cy;
                p->x[i * 2] = cx + ca * rx - sa * ry;
                p->x[i * 2 + 1] = cy + sa * rx + ca * ry;
            }
            ok = test_force(m, p, x_prev, f) == 0;
        }
        CHECK(ok, "rotation step failed");
        double worst = 0.0;
        for (int i = 0; i < p->n; i++) {
            const double expect[6] = {0, pre ? s0 : 0, 0, 0, 0, 0};
            for (int c = 0; c < 6; c++)
                worst = fmax(worst, fabs(s[i * 6 + c] - expect[c]));
        }
        const double scale = pre ? s0 : E * 1e-3;
        printf("rigid rotation by 90 degrees in %d steps, %s: largest stress error %.3g Pa "
               "(bound %.3g Pa)\n", steps, pre ? "pre-stressed" : "unstressed", worst,
               1e-9 * scale);
        CHECK(worst < 1e-9 * scale, "rigid rotation (%s): stress off by %.3g Pa",
              pre ? "pre-stressed" : "unstressed", worst);
        free(f);
        free(x_prev);
        solid_model_free(m);
        test_lattice_free(p);
    }
}

/* Index of the lattice point (a, b) of an nx-wide 2D lattice. */
static int at(int nx, int a, int b)
{
    return b * nx + a;
}

/* Point (4, 3) of a 10 x 7 lattice moved by 0.2 dx along +x: its links to the left
 * (strain 0.2), up-left and down-left (|(1.2, 1)| / sqrt 2 - 1 = 0.105) exceed the
 * failure strain 0.05; the vertical ones (0.0198) and the right-hand ones
 * (compressed) do not. After the point comes back the three stay broken: damage
 * 3/8 there, 1/8 at each of the three partners. */
static void check_failure(void)
{
    if (FSI_DIM != 2)
        return;
    const int nx = 10, ny = 7, moved = at(nx, 4, 3);
    for (int variant = 0; variant < 3; variant++) {
        /* 0: failure on; 1: failure on, the point in a no_failure zone; 2: failure off */
        solid_particles *p = test_lattice(nx, ny, 1, DX, RHO);
        if (variant == 1)
            p->flags[moved] |= SOLID_UNBREAKABLE;
        solid_model *m = model(p, variant == 2 ? "[solid.pseudo_spring]\nfailure = false\n"
                                               : "[solid.pseudo_spring]\nfailure = true\n"
                                                 "failure_strain = 0.05\n");
        const size_t vec = (size_t)p->n * FSI_DIM * sizeof(double);
        double *f = malloc(vec), *x_prev = malloc(vec);
        const double dt_intact = solid_model_stable_dt(m, p);
        memcpy(x_prev, p->x, vec);
        p->x[moved * 2] += 0.2 * DX;
        CHECK(test_force(m, p, x_prev, f) == 0, "failure step failed");
        memcpy(x_prev, p->x, vec);
        memcpy(p->x, p->x0, vec);
        CHECK(test_force(m, p, x_prev, f) == 0, "return step failed");
        const int64_t broken = pseudo_spring_broken_links(m);
        const double *damage = pseudo_spring_damage(m);
        const int partners[3] = {at(nx, 3, 3), at(nx, 3, 2), at(nx, 3, 4)};
        if (variant == 0) {
            CHECK(broken == 6, "%lld directed links broken, 6 expected", (long long)broken);
            CHECK(fabs(damage[moved] - 3.0 / 8.0) < 1e-15, "damage %g, 3/8 expected",
                  damage[moved]);
            for (int k = 0; k < 3; k++)
                CHECK(fabs(damage[partners[k]] - 1.0 / 8.0) < 1e-15,
                      "partner damage %g, 1/8 expected", damage[partners[k]]);
            CHECK(pseudo_spring_intact_count(m)[moved] == 5, "intact links %d, 5 expected",
                  pseudo_spring_intact_count(m)[moved]);
            /* The stable step follows the worst point's share of its links: 5 of 8. */
            const double dt_ratio = solid_model_stable_dt(m, p) / dt_intact;
            CHECK(fabs(dt_ratio - sqrt(5.0 / 8.0)) < 1e-14,
                  "stable step after failure %.15g of the intact one, sqrt(5/8) expected",
                  dt_ratio);
            /* Stays broken: a second stretch of the same links breaks nothing new. */
            memcpy(x_prev, p->x, vec);
            p->x[moved * 2] += 0.2 * DX;
            CHECK(test_force(m, p, x_prev, f) == 0, "second stretch failed");
            CHECK(pseudo_spring_broken_links(m) == 6 &&
                      pseudo_spring_intact_count(m)[moved] == 5,
                  "links came back or broke twice: %lld broken, %d intact",
                  (long long)pseudo_spring_broken_links(m), pseudo_spring_intact_count(m)[moved]);
        } else {
            CHECK(broken == 0, "%s: %lld links broken", variant == 1 ? "no_failure zone" :
                  "failure off", (long long)broken);
            CHECK(solid_model_stable_dt(m, p) == dt_intact,
                  "the stable step changed with no link broken");
        }
        printf("failure (%s): %lld directed links broken, damage %.4g at the moved point\n",
               variant == 0 ? "on" : variant == 1 ? "no_failure point" : "off",
               (long long)broken, damage[moved]);
        free(f);
        free(x_prev);
        solid_model_free(m);
        test_lattice_free(p);
    }
}

/* A crack along y = 0.03 (between rows 2 and 3) from x = 0 to 0.045 (ending between
 * columns 4 and 5): the vertical links of columns 0-4 and the diagonal links whose
 * crossing lies before x = 0.045 are broken at creation, the others intact; failure
 * is off, so this is the crack alone. */
static void check_crack(void)
{
    if (FSI_DIM != 2)
        return;
    const double y_crack = 0.03, x_end = 0.045;
    solid_particles *p = test_lattice(10, 6, 1, DX, RHO);
    char extra[256];
    snprintf(extra, sizeof extra, "[solid.crack notch]\nfrom = 0, %g\nto = %g, %g\n", y_crack,
             x_end, y_crack);
    solid_model *m = model(p, extra);
    const solid_bonds *l = pseudo_spring_links(m);
    long wrong = 0, cut = 0;
    for (int i = 0; i < p->n; i++)
        for (int64_t q = l->offset[i]; q < l->offset[i + 1]; q++) {
            const int j = l->neighbour[q];
            const double *xi = p->x0 + i * 2, *xj = p->x0 + j * 2;
            int crosses = 0;
            if ((xi[1] - y_crack) * (xj[1] - y_crack) < 0.0) {
                const double x = xi[0] + (y_crack - xi[1]) / (xj[1] - xi[1]) * (xj[0] - xi[0]);
                crosses = x >= 0.0 && x <= x_end;
            }
            cut += crosses;
            wrong += crosses == l->intact[q];
        }
    printf("crack: %ld directed links cross it, %ld in the wrong state\n", cut, wrong);
    /* Columns 0-4 have a vertical link each (5), the diagonals crossing at
     * x = 0.01 .. 0.04 (8) and at 0.0 does not exist: 13 pairs, 26 directed. */
    CHECK(cut == 26, "%ld directed links cross the crack, 26 expected", cut);
    CHECK(wrong == 0, "%ld links in the wrong state next to the crack", wrong);
    solid_model_free(m);
    test_lattice_free(p);
}

/* Stored energy of the positions p->x without a step (the stress work is still 0):
 * the hourglass control's alone. */
static double hourglass_energy(solid_model *m, const solid_particles *p)
{
    return solid_model_strain_energy(m, p);
}

static void check_zero_energy_mode(void)
{
    const int nx = 12, ny = 12, nz = 4;
    const int n_axis[3] = {nx, ny, nz};
    const double a = 1e-7, mu = E / (2.0 * (1.0 + NU)), eps = 2.0 * a / DX;
    solid_particles *p = test_lattice(nx, ny, nz, DX, RHO);
    const size_t vec = (size_t)p->n * FSI_DIM * sizeof(double);
    double *f = malloc(vec), *x_prev = malloc(vec);
    memcpy(x_prev, p->x0, vec);
    for (int i = 0; i < p->n; i++)
        p->x[i * FSI_DIM + 1] += (test_index(p, i, 0) % 2 ? -a : a);

    /* Without the control: the mode strains no interior point, to first order in a
     * (the mid-point configuration the gradient is taken on is itself perturbed by
     * a / dx = 1e-5; the edges, with one-sided stencils, see the mode in full). */
    solid_model *off = model(p, "[solid.pseudo_spring]\nhourglass_control = 0\n");
    CHECK(hourglass_energy(off, p) == 0.0, "hourglass_control = 0 stores energy");
    CHECK(test_force(off, p, x_prev, f) == 0, "zero-energy step failed");
    double inner = 0.0, edge = 0.0;
    for (int i = 0; i < p->n; i++) {
        double s = 0.0;
        for (int k = 0; k < 6; k++)
            s = fmax(s, fabs(pseudo_spring_stress(off)[i * 6 + k]));
        if (test_depth(p, i, n_axis) > 0)
            inner = fmax(inner, s);
        else
            edge = fmax(edge, s);
    }
    printf("zero-energy mode u_y = %g (-1)^i: largest interior stress %.3g Pa, edge %.3g Pa "
           "(G eps = %.3g Pa) without the control\n", a, inner, edge, mu * eps);
    CHECK(inner < 1e-3 * mu * eps && edge > 0.5 * mu * eps, "the mode strains interior points (%g Pa): it is not the "
          "stencil's zero-energy mode any more", inner);
    solid_model_free(off);

    /* With it: G V0 eps^2 / 2 per interior point (2D, exactly: H_i = 0 and r = -2 a on
     * the 6 links with an x offset), edges their own share. */
    solid_model *m = model(p, NULL);
    double expect = 0.0;
    for (int i = 0; i < p->n; i++)
        expect += 0.5 * mu * p->volume[i] * eps * eps;
    const double e_mode = hourglass_energy(m, p);
    printf("hourglass control: energy of the mode %.6g J, %.4f of G V0 eps^2 / 2 per point\n",
           e_mode, e_mode / expect);
    CHECK(e_mode > 0.3 * expect && e_mode < 1.5 * expect,
          "the zero-energy mode stores %g of G V0 eps^2 / 2", e_mode / expect);

    /* Its force is -dE/dx: x_prev = x (no strain increment, no relative velocity, no
     * stress) leaves the control's force alone; E is quadratic in x, so the central
     * difference is exact up to round-off. */
    for (int k = 0; k < p->n * FSI_DIM; k++)
        p->x[k] = p->x0[k] + 1e-6 * (test_uniform() - 0.5);
    memcpy(x_prev, p->x, vec);
    CHECK(test_force(m, p, x_prev, f) == 0, "hourglass force step failed");
    double worst = 0.0, scale = 0.0;
    for (int trial = 0; trial < 12; trial++) {
        const int k = (int)(test_uniform() * p->n * FSI_DIM) % (p->n * FSI_DIM);
        const double h = 1e-7, x0 = p->x[k];
        p->x[k] = x0 + h;
        const double ep = hourglass_energy(m, p);
        p->x[k] = x0 - h;
        const double em = hourglass_energy(m, p);
        p->x[k] = x0;
        worst = fmax(worst, fabs(f[k] + (ep - em) / (2.0 * h)));
        scale = fmax(scale, fabs(f[k]));
    }
    printf("hourglass force against -dE/dx: largest difference %.3g N (forces up to %.3g N)\n",
           worst, scale);
    CHECK(scale > 0.0 && worst < 1e-6 * scale, "hourglass force is not -dE/dx (%g against %g)",
          worst, scale);

    /* An affine field, a stretch and a rotation by 0.5 rad: nothing. Bending u_x = -k x y,
     * u_y = k x^2 / 2 (about the lattice centre): the quadratic part only, O(dx^2)
     * against the bending energy sum V0 E' (k y)^2 / 2. */
    double c[3] = {0};
    for (int i = 0; i < p->n; i++)
        for (int d = 0; d < FSI_DIM; d++)
            c[d] += p->x0[i * FSI_DIM + d] / p->n;
    const double th = 0.5;
    for (int i = 0; i < p->n; i++) {
        const double X = p->x0[i * FSI_DIM] - c[0], Y = p->x0[i * FSI_DIM + 1] - c[1];
        p->x[i * FSI_DIM] = c[0] + cos(th) * 1.01 * X - sin(th) * Y;
        p->x[i * FSI_DIM + 1] = c[1] + sin(th) * 1.01 * X + cos(th) * Y;
    }
    const double e_affine = hourglass_energy(m, p);
    const double kb = 1e-3 / (nx * DX), ep_plane = E / (1.0 - NU * NU);
    double e_bend = 0.0;
    for (int i = 0; i < p->n; i++) {
        const double X = p->x0[i * FSI_DIM] - c[0], Y = p->x0[i * FSI_DIM + 1] - c[1];
        p->x[i * FSI_DIM] = p->x0[i * FSI_DIM] - kb * X * Y;
        p->x[i * FSI_DIM + 1] = p->x0[i * FSI_DIM + 1] + 0.5 * kb * X * X;
        e_bend += 0.5 * p->volume[i] * ep_plane * kb * kb * Y * Y;
    }
    const double e_hg_bend = hourglass_energy(m, p);
    printf("hourglass control: affine field %.3g J (a 1 %% stretch stores %.3g J), bending "
           "%.4f of the bending energy\n", e_affine,
           0.5 * E * 1e-4 * p->n * p->volume[0], e_hg_bend / e_bend);
    CHECK(e_affine < 1e-12 * E * 1e-4 * p->n * p->volume[0], "an affine field stores %g J",
          e_affine);
    CHECK(e_hg_bend < 0.05 * e_bend, "bending stores %g of its energy in the control",
          e_hg_bend / e_bend);
    free(f);
    free(x_prev);
    solid_model_free(m);
    test_lattice_free(p);
}

static void check_mirrored_points(void)
{
    const double e = 1e-4;
    solid_particles *p = test_lattice(10, 7, 4, DX, RHO);
    const size_t vec = (size_t)p->n * FSI_DIM * sizeof(double);
    double *f = malloc(vec), *x_prev = malloc(vec);
    memcpy(x_prev, p->x0, vec);
    for (int i = 0; i < p->n; i++)
        p->x[i * FSI_DIM] = (1.0 + e) * p->x0[i * FSI_DIM];
    solid_model *plain = model(p, NULL);
    CHECK(test_force(plain, p, x_prev, f) == 0, "stretch step failed");
    const double e_plain = solid_model_strain_energy(plain, p);
    int ghosts = 0;
    for (int i = 0; i < p->n; i++)
        if (test_index(p, i, 0) == 0) {
            p->flags[i] |= SOLID_CLAMPED | SOLID_MIRRORED;
            ghosts++;
        }
    solid_model *m = model(p, NULL);
    CHECK(test_force(m, p, x_prev, f) == 0, "stretch step with mirrored points failed");
    double ghost_stress = 0.0, other = 0.0;
    for (int i = 0; i < p->n; i++)
        for (int k = 0; k < 6; k++) {
            const double a = pseudo_spring_stress(m)[i * 6 + k];
            if (p->flags[i] & SOLID_MIRRORED)
                ghost_stress = fmax(ghost_stress, fabs(a));
            else
                other = fmax(other, fabs(a - pseudo_spring_stress(plain)[i * 6 + k]));
        }
    /* A uniform stretch does the same work at every point. */
    const double e_ghost = solid_model_strain_energy(m, p);
    const double expect = e_plain * (p->n - ghosts) / p->n;
    printf("mirrored points: %d, their largest stress %.3g Pa, the others' change %.3g Pa, "
           "energy %.9g J against %.9g J for the material points\n", ghosts, ghost_stress,
           other, e_ghost, expect);
    CHECK(ghost_stress == 0.0, "a mirrored point carries a stress (%g Pa)", ghost_stress);
    CHECK(other == 0.0, "the material points' stress changed (%g Pa)", other);
    CHECK(fabs(e_ghost / expect - 1.0) < 1e-9, "energy %g J, material points' %g J", e_ghost,
          expect);
    free(f);
    free(x_prev);
    solid_model_free(m);
    solid_model_free(plain);
    test_lattice_free(p);
}

static void check_refuses_hyperelastic(void)
{
    static const char *const kinds[] = {"saint_venant_kirchhoff", "neo_hookean"};
    solid_particles *p = test_lattice(4, 4, 4, DX, RHO);
    for (int k = 0; k < 2; k++) {
        char text[1024], msg[512], want[128];
        snprintf(text, sizeof text, "%sconstitutive = %s\n", CASE_BASE, kinds[k]);
        fsi_case *c = test_case(text);
        solid_model *m = solid_model_create(c, p, msg, sizeof msg);
        snprintf(want, sizeof want, "[solid] constitutive: %s", kinds[k]);
        CHECK(!m && strstr(msg, want) &&
                  strstr(msg, "pseudo_spring has no deformation gradient; use linear_elastic"),
              "%s: model %p, message '%s'", kinds[k], (void *)m, msg);
        solid_model_free(m);
        fsi_case_free(c);
    }
    test_lattice_free(p);
}

int main(void)
{
    check_link_counts();
    check_reference_force();
    check_uniform_stretch();
    check_rigid_rotation();
    check_failure();
    check_crack();
    check_zero_energy_mode();
    check_mirrored_points();
    check_refuses_hyperelastic();
    return unit_check_report("test_pseudo_spring_model");
}
