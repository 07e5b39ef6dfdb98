/* The NOSB-PD model behind solid_model.h: creation (keys, bonds, reference shape
 * tensors, stable step), the surface set, output fields, the energy, and the
 * accessors of nosbpd.h. The internal force is in nosbpd_force.c. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "geometry.h"
#include "nosbpd_failure.h"
#include "nosbpd_internal.h"
#include "nosbpd_keys.h"
#include "nosbpd_stabilisation.h"
#include "solid_model_setup.h"

static const char *const SECTION = "solid";

#if FSI_DIM == 2
#define FAMILY_TOO_POOR                                                                   \
    "its family is too poor for a shape tensor (fewer than 3 bonds, or all nearly on a line)"
#else
#define FAMILY_TOO_POOR                                                                   \
    "its family is too poor for a shape tensor (fewer than 4 bonds, or all nearly on a plane)"
#endif

void solid_model_free(solid_model *m)
{
    if (!m)
        return;
    solid_bonds_free(&m->bonds);
    free(m->k_inv);
    free(m->moment_inv);
    free(m->fit);
    free(m->defgrad);
    free(m->gather);
    free(m->stress);
    free(m->mstate);
    free(m->work);
    free(m->thickness_stretch);
    free(m->family_volume);
    free(m->damage);
    free(m->intact_count);
    free(m->flags);
    free(m->scratch);
    free(m->iscratch);
    free(m);
}

/* Reads the model's keys (defaults as fallbacks: unit tests may pass unvalidated
 * cases). Returns 0, or -1 with msg. */
static int read_keys(solid_model *m, const fsi_case *c, char *msg, size_t msg_size)
{
    const char *own = fsi_case_solver_section(c, SECTION);     /* [solid.nosbpd] */
    const double factor =
        fsi_case_get_real(c, own, "horizon_factor", NOSBPD_DEFAULT_HORIZON_FACTOR);
    if (!(factor >= 1.0 && factor <= 10.0)) {
        snprintf(msg, msg_size, "[solid.nosbpd] horizon_factor = %g: needs 1 <= m <= 10", factor);
        return -1;
    }
    m->delta = factor * m->dx;
    const char *inf = fsi_case_get(c, own, "influence_function");
    if (nosbpd_influence_parse(inf ? inf : NOSBPD_DEFAULT_INFLUENCE, &m->influence) != 0) {
        snprintf(msg, msg_size, "[solid.nosbpd] influence_function = %s: needs one, inverse or "
                 "gaussian", inf);
        return -1;
    }
    m->gradient_order = (int)fsi_case_get_int(c, own, "gradient_order",
                                              NOSBPD_DEFAULT_GRADIENT_ORDER);
    if (m->gradient_order != 1 && m->gradient_order != 2) {
        snprintf(msg, msg_size, "[solid.nosbpd] gradient_order = %d: needs 1 or 2",
                 m->gradient_order);
        return -1;
    }
    m->n_basis = m->gradient_order == 1 ? FSI_DIM : NOSBPD_MAX_BASIS;
    m->gather_stride = FSI_DIM * m->n_basis + 1;
    m->zero_energy_coefficient = fsi_case_get_real(c, own, "zero_energy_coefficient",
                                                   NOSBPD_DEFAULT_ZERO_ENERGY_COEFFICIENT);
    if (!(m->zero_energy_coefficient >= 0.0 && m->zero_energy_coefficient <= 10.0)) {
        snprintf(msg, msg_size, "[solid.nosbpd] zero_energy_coefficient = %g: needs 0 <= G <= 10",
                 m->zero_energy_coefficient);
        return -1;
    }
    m->failure = fsi_case_get_bool(c, own, "failure", 0);
    const double s0 = fsi_case_get_real(c, own, "critical_stretch", 0.0);
    const double g0 = fsi_case_get_real(c, own, "fracture_energy", 0.0);
    if (!(s0 >= 0.0) || !(g0 >= 0.0)) {
        snprintf(msg, msg_size, "[solid.nosbpd] critical_stretch = %g, fracture_energy = %g: "
                 "neither may be negative", s0, g0);
        return -1;
    }
    m->critical_stretch = 0.0;
    if (m->failure) {
        /* critical_stretch wins when both are given. */
        m->critical_stretch =
            s0 > 0.0 ? s0 : nosbpd_critical_stretch_from_energy(&m->mat, g0, m->delta);
        if (!(m->critical_stretch > 0.0) || !isfinite(m->critical_stretch)) {
            snprintf(msg, msg_size, "[solid.nosbpd] failure = true needs critical_stretch > 0 or "
                     "fracture_energy > 0");
            return -1;
        }
    }
    return 0;
}

/* Silling & Askari 2005 bound dt < sqrt(2 rho / sum_J V_J C_IJ), with the bond
 * stiffness C_IJ = c / |xi| of the bond-based material of the same bulk modulus
 * (standing in for the correspondence force state) plus 2 G C_w omega of the
 * stabilisation (d(T_s,I - T_s,J)/dY = 2 G C_w omega), over the reference
 * families; and the lattice bound dx / c_p, c_p = sqrt(M / rho). The smaller one. */
static double stable_step(const solid_model *m, const solid_particles *p)
{
    const double c = nosbpd_micromodulus(&m->mat, m->delta);
    const nosbpd_bonds *b = &m->bonds;
    double dt = INFINITY;
    for (int i = 0; i < m->n; i++) {
        double stiffness = 0.0;
        for (int64_t q = b->offset[i]; q < b->offset[i + 1]; q++) {
            const double vj = p->volume[b->neighbour[q]];
            stiffness += vj * c / b->length[q] + 2.0 * m->stab_modulus * b->weight[q];
        }
        const double rho = p->density ? p->density[i] : m->mat.density;
        if (stiffness > 0.0)
            dt = fmin(dt, sqrt(2.0 * rho / stiffness));
        dt = fmin(dt, material_wave_crossing_time(&m->mat, rho, m->dx));
    }
    return dt;
}

solid_model *solid_model_create(const fsi_case *c, const solid_particles *p, char *msg,
                                size_t msg_size)
{
    solid_model *m = calloc(1, sizeof *m);
    if (!m) {
        snprintf(msg, msg_size, "nosbpd: out of memory creating the model");
        return NULL;
    }
    if (solid_model_setup(&m->mat, &m->dx, c, p, "nosbpd", msg, msg_size) != 0) {
        free(m);
        return NULL;
    }
    m->n = p->n;
    if (read_keys(m, c, msg, msg_size) != 0) {
        free(m);
        return NULL;
    }
    if (nosbpd_bonds_build(&m->bonds, p->x0, p->volume, p->n, m->delta, m->dx,
                           m->influence) != 0) {
        snprintf(msg, msg_size, "nosbpd: cannot build the bonds of %d points (out of memory "
                 "or a reference position is not finite)", p->n);
        free(m);
        return NULL;
    }
    if (solid_bonds_cut_cracks(&m->bonds, c, SECTION, p->x0, "nosbpd", msg, msg_size) !=
        0) {
        solid_bonds_free(&m->bonds);
        free(m);
        return NULL;
    }
    const int n = p->n;
    SOLID_ALLOC(m->k_inv, (int64_t)n * FSI_MAT_SIZE);
    SOLID_ALLOC(m->moment_inv, (int64_t)n * m->n_basis * m->n_basis);
    SOLID_ALLOC(m->fit, (int64_t)n * FSI_DIM * m->n_basis);
    SOLID_ALLOC(m->defgrad, (int64_t)n * FSI_MAT_SIZE);
    SOLID_ALLOC(m->gather, (int64_t)n * m->gather_stride);
    SOLID_ALLOC(m->stress, (int64_t)n * 6);
    SOLID_ALLOC(m->mstate, n);
    SOLID_ALLOC(m->work, n);
    SOLID_ALLOC(m->thickness_stretch, n);
    SOLID_ALLOC(m->family_volume, n);
    SOLID_ALLOC(m->damage, n);
    SOLID_ALLOC(m->intact_count, n);
    SOLID_ALLOC(m->flags, n);
    SOLID_ALLOC(m->scratch, (int64_t)n * FSI_MAT_SIZE);
    SOLID_ALLOC(m->iscratch, n);

    m->full = nosbpd_full_family_of_lattice(m->delta, m->dx, m->influence);
    m->stab_modulus =
        nosbpd_stabilisation_modulus(&m->mat, m->zero_energy_coefficient, m->delta, &m->full);
    for (int i = 0; i < n; i++) {
        double v = 0.0;
        for (int64_t q = m->bonds.offset[i]; q < m->bonds.offset[i + 1]; q++)
            v += p->volume[m->bonds.neighbour[q]];
        m->family_volume[i] = v;
        m->thickness_stretch[i] = 1.0;
        fsi_mat_identity(m->defgrad + (int64_t)i * FSI_MAT_SIZE);
        if (p->flags[i] & SOLID_MIRRORED)
            m->flags[i] |= NOSBPD_POINT_GHOST;
        for (int d = 0; d < FSI_DIM; d++)   /* C = [I | 0]: the reference fit */
            m->fit[((int64_t)i * FSI_DIM + d) * m->n_basis + d] = 1.0;
        if (nosbpd_shape_tensor(m, p, i) != 0 && !(m->flags[i] & NOSBPD_POINT_GHOST)) {
            m->flags[i] |= NOSBPD_POINT_SINGULAR_SHAPE;
            m->n_without_force_state++;
            nosbpd_warn_point(m, p, i, FAMILY_TOO_POOR ": it carries no force state of "
                              "its own", 0.0);
        }
    }
    if (m->n_warnings > NOSBPD_MAX_WARNINGS)
        fprintf(stderr, "nosbpd: warning: %d points in all have no usable shape tensor\n",
                m->n_warnings);
    m->stable_dt = stable_step(m, p);
    return m;

out_of_memory:
    snprintf(msg, msg_size, "nosbpd: out of memory for the state of %d points", p->n);
    solid_model_free(m);
    return NULL;
}

double solid_model_stable_dt(const solid_model *m, const solid_particles *p)
{
    (void)p;
    /* Bonds only break, which only lowers the stiffness: the reference bound holds. */
    return m->stable_dt;
}

int solid_model_surface(const solid_model *m, const solid_particles *p, uint8_t *surface)
{
    int count = 0;
    for (int i = 0; i < p->n; i++) {
        /* Mirrored clamp points are not material: the fluid never meets them. */
        surface[i] = m->intact_count[i] < m->full.count && !(m->flags[i] & NOSBPD_POINT_GHOST);
        count += surface[i];
    }
    return count;
}

int solid_model_write_fields(const solid_model *m, fsi_h5_writer *out)
{
    const int n = m->n;
    double *buf = m->scratch;
    int32_t *ibuf = m->iscratch;
    for (int i = 0; i < n; i++)
        fsi_sym6_to_mat(m->stress + (int64_t)i * 6, buf + (int64_t)i * FSI_MAT_SIZE);
    if (fsi_h5_write_field_real(out, "stress", buf, FSI_MAT_SIZE) != 0)
        return -1;
    if (fsi_h5_write_field_real(out, "damage", m->damage, 1) != 0)
        return -1;
    for (int i = 0; i < n; i++)
        buf[i] = m->mstate[i].equivalent_plastic_strain;
    if (fsi_h5_write_field_real(out, "equivalent_plastic_strain", buf, 1) != 0)
        return -1;
    if (fsi_h5_write_field_int(out, "intact_bonds", m->intact_count, 1) != 0)
        return -1;
    for (int i = 0; i < n; i++)
        ibuf[i] = (m->flags[i] & (NOSBPD_POINT_SINGULAR_SHAPE | NOSBPD_POINT_INVERTED)) != 0;
    if (fsi_h5_write_field_int(out, "no_force_state", ibuf, 1) != 0)
        return -1;
    return 0;
}

/* Sum over points of V_I (w_I + W_s,I): w_I the stress work per reference volume
 * accumulated by the Hughes-Winget update (= 1/2 sigma : eps for linear elasticity;
 * with plasticity it includes the dissipated plastic work), or for a hyperelastic
 * material its strain energy W(F) per reference volume at the last internal-force
 * call (material_total_stress); W_s,I the energy of the zero-energy mode control,
 * 1/2 G C_w sum_J omega V_J |z|^2, z = y - C b(xi), at the current positions with the
 * fit C of the last internal-force call. Per-point terms in parallel, the sum in
 * index order (independent of the thread count). */
double solid_model_strain_energy(const solid_model *m, const solid_particles *p)
{
    const nosbpd_bonds *b = &m->bonds;
    double *restrict e = m->scratch;
    const double s = m->stab_modulus, inv_delta = 1.0 / m->delta;
    const int nb = m->n_basis;
#pragma omp parallel for schedule(static) if (b->n_bonds >= NOSBPD_PARALLEL_MIN_BONDS)
    for (int i = 0; i < m->n; i++) {
        double ws = 0.0;
        if (s > 0.0 && !(m->flags[i] & NOSBPD_NO_FORCE_STATE)) {
            const double *fit = m->fit + (int64_t)i * FSI_DIM * nb;
            const double *xi_pos = p->x + (int64_t)i * FSI_DIM;
            for (int64_t q = b->offset[i]; q < b->offset[i + 1]; q++) {
                if (!b->intact[q])
                    continue;
                double basis[NOSBPD_MAX_BASIS];
                solid_fit_basis(b->xi + q * FSI_DIM, inv_delta, nb, basis);
                const double *xj = p->x + (int64_t)b->neighbour[q] * FSI_DIM;
                double z2 = 0.0;
                for (int d = 0; d < FSI_DIM; d++) {
                    double z = xj[d] - xi_pos[d];
                    for (int c = 0; c < nb; c++)
                        z -= fit[d * nb + c] * basis[c];
                    z2 += z * z;
                }
                ws += b->weight[q] * z2;
            }
            ws *= 0.5 * s;
        }
        e[i] = p->volume[i] * (m->work[i] + ws);
    }
    double total = 0.0;
    for (int i = 0; i < m->n; i++)
        total += e[i];
    return total;
}

int nosbpd_points_without_force_state(const solid_model *m)
{
    return m->n_without_force_state;
}

int64_t solid_model_interaction_count(const solid_model *m)
{
    return m->bonds.n_bonds;
}

/* Total Lagrangian: the reference density (solid_model.h). */
const double *solid_model_density(const solid_model *m, const solid_particles *p)
{
    (void)m;
    return p->density;
}

int64_t nosbpd_bond_count(const solid_model *m)
{
    return m->bonds.n_bonds;
}

int64_t nosbpd_broken_bond_count(const solid_model *m)
{
    return m->n_broken;
}

int solid_model_describe_fields(fsi_h5_writer *out)
{
    static const fsi_h5_field_info info[] = {
        {"damage", "1", "Volume-weighted fraction of the point's bonds that are broken "
                        "(000 Eq. 49; 0 intact, 1 fully separated)."},
        {"equivalent_plastic_strain", "1", "Accumulated equivalent plastic strain "
                                           "sqrt(2/3 e_p : e_p)."},
        {"intact_bonds", "1", "Number of the point's bonds not broken."},
        {"no_force_state", "1", "1 for a point without a force state (its shape tensor "
                                "singular or its deformation inverted, docs/nosbpd.md)."},
    };
    static const int32_t values[] = {0, 1};
    return fsi_h5_describe_fields(out, info, (int)(sizeof info / sizeof info[0])) ||
                   fsi_h5_name_flags(out, "no_force_state", FSI_H5_FLAG_VALUES, 2, values,
                                     "force_state no_force_state")
               ? -1
               : 0;
}

/* Half the horizon: a kernel of support 2 h then spans the family. */
double solid_model_smoothing_length(const solid_model *m)
{
    return 0.5 * m->delta;
}

double nosbpd_horizon(const solid_model *m)
{
    return m->delta;
}

double nosbpd_critical_stretch(const solid_model *m)
{
    return m->critical_stretch;
}

double nosbpd_stabilisation_modulus_of(const solid_model *m)
{
    return m->stab_modulus;
}

int nosbpd_full_family_count(const solid_model *m)
{
    return m->full.count;
}

const nosbpd_bonds *nosbpd_model_bonds(const solid_model *m)
{
    return &m->bonds;
}

double *nosbpd_stress(solid_model *m)
{
    return m->stress;
}

const double *nosbpd_deformation_gradient(const solid_model *m)
{
    return m->defgrad;
}

const double *nosbpd_shape_tensor_inverse(const solid_model *m)
{
    return m->k_inv;
}

const double *nosbpd_damage(const solid_model *m)
{
    return m->damage;
}

const uint8_t *nosbpd_point_flags(const solid_model *m)
{
    return m->flags;
}

/* Every call commits the stress update, plastic state and broken bonds: no trial
 * evaluations (solid_model.h). */
int solid_model_stateless(const solid_model *m)
{
    (void)m;
    return 0;
}
