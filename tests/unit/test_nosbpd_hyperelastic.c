/* NOSB-PD with the hyperelastic materials (total form, material_total_stress):
 *  - a homogeneous finite deformation x = F X (rotation and 15-20 % stretches):
 *    every point's F and Cauchy stress are the material's at that F, and the strain
 *    energy is sum V W(F) (the zero-energy control stores nothing for an affine
 *    motion), to round-off (1e-12: F = N A^-1 is exact for affine motions up to a few
 *    1e-16, and W, sigma depend smoothly on F);
 *  - the internal force is minus the gradient of the strain energy: central
 *    differences of solid_model_strain_energy in single coordinates at a random
 *    finite displacement field match -f to 1e-6 of the largest force (the step
 *    1e-6 dx gives truncation ~1e-12 and cancellation ~1e-16 E / h ~1e-9 of it), so
 *    the energy check of the main loop (kinetic + this energy) holds for these
 *    materials. A force or an energy of the wrong material, a W per current instead
 *    of reference volume, or a stabilisation energy that does not match its force
 *    fails by the size of the strain (1e-2).
 * For SVK and neo-Hookean, in plane strain and plane stress (2D) or 3D, with the
 * default gradient order and with the linear one. */
#include "test_nosbpd_common.h"

#include "material.h"

static const char *const KINDS[] = {"saint_venant_kirchhoff", "neo_hookean"};

static const char *case_text(const char *kind, const char *plane, int order)
{
    static char text[512];
    snprintf(text, sizeof text,
             "[solid]\nsolver = nosbpd\ndensity = 1000\nyoungs_modulus = 1e6\n"
             "poisson_ratio = 0.35\nplane = %s\nconstitutive = %s\n"
             "[solid.nosbpd]\ngradient_order = %d\n",
             plane, kind, order);
    return text;
}

static material material_of(const char *text)
{
    fsi_case *c = test_case(text);
    material mat;
    char msg[512];
    CHECK(material_from_case(&mat, c, "solid", msg, sizeof msg) == 0, "material: %s", msg);
    fsi_case_free(c);
    return mat;
}

static void check_homogeneous(const char *kind, const char *plane, int order)
{
    const double dx = 0.01;
    solid_particles *p = test_lattice(14, 12, 8, dx, 1000.0);
    const char *text = case_text(kind, plane, order);
    solid_model *m = test_model(text, p);
    const material mat = material_of(text);
    /* F = Q U: U a symmetric stretch, Q a rotation by 0.7 rad (about z in 3D). */
    double f[FSI_MAT_SIZE], q[FSI_MAT_SIZE], u[FSI_MAT_SIZE];
    fsi_mat_identity(q);
    fsi_mat_identity(u);
    q[0] = cos(0.7);
    FSI_MAT(q, 0, 1) = -sin(0.7);
    FSI_MAT(q, 1, 0) = sin(0.7);
    FSI_MAT(q, 1, 1) = cos(0.7);
    u[0] = 1.2;
    FSI_MAT(u, 1, 1) = 0.85;
    FSI_MAT(u, 0, 1) = FSI_MAT(u, 1, 0) = 0.1;
    fsi_mat_mul(q, u, f);
    double *x_prev = malloc((size_t)p->n * FSI_DIM * sizeof *x_prev);
    double *force = malloc((size_t)p->n * FSI_DIM * sizeof *force);
    memcpy(x_prev, p->x, (size_t)p->n * FSI_DIM * sizeof *x_prev);
    for (int i = 0; i < p->n; i++)
        fsi_mat_vec(f, p->x0 + (size_t)i * FSI_DIM, p->x + (size_t)i * FSI_DIM);
    CHECK(test_force(m, p, x_prev, force) == 0, "%s %s: homogeneous step failed", kind, plane);

    double pk1[FSI_MAT_SIZE], sigma[6], w = 0.0, volume = 0.0;
    CHECK(material_total_stress(&mat, f, pk1, sigma, &w, NULL) == 0, "material at F");
    const double scale = fmax(fabs(sigma[0]), fabs(sigma[1]));
    const double *defgrad = nosbpd_deformation_gradient(m);
    const double *stress = nosbpd_stress(m);
    double worst_f = 0.0, worst_s = 0.0;
    for (int i = 0; i < p->n; i++) {
        volume += p->volume[i];
        for (int k = 0; k < FSI_MAT_SIZE; k++)
            worst_f = fmax(worst_f, fabs(defgrad[(size_t)i * FSI_MAT_SIZE + k] - f[k]));
        for (int k = 0; k < 6; k++)
            worst_s = fmax(worst_s, fabs(stress[(size_t)i * 6 + k] - sigma[k]));
    }
    const double energy = solid_model_strain_energy(m, p);
    CHECK(worst_f <= 1e-12 && worst_s <= 1e-12 * scale,
          "%s %s order %d: F off by %.3g, stress off the material's by %.3g of %.3g", kind,
          plane, order, worst_f, worst_s, scale);
    CHECK(fabs(energy - volume * w) <= 1e-12 * volume * w,
          "%s %s order %d: strain energy %.17g, sum V W(F) %.17g", kind, plane, order, energy,
          volume * w);
    free(x_prev);
    free(force);
    solid_model_free(m);
    test_lattice_free(p);
}

static void check_energy_gradient(const char *kind, const char *plane, int order)
{
    const double dx = 0.01, h = 1e-6 * dx;
    solid_particles *p = test_lattice(10, 9, 7, dx, 1000.0);
    solid_model *m = test_model(case_text(kind, plane, order), p);
    const size_t size = (size_t)p->n * FSI_DIM * sizeof(double);
    double *x_prev = malloc(size), *force = malloc(size), *scratch = malloc(size);
    memcpy(x_prev, p->x, size);
    /* A smooth stretch and shear (about 10 %) plus a random part (about 1 %). */
    for (int i = 0; i < p->n; i++) {
        double *x = p->x + (size_t)i * FSI_DIM;
        const double *x0 = p->x0 + (size_t)i * FSI_DIM;
        x[0] += 0.1 * x0[0] + 0.05 * x0[1] + 0.01 * dx * (test_uniform() - 0.5);
        x[1] += -0.05 * x0[1] + 2.0 * x0[0] * x0[0] + 0.01 * dx * (test_uniform() - 0.5);
    }
    CHECK(test_force(m, p, x_prev, force) == 0, "%s %s: step failed", kind, plane);
    double f_max = 0.0;
    for (int k = 0; k < p->n * FSI_DIM; k++)
        f_max = fmax(f_max, fabs(force[k]));
    double worst = 0.0;
    for (int trial = 0; trial < 12; trial++) {
        const int k = (int)(test_uniform() * p->n * FSI_DIM);
        const double x_k = p->x[k];
        double e[2];
        for (int s = 0; s < 2; s++) {
            p->x[k] = x_k + (s ? -h : h);
            CHECK(test_force(m, p, x_prev, scratch) == 0, "perturbed step failed");
            e[s] = solid_model_strain_energy(m, p);
        }
        p->x[k] = x_k;
        worst = fmax(worst, fabs((e[0] - e[1]) / (2.0 * h) + force[k]));
    }
    CHECK(f_max > 0.0 && worst <= 1e-6 * f_max,
          "%s %s order %d: |dE/dx + f| = %.3g of the largest force %.3g", kind, plane, order,
          worst, f_max);
    free(x_prev);
    free(force);
    free(scratch);
    solid_model_free(m);
    test_lattice_free(p);
}

int main(void)
{
    static const char *const planes[] = {"strain", "stress"};
    for (int k = 0; k < 2; k++)
        for (int pl = 0; pl < (FSI_DIM == 2 ? 2 : 1); pl++)
            for (int order = 1; order <= 2; order++) {
                check_homogeneous(KINDS[k], planes[pl], order);
                check_energy_gradient(KINDS[k], planes[pl], order);
            }
    return unit_check_report("test_nosbpd_hyperelastic");
}
