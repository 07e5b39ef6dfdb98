/* Unit tests of the total-Lagrangian SPH solid (solid_solver/tlsph, 003 §2.2). What
 * solid_model.h asks of every model is the contract's (tests/contract); here, on a
 * 12 x 8 (x 6) lattice, for gradient_order 1 (003 Eq. 35's corrected gradient) and 2
 * (the quadratic fit) and both kernels (cubic_spline, wendland_c2):
 *  - F = I in the reference configuration at every point, corners included, and an
 *    affine map x = A X + c gives F = A at every point (1e-12: round-off of F formed
 *    from positions of 0.1 m and differences of 0.01 m with a shape matrix of
 *    condition below 10);
 *  - a quadratic field: order 2 gives the exact gradient at every point, edges and
 *    corners included (1e-10 of the largest displacement gradient); order 1 gives it
 *    inside (a symmetric family cancels the quadratic term) but misses it at the
 *    edges by more than 1e-3 of it (a one-sided family), the reason for order 2;
 *  - with saint_venant_kirchhoff (an exact strain energy) the internal force is
 *    -dE/dx by central differences of solid_model_strain_energy at a random finite
 *    deformation (1e-6 of the largest force), and the forces carry no net force or
 *    moment (1e-12 of sum |f| and sum |x| |f|: P F^T is symmetric);
 *  - the model is stateless: solid_model_stateless is 1 and a force at positions x
 *    is the same bit for bit before and after a call at other positions; a
 *    drucker_prager material is refused naming 'constitutive', and a body one point
 *    thick naming the shape matrix;
 *  - the hourglass control (hourglass_control = 1) adds nothing for an affine field
 *    (1e-10 of the largest force) and opposes the alternating mode u_y = a (-1)^i
 *    along x (sum f . u < 0) with no net force or moment, a zero-energy mode of
 *    gradient_order 1: F stays I at every interior point;
 *  - mirrored clamp points (SOLID_CLAMPED | SOLID_MIRRORED) contribute positions
 *    only: they store no strain energy (the model's is the material points' sum of
 *    V W(F), though the images' own F is strained), and the force, with an image's
 *    handed to its partner (solid_mirror_forces), is -dE/dx of the partner moving
 *    its image along. */
#include "material.h"
#include "solid_integrate.h"
#include "tlsph.h"
#include "unit_solid_model.h"

static const double DX = 0.01, RHO = 1000.0;
/* 6 across in 3D: points two layers from every face exist (a full family). */
static const int SIDES[3] = {12, 8, 6};
static const char *const KERNELS[] = {"cubic_spline", "wendland_c2"};

static const char *case_text(const char *kernel, int order, const char *constitutive,
                             const char *extra)
{
    static char text[1024];
    snprintf(text, sizeof text,
             "[solid]\nsolver = tlsph\nspacing = 0.01\ndensity = 1000\n"
             "youngs_modulus = 1e6\npoisson_ratio = 0.3\nconstitutive = %s\n%s"
             "[solid.tlsph]\nkernel = %s\ngradient_order = %d\n%s",
             constitutive, strstr(constitutive, "drucker") ? "cohesion = 1e4\n"
                                                            "friction_angle = 30\n" : "",
             kernel, order, extra ? extra : "");
    return text;
}

static solid_model *model(const solid_particles *p, const char *kernel, int order,
                          const char *extra)
{
    return test_model(case_text(kernel, order, "saint_venant_kirchhoff", extra), p);
}

static solid_particles *lattice(void)
{
    return test_lattice(SIDES[0], SIDES[1], SIDES[2], DX, RHO);
}

/* Largest |F_i - expect| entry at positions x, over the points with depth (lattice
 * layers to the nearest edge) in [lo, hi]; *where the worst point. NaN when no point
 * has such a depth (so that no check passes on nothing). */
static double worst_gradient(const solid_model *m, const solid_particles *p, const double *x,
                             const double *expect_all, int per_point, int lo, int hi,
                             int *where)
{
    double worst = 0.0;
    int count = 0;
    for (int i = 0; i < p->n; i++) {
        const int depth = test_depth(p, i, SIDES);
        if (depth < lo || depth > hi)
            continue;
        count++;
        double f[FSI_MAT_SIZE];
        tlsph_deformation_gradient(m, x, i, f);
        const double *expect = expect_all + (per_point ? (size_t)i * FSI_MAT_SIZE : 0);
        for (int k = 0; k < FSI_MAT_SIZE; k++)
            if (fabs(f[k] - expect[k]) > worst) {
                worst = fabs(f[k] - expect[k]);
                if (where)
                    *where = i;
            }
    }
    return count ? worst : NAN;
}

static void check_reference_and_affine(const char *kernel, int order)
{
    solid_particles *p = lattice();
    solid_model *m = model(p, kernel, order, NULL);
    double eye[FSI_MAT_SIZE], a[FSI_MAT_SIZE];
    fsi_mat_identity(eye);
    const double at_rest = worst_gradient(m, p, p->x0, eye, 0, 0, 1 << 30, NULL);
    /* A = a stretch, a shear and a rotation, no symmetry; c a translation. */
    const double entries[9] = {1.1, 0.2, -0.05, -0.15, 0.93, 0.07, 0.04, -0.08, 1.02};
    for (int r = 0; r < FSI_DIM; r++)
        for (int c = 0; c < FSI_DIM; c++)
            FSI_MAT(a, r, c) = entries[r * 3 + c];
    for (int i = 0; i < p->n; i++) {
        fsi_mat_vec(a, p->x0 + (size_t)i * FSI_DIM, p->x + (size_t)i * FSI_DIM);
        for (int d = 0; d < FSI_DIM; d++)
            p->x[i * FSI_DIM + d] += 0.3 - 0.2 * d;
    }
    const double affine = worst_gradient(m, p, p->x, a, 0, 0, 1 << 30, NULL);
    printf("%s, order %d: F - I at rest up to %.3g, F - A for x = A X + c up to %.3g "
           "(%d points, corners included)\n", kernel, order, at_rest, affine, p->n);
    CHECK(at_rest <= 1e-12, "%s order %d: F off I by %.3g at rest", kernel, order, at_rest);
    CHECK(affine <= 1e-12, "%s order %d: F off A by %.3g for an affine map", kernel, order,
          affine);
    solid_model_free(m);
    test_lattice_free(p);
}

/* u_d = kappa sum_ab C_dab X_a X_b and its gradient du_d/dX_e = kappa sum_b
 * (C_deb + C_dbe) X_b; kappa = 2 /m makes gradients of about 0.2 on the lattice. */
static void quadratic_field(const double *x0, double *u, double *grad)
{
    static const double c[3][3][3] = {{{0.5, 0.3, 0.1}, {0.0, -0.2, 0.2}, {0.0, 0.0, 0.3}},
                                      {{-0.4, 0.25, -0.1}, {0.0, 0.6, 0.15}, {0.0, 0.0, -0.2}},
                                      {{0.2, -0.1, 0.3}, {0.0, 0.1, 0.05}, {0.0, 0.0, 0.4}}};
    const double kappa = 2.0;
    for (int d = 0; d < FSI_DIM; d++) {
        u[d] = 0.0;
        for (int a = 0; a < FSI_DIM; a++)
            for (int b = 0; b < FSI_DIM; b++)
                u[d] += kappa * c[d][a][b] * x0[a] * x0[b];
        for (int e = 0; e < FSI_DIM; e++) {
            double g = 0.0;
            for (int b = 0; b < FSI_DIM; b++)
                g += kappa * (c[d][e][b] + c[d][b][e]) * x0[b];
            FSI_MAT(grad, d, e) = g;
        }
    }
}

static void check_quadratic(const char *kernel)
{
    solid_particles *p = lattice();
    double *exact = malloc((size_t)p->n * FSI_MAT_SIZE * sizeof *exact);
    double scale = 0.0;
    for (int i = 0; i < p->n; i++) {
        double u[FSI_DIM];
        double *g = exact + (size_t)i * FSI_MAT_SIZE;
        quadratic_field(p->x0 + (size_t)i * FSI_DIM, u, g);
        for (int k = 0; k < FSI_MAT_SIZE; k++)
            scale = fmax(scale, fabs(g[k]));
        for (int d = 0; d < FSI_DIM; d++) {
            p->x[i * FSI_DIM + d] = p->x0[i * FSI_DIM + d] + u[d];
            FSI_MAT(g, d, d) += 1.0;        /* F = I + grad u */
        }
    }
    double worst[3] = {0};  /* order 2 everywhere, order 1 inside, order 1 at the edges */
    int where = -1;
    for (int order = 1; order <= 2; order++) {
        solid_model *m = model(p, kernel, order, NULL);
        if (order == 2) {
            worst[0] = worst_gradient(m, p, p->x, exact, 1, 0, 1 << 30, NULL) / scale;
        } else {
            worst[1] = worst_gradient(m, p, p->x, exact, 1, 2, 1 << 30, NULL) / scale;
            worst[2] = worst_gradient(m, p, p->x, exact, 1, 0, 0, &where) / scale;
        }
        solid_model_free(m);
    }
    printf("%s, quadratic field (gradients up to %.3g): order 2 off by %.3g everywhere; "
           "order 1 by %.3g inside (depth >= 2) and %.3g at the edges (worst at (%g, %g))\n",
           kernel, scale, worst[0], worst[1], worst[2], p->x0[where * FSI_DIM],
           p->x0[where * FSI_DIM + 1]);
    CHECK(worst[0] <= 1e-10, "%s: order 2 misses a quadratic field's gradient by %.3g", kernel,
          worst[0]);
    CHECK(worst[1] <= 1e-10, "%s: order 1 misses a quadratic field's gradient inside by %.3g",
          kernel, worst[1]);
    CHECK(worst[2] > 1e-3, "%s: order 1 gets a quadratic field's gradient at the edges to "
          "%.3g: order 2 would not be needed", kernel, worst[2]);
    free(exact);
    test_lattice_free(p);
}

/* A smooth stretch, shear and bending (about 10 %) plus a random part (1 % of dx). */
static void finite_deformation(solid_particles *p)
{
    for (int i = 0; i < p->n; i++) {
        double *x = p->x + (size_t)i * FSI_DIM;
        const double *x0 = p->x0 + (size_t)i * FSI_DIM;
        for (int d = 0; d < FSI_DIM; d++)
            x[d] = x0[d] + 0.01 * DX * (test_uniform() - 0.5);
        x[0] += 0.1 * x0[0] + 0.05 * x0[1];
        x[1] += -0.05 * x0[1] + 2.0 * x0[0] * x0[0];
    }
}

/* Net force and moment of f at p->x, relative to sum |f| and sum |x| |f|. */
static void momentum_sums(const solid_particles *p, const double *f, double *linear,
                          double *angular)
{
    double sum[FSI_DIM] = {0}, moment[3] = {0}, f_abs = 0.0, m_abs = 0.0;
    for (int i = 0; i < p->n; i++) {
        const double *x = p->x + (size_t)i * FSI_DIM, *fi = f + (size_t)i * FSI_DIM;
        double x3[3] = {0}, f3[3] = {0}, nx = 0.0, nf = 0.0;
        for (int d = 0; d < FSI_DIM; d++) {
            sum[d] += fi[d];
            x3[d] = x[d];
            f3[d] = fi[d];
            nx += x[d] * x[d];
            nf += fi[d] * fi[d];
        }
        moment[0] += x3[1] * f3[2] - x3[2] * f3[1];
        moment[1] += x3[2] * f3[0] - x3[0] * f3[2];
        moment[2] += x3[0] * f3[1] - x3[1] * f3[0];
        f_abs += sqrt(nf);
        m_abs += sqrt(nx * nf);
    }
    *linear = 0.0;
    *angular = 0.0;
    for (int d = 0; d < FSI_DIM; d++)
        *linear = fmax(*linear, fabs(sum[d]) / f_abs);
    for (int d = 0; d < 3; d++)
        *angular = fmax(*angular, fabs(moment[d]) / m_abs);
}

/* Central differences of the energy in coordinate k with the step e (an image of k's
 * point, if any, moved along by solid_follow_partners). */
static double energy_slope(solid_model *m, solid_particles *p, int k, double e)
{
    const double x_k = p->x[k];
    double energy[2];
    for (int s = 0; s < 2; s++) {
        p->x[k] = x_k + (s ? -e : e);
        solid_follow_partners(p);
        energy[s] = solid_model_strain_energy(m, p);
    }
    p->x[k] = x_k;
    solid_follow_partners(p);
    return (energy[0] - energy[1]) / (2.0 * e);
}

/* -dE/dx against f at 'trials' random coordinates of points that are not images:
 * the largest difference over the largest force. The step e = 1e-6 dx leaves a
 * truncation error of about (1e-6)^2 of the force and a cancellation error of
 * 2e-16 E / e, 1e-9 of it (2D: E of 6e2 J, forces up to 1e4 N), so 1e-6 of the
 * largest force is the tolerance; a force that is not the energy's gradient is off
 * by the size of the strain (1e-1). */
static double energy_gradient_error(solid_model *m, solid_particles *p, const double *f,
                                    int trials, double *f_max)
{
    *f_max = 0.0;
    for (int k = 0; k < p->n * FSI_DIM; k++)
        *f_max = fmax(*f_max, fabs(f[k]));
    double worst = 0.0;
    for (int t = 0; t < trials; t++) {
        int k;
        do
            k = (int)(test_uniform() * p->n * FSI_DIM);
        while (p->flags[k / FSI_DIM] & SOLID_MIRRORED);
        worst = fmax(worst, fabs(energy_slope(m, p, k, 1e-6 * DX) + f[k]));
    }
    return worst / *f_max;
}

static void check_energy_and_momentum(const char *kernel, int order)
{
    solid_particles *p = lattice();
    solid_model *m = model(p, kernel, order, NULL);
    finite_deformation(p);
    const size_t size = (size_t)p->n * FSI_DIM * sizeof(double);
    double *f = malloc(size);
    CHECK(test_force(m, p, p->x, f) == 0, "%s order %d: force failed", kernel, order);
    double f_max, linear, angular;
    const double worst = energy_gradient_error(m, p, f, 16, &f_max);
    momentum_sums(p, f, &linear, &angular);
    printf("%s, order %d, SVK at a finite deformation: |dE/dx + f| up to %.3g of the largest "
           "force %.3g N; net force %.3g of sum |f|, net moment %.3g of sum |x| |f|\n", kernel,
           order, worst, f_max, linear, angular);
    CHECK(f_max > 0.0 && worst <= 1e-6, "%s order %d: the force is not -dE/dx (%.3g of the "
          "largest force)", kernel, order, worst);
    CHECK(linear <= 1e-12 && angular <= 1e-12, "%s order %d: net force %.3g, net moment %.3g",
          kernel, order, linear, angular);
    free(f);
    solid_model_free(m);
    test_lattice_free(p);
}

static void check_stateless(void)
{
    solid_particles *p = lattice();
    solid_model *m = model(p, "cubic_spline", 2, NULL);
    const size_t size = (size_t)p->n * FSI_DIM * sizeof(double);
    double *first = malloc(size), *again = malloc(size), *x1 = malloc(size);
    finite_deformation(p);
    memcpy(x1, p->x, size);
    int ok = test_force(m, p, p->x, first) == 0;
    /* Elsewhere (a larger deformation), then back. */
    for (int k = 0; k < p->n * FSI_DIM; k++)
        p->x[k] += 0.5 * (p->x[k] - p->x0[k]);
    ok &= test_force(m, p, p->x, again) == 0;
    memcpy(p->x, x1, size);
    ok &= test_force(m, p, p->x, again) == 0;
    const int same = memcmp(first, again, size) == 0;
    printf("stateless: solid_model_stateless %d, the force at x after a call elsewhere is %s\n",
           solid_model_stateless(m), same ? "the same bit for bit" : "different");
    CHECK(solid_model_stateless(m) == 1, "solid_model_stateless is %d", solid_model_stateless(m));
    CHECK(ok && same, "the force at the same positions changed after a call elsewhere");
    free(first);
    free(again);
    free(x1);
    solid_model_free(m);
    test_lattice_free(p);
}

static void check_refusals(void)
{
    char msg[512];
    solid_particles *p = lattice();
    fsi_case *c = test_case(case_text("cubic_spline", 2, "drucker_prager", NULL));
    solid_model *m = solid_model_create(c, p, msg, sizeof msg);
    printf("drucker_prager: %s\n", m ? "(accepted)" : msg);
    CHECK(!m && strstr(msg, "[solid] constitutive") && strstr(msg, "drucker_prager"),
          "drucker_prager: model %p, message '%s'", (void *)m, msg);
    solid_model_free(m);
    fsi_case_free(c);
    test_lattice_free(p);

    /* One point thick: every family on a line (a plane in 3D), K singular. */
    p = test_lattice(SIDES[0], 1, SIDES[2], DX, RHO);
    for (int order = 1; order <= 2; order++) {
        c = test_case(case_text("cubic_spline", order, "saint_venant_kirchhoff", NULL));
        m = solid_model_create(c, p, msg, sizeof msg);
        if (order == 1)
            printf("one point thick: %s\n", m ? "(accepted)" : msg);
        CHECK(!m && strstr(msg, "shape matrix"), "one point thick, order %d: model %p, "
              "message '%s'", order, (void *)m, msg);
        solid_model_free(m);
        fsi_case_free(c);
    }
    test_lattice_free(p);
}

/* Forces at p->x with and without hourglass_control = 1: the control's force is the
 * difference. */
static void hourglass_force(const solid_particles *p, const char *kernel, int order,
                            double *plain, double *control)
{
    solid_model *off = model(p, kernel, order, NULL);
    solid_model *on = model(p, kernel, order, "hourglass_control = 1\n");
    CHECK(test_force(off, p, p->x, plain) == 0 && test_force(on, p, p->x, control) == 0,
          "%s order %d: hourglass force step failed", kernel, order);
    for (int k = 0; k < p->n * FSI_DIM; k++)
        control[k] -= plain[k];
    solid_model_free(off);
    solid_model_free(on);
}

static void check_hourglass(const char *kernel, int order)
{
    solid_particles *p = lattice();
    const size_t size = (size_t)p->n * FSI_DIM * sizeof(double);
    double *plain = malloc(size), *control = malloc(size);
    /* An affine field: a stretch, a shear and a rotation by 0.5 rad. */
    const double th = 0.5;
    for (int i = 0; i < p->n; i++) {
        const double x = p->x0[i * FSI_DIM], y = p->x0[i * FSI_DIM + 1];
        p->x[i * FSI_DIM] = cos(th) * (1.05 * x + 0.1 * y) - sin(th) * 0.97 * y;
        p->x[i * FSI_DIM + 1] = sin(th) * (1.05 * x + 0.1 * y) + cos(th) * 0.97 * y;
    }
    hourglass_force(p, kernel, order, plain, control);
    double f_max = 0.0, extra = 0.0;
    for (int k = 0; k < p->n * FSI_DIM; k++) {
        f_max = fmax(f_max, fabs(plain[k]));
        extra = fmax(extra, fabs(control[k]));
    }
    printf("%s, order %d, hourglass control: an affine field adds %.3g of the largest force "
           "%.3g N\n", kernel, order, extra / f_max, f_max);
    CHECK(extra <= 1e-10 * f_max, "%s order %d: the control adds %.3g N to an affine field",
          kernel, order, extra);

    /* The alternating mode u_y = a (-1)^i along x, a = 1e-3 dx (a strain 2 a / dx). */
    const double a = 1e-3 * DX;
    memcpy(p->x, p->x0, size);
    for (int i = 0; i < p->n; i++)
        p->x[i * FSI_DIM + 1] += test_index(p, i, 0) % 2 ? -a : a;
    double eye[FSI_MAT_SIZE];
    fsi_mat_identity(eye);
    solid_model *m = model(p, kernel, order, NULL);
    const double inside = worst_gradient(m, p, p->x, eye, 0, 2, 1 << 30, NULL);
    const double edge = worst_gradient(m, p, p->x, eye, 0, 0, 0, NULL);
    solid_model_free(m);
    hourglass_force(p, kernel, order, plain, control);
    double work = 0.0, scale = 0.0, linear, angular;
    for (int k = 0; k < p->n * FSI_DIM; k++) {
        work += control[k] * (p->x[k] - p->x0[k]);
        scale += fabs(control[k] * (p->x[k] - p->x0[k]));
    }
    momentum_sums(p, control, &linear, &angular);
    printf("%s, order %d, mode u_y = a (-1)^i: |F - I| up to %.3g inside (depth >= 2), %.3g "
           "at the edges (2 a / dx = %.3g); the control's sum f . u = %.3g of sum |f . u|, "
           "its net force %.3g and moment %.3g (relative)\n",
           kernel, order, inside, edge, 2.0 * a / DX, work / scale, linear, angular);
    if (order == 1) {
        /* The zero-energy mode of the corrected gradient: a symmetric family sums the
         * odd-offset differences -2 a (-1)^i against g_iJ = -g_i(-J) to zero. */
        CHECK(inside <= 1e-12, "%s order 1: the mode strains interior points (|F - I| = "
              "%.3g): it is no zero-energy mode", kernel, inside);
        CHECK(edge > 0.1 * 2.0 * a / DX, "%s order 1: the edges do not see the mode either "
              "(%.3g)", kernel, edge);
    }
    CHECK(scale > 0.0 && work < 0.0, "%s order %d: the hourglass force does not oppose the "
          "mode (sum f . u = %.3g of sum |f . u|)", kernel, order, work / scale);
    /* Equal, opposite and central pair forces: neither momentum changes. */
    CHECK(linear <= 1e-12 && angular <= 1e-12, "%s order %d: the control's net force %.3g, "
          "net moment %.3g", kernel, order, linear, angular);
    free(plain);
    free(control);
    test_lattice_free(p);
}

/* The first three columns mirror the next three across x = 3 dx (column a's partner is
 * 5 - a in the same row): a clamp face at x = 3 dx with images behind it, as the
 * geometry builder makes them with clamp_face. */
static void mirror_columns(solid_particles *p)
{
    p->mirror = malloc((size_t)p->n * sizeof *p->mirror);
    for (int i = 0; i < p->n; i++) {
        const int a = test_index(p, i, 0);
        p->mirror[i] = -1;
        if (a < 3) {
            p->flags[i] |= SOLID_CLAMPED | SOLID_MIRRORED;
            p->mirror[i] = i + (5 - 2 * a);
        }
    }
}

static void check_mirrored_points(const char *kernel, int order)
{
    solid_particles *p = lattice();
    mirror_columns(p);
    const char *text = case_text(kernel, order, "saint_venant_kirchhoff", NULL);
    solid_model *m = test_model(text, p);
    fsi_case *c = test_case(text);
    material mat;
    char msg[512];
    CHECK(material_from_case(&mat, c, "solid", msg, sizeof msg) == 0, "material: %s", msg);
    fsi_case_free(c);
    finite_deformation(p);
    solid_follow_partners(p);
    double material_sum = 0.0, image_sum = 0.0;
    for (int i = 0; i < p->n; i++) {
        double f[FSI_MAT_SIZE], pk1[FSI_MAT_SIZE], w = 0.0;
        tlsph_deformation_gradient(m, p->x, i, f);
        CHECK(material_total_stress(&mat, f, pk1, NULL, &w, NULL) == 0, "W at point %d", i);
        if (p->flags[i] & SOLID_MIRRORED)
            image_sum += p->volume[i] * w;
        else
            material_sum += p->volume[i] * w;
    }
    const double energy = solid_model_strain_energy(m, p);
    /* The force, the images' handed to their partners (the main loop's chain rule),
     * against -dE/dx with the images following. */
    const size_t size = (size_t)p->n * FSI_DIM * sizeof(double);
    double *f = malloc(size), f_max;
    CHECK(test_force(m, p, p->x, f) == 0, "%s order %d: force with images failed", kernel,
          order);
    solid_mirror_forces(p, f);
    const double worst = energy_gradient_error(m, p, f, 16, &f_max);
    printf("%s, order %d, mirrored clamp points: energy %.12g J, the material points' sum "
           "V W(F) %.12g J (the images' F would store %.4g J more); |dE/dx + f| up to %.3g "
           "of the largest force\n", kernel, order, energy, material_sum, image_sum, worst);
    CHECK(fabs(energy - material_sum) <= 1e-12 * material_sum, "%s order %d: energy %.17g J, "
          "the material points' %.17g J", kernel, order, energy, material_sum);
    CHECK(image_sum > 1e-3 * material_sum, "%s order %d: the images' F stores nothing (%g J): "
          "the check above shows nothing", kernel, order, image_sum);
    CHECK(worst <= 1e-6, "%s order %d: with images, the force is not -dE/dx (%.3g of the "
          "largest force)", kernel, order, worst);
    free(f);
    solid_model_free(m);
    test_lattice_free(p);
}

int main(void)
{
    for (int k = 0; k < 2; k++) {
        for (int order = 1; order <= 2; order++) {
            check_reference_and_affine(KERNELS[k], order);
            check_energy_and_momentum(KERNELS[k], order);
            check_hourglass(KERNELS[k], order);
            check_mirrored_points(KERNELS[k], order);
        }
        check_quadratic(KERNELS[k]);
    }
    check_stateless();
    check_refusals();
    return unit_check_report("test_tlsph_model");
}
