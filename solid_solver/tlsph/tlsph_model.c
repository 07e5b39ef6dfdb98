/* The TLSPH solid behind solid_model.h: creation (keys, reference families, the
 * corrected reference gradients of 003 Eqs. 35-36), the stable step, the surface set,
 * output fields, the energy and the accessors of tlsph.h. The internal force is in
 * tlsph_force.c, the hourglass control in tlsph_hourglass.c. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cubic_spline.h"
#include "particle_health.h"
#include "solid_point_text.h"
#include "solid_model_setup.h"
#include "tlsph_internal.h"
#include "tlsph_keys.h"
#include "wendland_c2.h"

static const char *const SECTION = "solid";

void solid_model_free(solid_model *m)
{
    if (!m)
        return;
    solid_bonds_free(&m->family);
    free(m->reverse);
    free(m->grad);
    free(m->kernel_w);
    free(m->ghost);
    free(m->pk1);
    free(m->defgrad);
    free(m->grad_sum);
    free(m);
}

typedef struct {
    int wendland;
    cubic_spline_kernel cubic;
    wendland_c2_kernel wendland_c2;
} reference_kernel;

/* W and F = (dW/dr) / r of the chosen kernel at squared distance r2. */
static void kernel_eval(const reference_kernel *k, double r2, double *w, double *f)
{
    if (k->wendland)
        wendland_c2_eval2(&k->wendland_c2, r2, w, f);
    else
        cubic_spline_eval2(&k->cubic, r2, w, f);
}

/* Reads the model's keys (defaults as fallbacks: unit tests may pass unvalidated
 * cases; a validated case has had the key table's bounds checked with file and line).
 * Returns 0, or -1 with msg. */
static int read_keys(solid_model *m, reference_kernel *k, const fsi_case *c, char *msg,
                     size_t msg_size)
{
    const char *own = fsi_case_solver_section(c, SECTION); /* [solid.tlsph] */
    const char *kind = fsi_case_get(c, own, "kernel");
    const double factor =
        fsi_case_get_real(c, own, "smoothing_length_factor", TLSPH_DEFAULT_H_FACTOR);
    m->courant = fsi_case_get_real(c, own, "courant_number", TLSPH_DEFAULT_COURANT);
    m->hg_alpha = fsi_case_get_real(c, own, "hourglass_control", TLSPH_DEFAULT_HOURGLASS);
    m->gradient_order = (int)fsi_case_get_real(c, own, "gradient_order",
                                               TLSPH_DEFAULT_GRADIENT_ORDER);
    k->wendland = kind && strcmp(kind, "wendland_c2") == 0;
    if ((kind && !k->wendland && strcmp(kind, "cubic_spline") != 0) ||
        !(factor >= 1.0 && factor <= 3.0) || !(m->courant > 0.0 && m->courant <= 1.0) ||
        !(m->hg_alpha >= 0.0 && m->hg_alpha <= 100.0) ||
        !(m->gradient_order == 1 || m->gradient_order == 2)) {
        snprintf(msg, msg_size, "[solid.tlsph] a key is out of range (kernel %s, "
                 "smoothing_length_factor %g, courant_number %g, hourglass_control %g, "
                 "gradient_order %d; docs/cases.md has the ranges)",
                 kind ? kind : "(default)", factor, m->courant, m->hg_alpha,
                 m->gradient_order);
        return -1;
    }
    m->h = factor * m->dx;
    const int rc = k->wendland ? wendland_c2_init(&k->wendland_c2, m->h)
                               : cubic_spline_init(&k->cubic, m->h);
    if (rc != 0) {
        snprintf(msg, msg_size, "tlsph: smoothing length %g m is not usable", m->h);
        return -1;
    }
    return 0;
}

/* 003 Eq. 35 for point i: K_i = sum_J V_J (X_J - X_i) (x) grad_0 W_iJ, and the
 * corrected gradients g_iJ = K_i^-T grad_0 W_iJ of its family, for which
 * sum_J V_J (X_J - X_i) (x) g_iJ = K_i K_i^-1 = I: F = I exactly in the reference
 * configuration (Eq. 36), and every linear field's gradient is exact. (003 writes
 * K_a^-1 grad W with K in the order of Eq. 35; the transpose is what makes Eq. 36
 * reproduce F = I. Since grad_0 W_iJ = omega xi with omega = -(dW/dr) / r >= 0 and
 * xi = X_J - X_i, K_i = sum V omega xi xi^T is symmetric and g_iJ = K^-1 omega xi: the
 * gradient of the weighted least-squares linear fit of the family's motion.)
 * gradient_order = 2 fits the quadratic monomials too (solid_fit.h, weights omega V):
 * g_iJ = the first FSI_DIM rows of A_i^-1 omega b(xi), A_i = sum V omega b b^T. It
 * still gives F = I at rest and exact linear gradients, and also exact gradients of
 * quadratic fields where the family is one-sided (near a surface, where bending puts
 * the largest strains); a family that cannot carry the quadratic fit keeps the linear
 * one. Returns 0, or -1 when K_i is singular or ill-conditioned. */
static int shape_point(solid_model *m, const reference_kernel *k, int i)
{
    const solid_bonds *b = &m->family;
    double kmat[FSI_MAT_SIZE], kinv[FSI_MAT_SIZE];
    double a[SOLID_FIT_MAX_BASIS * SOLID_FIT_MAX_BASIS] = {0};
    double a_inv[SOLID_FIT_MAX_BASIS * SOLID_FIT_MAX_BASIS];
    const int nb = m->gradient_order == 2 ? SOLID_FIT_MAX_BASIS : FSI_DIM;
    const double inv_support = 1.0 / (2.0 * m->h);
    fsi_mat_zero(kmat);
    for (int64_t q = b->offset[i]; q < b->offset[i + 1]; q++) {
        const double *xi = b->xi + q * FSI_DIM;        /* X_J - X_i */
        double w, f, basis[SOLID_FIT_MAX_BASIS];
        kernel_eval(k, b->length[q] * b->length[q], &w, &f);
        m->kernel_w[q] = w;
        m->grad[q * FSI_DIM] = -f;                     /* omega, for the pass below */
        fsi_mat_add_outer(kmat, -f * b->weight[q], xi, xi);
        solid_fit_basis(xi, inv_support, nb, basis);
        for (int r = 0; r < nb; r++)
            for (int c = 0; c < nb; c++)
                a[r * nb + c] += -f * b->weight[q] * basis[r] * basis[c];
    }
    if (fsi_mat_inverse(kmat, kinv, TLSPH_MAX_CONDITION_K) != 0)
        return -1;
    const int quadratic =
        nb > FSI_DIM && solid_fit_inverse(a, nb, a_inv, TLSPH_MAX_CONDITION_FIT) == 0;
    m->linear_fit_points += nb > FSI_DIM && !quadratic;
    for (int64_t q = b->offset[i]; q < b->offset[i + 1]; q++) {
        const double *xi = b->xi + q * FSI_DIM;
        const double omega = m->grad[q * FSI_DIM];
        double g[FSI_DIM], basis[SOLID_FIT_MAX_BASIS];
        solid_fit_basis(xi, inv_support, nb, basis);
        for (int r = 0; r < FSI_DIM; r++) {
            g[r] = 0.0;
            if (quadratic)
                for (int s = 0; s < nb; s++)
                    g[r] += a_inv[r * nb + s] * omega * basis[s];
            else
                for (int s = 0; s < FSI_DIM; s++)
                    g[r] += FSI_MAT(kinv, r, s) * omega * xi[s];
        }
        memcpy(m->grad + q * FSI_DIM, g, sizeof g);
        for (int d = 0; d < FSI_DIM; d++)
            m->grad_sum[(int64_t)i * FSI_DIM + d] += b->weight[q] * g[d];
    }
    return 0;
}

solid_model *solid_model_create(const fsi_case *c, const solid_particles *p, char *msg,
                                size_t msg_size)
{
    solid_model *m = calloc(1, sizeof *m);
    if (!m) {
        snprintf(msg, msg_size, "tlsph: out of memory creating the model");
        return NULL;
    }
    if (solid_model_setup(&m->mat, &m->dx, c, p, "tlsph", msg, msg_size) != 0) {
        free(m);
        return NULL;
    }
    if (m->mat.kind == MATERIAL_DRUCKER_PRAGER) {
        snprintf(msg, msg_size, "[solid] constitutive: tlsph takes the total-form materials "
                 "(linear_elastic, saint_venant_kirchhoff, neo_hookean), not drucker_prager, "
                 "whose plastic flow needs an incremental update");
        free(m);
        return NULL;
    }
    m->n = p->n;
    reference_kernel k;
    if (read_keys(m, &k, c, msg, msg_size) != 0) {
        free(m);
        return NULL;
    }
    /* Every point within the support 2 h of the reference configuration. */
    const double reach = 2.0 * m->h * (1.0 - 1e-9);
    if (solid_bonds_build(&m->family, p->x0, p->volume, p->n, reach, m->dx) != 0) {
        snprintf(msg, msg_size, "tlsph: cannot build the families of %d points (out of "
                 "memory or a reference position is not finite)", p->n);
        free(m);
        return NULL;
    }
    m->full_count = solid_bonds_full_count(reach, m->dx);
    const int n = p->n;
    m->reverse = solid_bonds_reverse(&m->family);
    if (!m->reverse)
        goto out_of_memory;
    SOLID_ALLOC(m->grad, m->family.n_bonds * FSI_DIM);
    SOLID_ALLOC(m->kernel_w, m->family.n_bonds);
    SOLID_ALLOC(m->ghost, n);
    SOLID_ALLOC(m->pk1, (int64_t)n * FSI_MAT_SIZE);
    SOLID_ALLOC(m->defgrad, (int64_t)n * FSI_MAT_SIZE);
    SOLID_ALLOC(m->grad_sum, (int64_t)n * FSI_DIM);
    double c_max = 0.0;
    const double modulus = material_wave_modulus(&m->mat);
    for (int i = 0; i < n; i++) {
        m->ghost[i] = (p->flags[i] & SOLID_MIRRORED) != 0;
        fsi_mat_identity(m->defgrad + (int64_t)i * FSI_MAT_SIZE);
        c_max = fmax(c_max, sqrt(modulus / p->density[i]));
        if (shape_point(m, &k, i) != 0) {
            char where[160];
            solid_describe_point(p, i, where, sizeof where);
            snprintf(msg, msg_size, "tlsph: the shape matrix (003 Eq. 35) of %s is singular "
                     "or ill-conditioned (%d neighbours within 2 h = %g m): its neighbours "
                     "nearly lie on a %s; a body needs at least two points across with "
                     "h >= dx", where, (int)(m->family.offset[i + 1] - m->family.offset[i]),
                     2.0 * m->h, FSI_DIM == 2 ? "line" : "plane");
            solid_model_free(m);
            return NULL;
        }
    }
    m->sound_speed = c_max;
    if (m->linear_fit_points > 0)
        fprintf(stderr, "tlsph: %d points keep the linear fit (their family cannot carry "
                "the quadratic one of gradient_order = 2)\n", m->linear_fit_points);
    return m;

out_of_memory:
    snprintf(msg, msg_size, "tlsph: out of memory for the state of %d points", p->n);
    solid_model_free(m);
    return NULL;
}

/* The SPH solid's CFL condition dt = C h / (c + |v|max) (Monaghan 1992 without the
 * viscous term), c = sqrt(M / rho) the P-wave speed of the reference state; never
 * above the lattice bound dx / c that solid_step_check.c estimates from. */
double solid_model_stable_dt(const solid_model *m, const solid_particles *p)
{
    double speed;
    fsi_fastest(p->v, p->n, &speed);
    const double c = m->sound_speed;
    return fmin(m->courant * m->h / (c + speed), m->dx / c);
}

/* The internal force is a function of the positions alone (total Lagrangian, a
 * total-form material, fixed families): nothing is committed per call, so a
 * multi-stage integrator may evaluate it at trial states. */
int solid_model_stateless(const solid_model *m)
{
    (void)m;
    return 1;
}

int solid_model_surface(const solid_model *m, const solid_particles *p, uint8_t *surface)
{
    int count = 0;
    for (int i = 0; i < p->n; i++) {
        const int members = (int)(m->family.offset[i + 1] - m->family.offset[i]);
        surface[i] = members < m->full_count && !m->ghost[i];
        count += surface[i];
    }
    return count;
}

/* The Cauchy stress and det F of the last evaluation (the current state: every
 * integrator's last evaluation is at the step's end), from its F. */
int solid_model_write_fields(const solid_model *m, fsi_h5_writer *out)
{
    const int n = m->n;
    double *sigma = malloc((size_t)n * FSI_MAT_SIZE * sizeof *sigma);
    double *jac = malloc((size_t)n * sizeof *jac);
    int rc = -1;
    if (sigma && jac) {
        for (int i = 0; i < n; i++) {
            const double *f = m->defgrad + (int64_t)i * FSI_MAT_SIZE;
            double pk1[FSI_MAT_SIZE], s6[6] = {0};
            if (!m->ghost[i])
                material_total_stress(&m->mat, f, pk1, s6, NULL, NULL);
            fsi_sym6_to_mat(s6, sigma + (int64_t)i * FSI_MAT_SIZE);
            jac[i] = fsi_mat_det(f);
        }
        rc = fsi_h5_write_field_real(out, "stress", sigma, FSI_MAT_SIZE) != 0 ||
                     fsi_h5_write_field_real(out, "jacobian", jac, 1) != 0
                 ? -1
                 : 0;
    }
    free(sigma);
    free(jac);
    return rc;
}

/* Sum over material points of V0_i W(F_i) at the current positions, F_i of Eq. 36
 * (mirrored clamp points are images and store nothing). For the hyperelastic
 * materials this is the energy whose derivative the internal force is (less the
 * hourglass control's pair forces, which are not derived from an energy); for
 * linear_elastic (003's Hooke law on the Almansi strain) it is the small-strain
 * energy, exact to second order. In index order (independent of the thread count). */
double solid_model_strain_energy(const solid_model *m, const solid_particles *p)
{
    double total = 0.0;
    for (int i = 0; i < m->n; i++) {
        double w;
        if (m->ghost[i])
            continue;
        if (tlsph_point_response(m, p->x, i, &w, NULL) != 0)
            return INFINITY;    /* an inverted point: the energy check stops the run */
        total += p->volume[i] * w;
    }
    return total;
}

int64_t solid_model_interaction_count(const solid_model *m)
{
    return m->family.n_bonds;
}

int solid_model_describe_fields(fsi_h5_writer *out)
{
    static const fsi_h5_field_info info[] = {
        {"jacobian", "1", "det F, the ratio of current to reference volume."},
    };
    return fsi_h5_describe_fields(out, info, (int)(sizeof info / sizeof info[0]));
}

double solid_model_smoothing_length(const solid_model *m)
{
    return m->h;
}

/* Total Lagrangian: the reference density (solid_model.h). */
const double *solid_model_density(const solid_model *m, const solid_particles *p)
{
    (void)m;
    return p->density;
}

const solid_bonds *tlsph_families(const solid_model *m)
{
    return &m->family;
}
