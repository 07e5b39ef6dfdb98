/* The pseudo-spring SPH solid behind solid_model.h: creation (keys, links, cracks,
 * kernel), the stable step, the surface set, output fields, the energy and the
 * accessors of pseudo_spring.h. The internal force is in pseudo_spring_force.c. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "pseudo_spring_internal.h"
#include "pseudo_spring_keys.h"
#include "solid_model_setup.h"

static const char *const SECTION = "solid";

void solid_model_free(solid_model *m)
{
    if (!m)
        return;
    solid_bonds_free(&m->links);
    free(m->mass);
    free(m->density);
    free(m->density_next);
    free(m->stress);
    free(m->mstate);
    free(m->work);
    free(m->thickness_stretch);
    free(m->reverse);
    free(m->link_f);
    free(m->link_art);
    free(m->gather);
    free(m->art_r);
    free(m->hourglass);
    free(m->damage);
    free(m->initial_count);
    free(m->intact_count);
    free(m->flags);
    free(m->scratch);
    free(m);
}

/* Reads the model's keys (defaults as fallbacks: unit tests may pass unvalidated
 * cases; a validated case has had the key table's bounds checked with file and line).
 * Returns 0, or -1 with msg. */
static int read_keys(solid_model *m, const fsi_case *c, char *msg, size_t msg_size)
{
    const char *own = fsi_case_solver_section(c, SECTION);     /* [solid.pseudo_spring] */
    const double factor = fsi_case_get_real(c, own, "smoothing_length_factor",
                                            PSEUDO_SPRING_DEFAULT_H_FACTOR);
    m->visc_alpha = fsi_case_get_real(c, own, "artificial_viscosity_alpha",
                                      PSEUDO_SPRING_DEFAULT_VISC_ALPHA);
    m->visc_beta = fsi_case_get_real(c, own, "artificial_viscosity_beta",
                                     PSEUDO_SPRING_DEFAULT_VISC_BETA);
    m->art_stress = fsi_case_get_real(c, own, "artificial_stress",
                                      PSEUDO_SPRING_DEFAULT_ART_STRESS);
    m->art_exponent = fsi_case_get_real(c, own, "artificial_stress_exponent", 0.0);
    m->failure = fsi_case_get_bool(c, own, "failure", 0);
    m->failure_strain = fsi_case_get_real(c, own, "failure_strain",
                                          PSEUDO_SPRING_DEFAULT_FAILURE_STRAIN);
    m->courant = fsi_case_get_real(c, own, "courant_number", PSEUDO_SPRING_DEFAULT_COURANT);
    m->hg_coefficient = fsi_case_get_real(c, own, "hourglass_control",
                                          PSEUDO_SPRING_DEFAULT_HOURGLASS);
    if (!(factor >= 1.0 && factor <= 3.0) || !(m->visc_alpha >= 0.0) ||
        !(m->visc_beta >= 0.0) || !(m->art_stress >= 0.0) || !(m->art_exponent >= 0.0) ||
        !(m->failure_strain > 0.0) || !(m->courant > 0.0 && m->courant <= 1.0) ||
        !(m->hg_coefficient >= 0.0 && m->hg_coefficient <= 10.0)) {
        snprintf(msg, msg_size, "[solid.pseudo_spring] a key is out of range "
                 "(smoothing_length_factor %g, artificial_viscosity_alpha %g, beta %g, "
                 "artificial_stress %g, exponent %g, failure_strain %g, courant_number %g, "
                 "hourglass_control %g; docs/cases.md has the ranges)", factor, m->visc_alpha,
                 m->visc_beta, m->art_stress, m->art_exponent, m->failure_strain, m->courant,
                 m->hg_coefficient);
        return -1;
    }
    if (!m->failure)
        m->failure_strain = 0.0;
    if (wendland_c2_init(&m->kernel, factor * m->dx) != 0) {
        snprintf(msg, msg_size, "pseudo_spring: smoothing length %g m is not usable",
                 factor * m->dx);
        return -1;
    }
    double w0, wdx, f;
    wendland_c2_eval2(&m->kernel, 0.0, &w0, &f);
    wendland_c2_eval2(&m->kernel, m->dx * m->dx, &wdx, &f);
    m->w_dx = wdx;
    /* 004 §3, after Eq. 16: n = W(0) / W(dp) unless the case sets it. */
    if (m->art_exponent == 0.0)
        m->art_exponent = w0 / wdx;
    return 0;
}

solid_model *solid_model_create(const fsi_case *c, const solid_particles *p, char *msg,
                                size_t msg_size)
{
    solid_model *m = calloc(1, sizeof *m);
    if (!m) {
        snprintf(msg, msg_size, "pseudo_spring: out of memory creating the model");
        return NULL;
    }
    if (solid_model_setup(&m->mat, &m->dx, c, p, "pseudo_spring", msg, msg_size) != 0) {
        free(m);
        return NULL;
    }
    if (material_is_hyperelastic(&m->mat)) {
        /* Its stress is integrated from the Jaumann rate (004 Eq. 17): there is no
         * deformation gradient for a stress of F (materials/hyperelastic.c). */
        const char *at = fsi_case_origin(c, SECTION, "constitutive");
        snprintf(msg, msg_size,
                 "%s%s[%s] constitutive: %s is hyperelastic (a stress of the deformation "
                 "gradient); pseudo_spring has no deformation gradient; use linear_elastic",
                 at ? at : "", at ? ": " : "", SECTION, material_kind_name(m->mat.kind));
        free(m);
        return NULL;
    }
    m->n = p->n;
    if (read_keys(m, c, msg, msg_size) != 0) {
        free(m);
        return NULL;
    }
    /* 004 §3.2: the immediate neighbours of the lattice, within sqrt(DIM) dx. */
    const double reach = sqrt((double)FSI_DIM) * m->dx;
    if (solid_bonds_build(&m->links, p->x0, p->volume, p->n, reach, m->dx) != 0) {
        snprintf(msg, msg_size, "pseudo_spring: cannot build the links of %d points (out of "
                 "memory or a reference position is not finite)", p->n);
        free(m);
        return NULL;
    }
    m->full_count = solid_bonds_full_count(reach, m->dx);
    ps_hourglass_weights(m, p);
    const int n = p->n;
    m->reverse = solid_bonds_reverse(&m->links);
    if (!m->reverse)
        goto out_of_memory;     /* the rows are symmetric: no bond lacks its reverse */
    SOLID_ALLOC(m->link_f, m->links.n_bonds);
    if (m->art_stress > 0.0) {
        /* 004 Eq. 16 is on: R per point, P^a per link (else neither, and no pow). */
        SOLID_ALLOC(m->link_art, m->links.n_bonds);
        SOLID_ALLOC(m->art_r, n);
    }
    SOLID_ALLOC(m->mass, n);
    SOLID_ALLOC(m->density, n);
    SOLID_ALLOC(m->density_next, n);
    SOLID_ALLOC(m->stress, (int64_t)n * 6);
    SOLID_ALLOC(m->mstate, n);
    SOLID_ALLOC(m->work, n);
    SOLID_ALLOC(m->thickness_stretch, n);
    SOLID_ALLOC(m->gather, (int64_t)n * FSI_MAT_SIZE);
    SOLID_ALLOC(m->hourglass, (int64_t)n * PS_HOURGLASS_STRIDE);
    SOLID_ALLOC(m->damage, n);
    SOLID_ALLOC(m->initial_count, n);
    SOLID_ALLOC(m->intact_count, n);
    SOLID_ALLOC(m->flags, n);
    SOLID_ALLOC(m->scratch, (int64_t)n * FSI_MAT_SIZE);
    for (int i = 0; i < n; i++) {
        m->initial_count[i] = (int32_t)(m->links.offset[i + 1] - m->links.offset[i]);
        m->mass[i] = p->density[i] * p->volume[i];
        m->density[i] = m->density_next[i] = p->density[i];
        m->thickness_stretch[i] = 1.0;
        if (p->flags[i] & SOLID_MIRRORED)
            m->flags[i] |= PS_POINT_GHOST;
    }
    /* Links across a [solid.crack] start broken (and count as failed in D_i). */
    if (solid_bonds_cut_cracks(&m->links, c, SECTION, p->x0, "pseudo_spring", msg, msg_size) !=
        0) {
        solid_model_free(m);
        return NULL;
    }
    double c_max = 0.0;
    const double modulus = material_wave_modulus(&m->mat);
    for (int i = 0; i < n; i++) {
        ps_count_links(m, i);
        c_max = fmax(c_max, sqrt(modulus / p->density[i]));
    }
    m->sound_speed = c_max;
    return m;

out_of_memory:
    snprintf(msg, msg_size, "pseudo_spring: out of memory for the state of %d points", p->n);
    solid_model_free(m);
    return NULL;
}

/* The SPH solid's CFL condition dt = C h / (c + |v|max) (Monaghan 1992 without the
 * viscous term, which is small for elastic solids), c = sqrt(M / rho) the P-wave
 * speed, M = K + 4 G / 3 (or its plane-stress form, material_wave_modulus); never
 * above the lattice bound dx / c that solid_step_check.c estimates from.
 * After failure: a point left with n of its n0 lattice links carries its whole mass
 * on fewer links, each weighted up by the correction B = A^-1 (Eq. 20, A summed over
 * the intact links), so its stiffness grows as about n0 / n and its frequency as
 * sqrt(n0 / n). The step shrinks by sqrt(n / n0) of the worst such point (detached
 * points interact with nothing and do not count); the factor is 1 while no link is
 * broken or cut. C6 at dx = 2.5 mm went unstable without it when an edge point fell
 * to 1 of its 5 links (docs/pseudo_spring.md, "Stable step"). */
double solid_model_stable_dt(const solid_model *m, const solid_particles *p)
{
    double v2 = 0.0, link_ratio = 1.0;
    for (int i = 0; i < p->n; i++) {
        double s = 0.0;
        for (int d = 0; d < FSI_DIM; d++)
            s += p->v[i * FSI_DIM + d] * p->v[i * FSI_DIM + d];
        v2 = fmax(v2, s);
        if (m->intact_count[i] > 0 && m->intact_count[i] < m->initial_count[i])
            link_ratio = fmin(link_ratio, (double)m->intact_count[i] / m->initial_count[i]);
    }
    const double c = m->sound_speed;
    return sqrt(link_ratio) * fmin(m->courant * m->kernel.h / (c + sqrt(v2)), m->dx / c);
}

int solid_model_surface(const solid_model *m, const solid_particles *p, uint8_t *surface)
{
    int count = 0;
    for (int i = 0; i < p->n; i++) {
        /* Mirrored clamp points are not material: the fluid never meets them. */
        surface[i] = m->intact_count[i] < m->full_count && !(m->flags[i] & PS_POINT_GHOST);
        count += surface[i];
    }
    return count;
}

int solid_model_write_fields(const solid_model *m, fsi_h5_writer *out)
{
    const int n = m->n;
    double *buf = m->scratch;
    for (int i = 0; i < n; i++)
        fsi_sym6_to_mat(m->stress + (int64_t)i * 6, buf + (int64_t)i * FSI_MAT_SIZE);
    if (fsi_h5_write_field_real(out, "stress", buf, FSI_MAT_SIZE) != 0)
        return -1;
    if (fsi_h5_write_field_real(out, "damage", m->damage, 1) != 0)
        return -1;
    if (fsi_h5_write_field_real(out, "current_density", m->density, 1) != 0)
        return -1;
    for (int i = 0; i < n; i++)
        buf[i] = m->mstate[i].equivalent_plastic_strain;
    if (fsi_h5_write_field_real(out, "equivalent_plastic_strain", buf, 1) != 0)
        return -1;
    if (fsi_h5_write_field_int(out, "intact_links", m->intact_count, 1) != 0)
        return -1;
    return 0;
}

/* Sum over points of V0_i w_i, w_i the stress work per reference volume accumulated
 * by the objective update (= sigma : eps / 2 for linear elasticity; with plasticity
 * it includes the dissipated plastic work), plus the hourglass control's energy of
 * the current positions (pseudo_spring_hourglass.c). Mirrored clamp points store
 * nothing (they are images: w = 0, no hourglass energy); their positions enter the
 * material points' terms, and the main loop hands their forces to the partners (the
 * chain rule), so this is what the internal forces exchange with the kinetic energy.
 * In index order (independent of the thread count). */
double solid_model_strain_energy(const solid_model *m, const solid_particles *p)
{
    double total = 0.0;
    for (int i = 0; i < m->n; i++)
        total += p->volume[i] * m->work[i] + ps_hourglass_energy(m, p, i);
    return total;
}

int64_t solid_model_interaction_count(const solid_model *m)
{
    return m->links.n_bonds;
}

const solid_bonds *pseudo_spring_links(const solid_model *m)
{
    return &m->links;
}

int64_t pseudo_spring_broken_links(const solid_model *m)
{
    return m->n_broken;
}

int pseudo_spring_full_count(const solid_model *m)
{
    return m->full_count;
}

double *pseudo_spring_stress(solid_model *m)
{
    return m->stress;
}

int solid_model_describe_fields(fsi_h5_writer *out)
{
    static const fsi_h5_field_info info[] = {
        {"damage", "1", "Broken links over the links the point had at the start (0 intact, "
                        "1 fully separated)."},
        {"current_density", "kg/m^3", "Current density of the continuity equation "
                                      "(004 Eq. 14); the same as density."},
        {"equivalent_plastic_strain", "1", "Accumulated equivalent plastic strain "
                                           "sqrt(2/3 e_p : e_p)."},
        {"intact_links", "1", "Number of the point's links not broken."},
    };
    return fsi_h5_describe_fields(out, info, (int)(sizeof info / sizeof info[0]));
}

double solid_model_smoothing_length(const solid_model *m)
{
    return m->kernel.h;
}

/* The continuity equation's current density (004 Eq. 14), which the sums use. */
const double *solid_model_density(const solid_model *m, const solid_particles *p)
{
    (void)p;
    return m->density;
}

const double *pseudo_spring_damage(const solid_model *m)
{
    return m->damage;
}

const int32_t *pseudo_spring_intact_count(const solid_model *m)
{
    return m->intact_count;
}

const int32_t *pseudo_spring_initial_count(const solid_model *m)
{
    return m->initial_count;
}

/* Every call commits the stress and density updates and broken links: no trial
 * evaluations (solid_model.h). */
int solid_model_stateless(const solid_model *m)
{
    (void)m;
    return 0;
}
