/* Continuity, momentum, contact and boundary loads of WCSPH (wcsph_rates.h). */
#include "wcsph_rates.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "fluid_parallel.h"
#include "pair_reaction.h"
#include "small_tensor.h"
#include "soft_contact.h"

/* Bound on the Frobenius condition number of the renormalisation matrix: beyond it (a
 * particle with its neighbours nearly on a line, a lone spray particle) L = 0 and the
 * corrected gradient is zero, so Antuono's term falls back to Molteni's for that pair
 * side rather than amplify noise. Inside a lattice it is 2 (FSI_DIM). */
#define WCSPH_MAX_CONDITION 1e2

int wcsph_scratch_reserve(wcsph_scratch *s, int n)
{
    if (n <= s->capacity)
        return 0;
    wcsph_scratch_free(s);
    const size_t m = (size_t)(n > 0 ? n : 1);
    s->tau_rho2 = malloc(m * FSI_MAT_SIZE * sizeof(double));
    s->renorm = malloc(m * FSI_MAT_SIZE * sizeof(double));
    s->density_gradient = malloc(m * FSI_DIM * sizeof(double));
    s->sound = malloc(m * sizeof(double));
    if (!s->tau_rho2 || !s->renorm || !s->density_gradient || !s->sound) {
        wcsph_scratch_free(s);
        return -1;
    }
    s->capacity = n;
    return 0;
}

void wcsph_scratch_free(wcsph_scratch *s)
{
    free(s->tau_rho2);
    free(s->renorm);
    free(s->density_gradient);
    free(s->sound);
    memset(s, 0, sizeof *s);
}

void wcsph_gradients(const wcsph_pairs *pl, const wcsph_params *prm, const fluid_particles *p,
                     const double *u, wcsph_scratch *s)
{
    const int n = p->n;
    const double sound_exponent = 0.5 * (prm->gamma - 1.0);
#pragma omp parallel for schedule(dynamic, FLUID_CHUNK) if (n >= FLUID_PARALLEL_MIN_PARTICLES)
    for (int i = 0; i < n; i++) {
        double b[FSI_MAT_SIZE], grad_u[FSI_MAT_SIZE], grad_rho[FSI_DIM] = {0};
        fsi_mat_zero(b);
        fsi_mat_zero(grad_u);
        const double *u_i = &u[i * FSI_DIM];
        for (int64_t k = pl->pairs.offset[i]; k < pl->pairs.offset[i + 1]; k++) {
            const int j = pl->pairs.neighbour[k];
            if (!wcsph_in_sums(prm, p, j))
                continue;
            const double *rel = &pl->rel[k * FSI_DIM];
            /* V_J grad_I W_IJ = -V_J F x_IJ */
            double gw[FSI_DIM], du[FSI_DIM];
            const double vf = -p->volume[j] * pl->f[k];
            for (int d = 0; d < FSI_DIM; d++) {
                gw[d] = vf * rel[d];
                du[d] = u[j * FSI_DIM + d] - u_i[d];
                grad_rho[d] += (p->density[j] - p->density[i]) * gw[d];
            }
            fsi_mat_add_outer(b, 1.0, rel, gw);
            fsi_mat_add_outer(grad_u, 1.0, du, gw);
        }
        double *L = &s->renorm[(size_t)i * FSI_MAT_SIZE];
        if (fsi_mat_inverse(b, L, WCSPH_MAX_CONDITION) != 0)
            fsi_mat_zero(L);
        /* sum_J (rho_J - rho_I) L grad_I W V_J = L raw; for rho_J - rho_I = G . x_IJ,
         * raw = B^T G = B G (B is symmetric: grad_I W is parallel to x_IJ), so it is G. */
        fsi_mat_vec(L, grad_rho, &s->density_gradient[i * FSI_DIM]);
        double *t = &s->tau_rho2[(size_t)i * FSI_MAT_SIZE];
        const double scale = prm->laplacian ? 0.0
                                            : prm->viscosity / (p->density[i] * p->density[i]);
        for (int a = 0; a < FSI_DIM; a++)
            for (int c = 0; c < FSI_DIM; c++)
                FSI_MAT(t, a, c) = scale * (FSI_MAT(grad_u, a, c) + FSI_MAT(grad_u, c, a));
        const double ratio = p->density[i] / prm->rho0;
        s->sound[i] = prm->c0 * (sound_exponent == 3.0 ? ratio * ratio * ratio
                                                       : pow(ratio, sound_exponent));
    }
}

/* What every pair term reads. */
typedef struct {
    const wcsph_pairs *pl;
    const wcsph_params *prm;
    const fluid_particles *p;
    const double *u;
    const wcsph_scratch *s;
    double eps2, contact_k_c2, contact_inv_eta_scale;
} pair_context;

static pair_context make_context(const wcsph_pairs *pl, const wcsph_params *prm,
                                 const fluid_particles *p, const double *u,
                                 const wcsph_scratch *s)
{
    return (pair_context){pl, prm, p, u, s, 0.01 * prm->h * prm->h,
                          prm->contact * prm->c0 * prm->c0, 1.0 / (0.75 * prm->h)};
}

/* The acceleration of fluid particle I from neighbour J (entry k of I's row), gravity
 * excluded; the force on I is m_I times it. */
static inline void pair_acceleration(const pair_context *c, int i, int64_t k, double *out)
{
    const fluid_particles *p = c->p;
    const wcsph_params *prm = c->prm;
    const int j = c->pl->pairs.neighbour[k];
    const double *rel = &c->pl->rel[k * FSI_DIM];
    double r2 = 0.0;
    for (int d = 0; d < FSI_DIM; d++) {
        r2 += rel[d] * rel[d];
        out[d] = 0.0;
    }
    const int fluid_j = p->flags[j] & FLUID_PARTICLE_FLUID;
    if (wcsph_in_sums(prm, p, j)) {
        const double f = c->pl->f[k], m_j = p->mass[j];
        const double rho_i = p->density[i], rho_j = p->density[j];
        const double p_i = fluid_j ? p->pressure[i] : fmax(p->pressure[i], 0.0);
        /* v_IJ . (x_I - x_J) = (u_J - u_I) . x_IJ */
        double vx = 0.0;
        for (int d = 0; d < FSI_DIM; d++)
            vx += (c->u[j * FSI_DIM + d] - c->u[i * FSI_DIM + d]) * rel[d];
        double pi_ij = 0.0;
        if (vx < 0.0) {
            const double mu = prm->h * vx / (r2 + c->eps2);
            pi_ij = (-prm->beta1 * 0.5 * (c->s->sound[i] + c->s->sound[j]) * mu +
                     prm->beta2 * mu * mu) / (0.5 * (rho_i + rho_j));
        }
        /* -m_J (P_I + P_J + pi_IJ) grad_I W = m_J (P_I + P_J + pi_IJ) F x_IJ */
        const double radial = m_j * f * (p_i / (rho_i * rho_i) + p->pressure[j] / (rho_j * rho_j) +
                                         pi_ij);
        for (int d = 0; d < FSI_DIM; d++)
            out[d] += radial * rel[d];
        if (prm->laplacian) {
            /* (x_I - x_J) . grad_I W = F r^2 */
            const double lap = m_j * 2.0 * prm->viscosity * f * r2 /
                               (rho_i * rho_j * (r2 + c->eps2));
            for (int d = 0; d < FSI_DIM; d++)
                out[d] += lap * (c->u[i * FSI_DIM + d] - c->u[j * FSI_DIM + d]);
        } else {
            /* m_J (T_I + T_J) grad_I W = -m_J F (T_I + T_J) x_IJ */
            const double *ti = &c->s->tau_rho2[(size_t)i * FSI_MAT_SIZE];
            const double *tj = &c->s->tau_rho2[(size_t)j * FSI_MAT_SIZE];
            for (int a = 0; a < FSI_DIM; a++) {
                double sum = 0.0;
                for (int b = 0; b < FSI_DIM; b++)
                    sum += (FSI_MAT(ti, a, b) + FSI_MAT(tj, a, b)) * rel[b];
                out[a] -= m_j * f * sum;
            }
        }
    }
    if ((p->flags[j] & FLUID_PARTICLE_MOVING_BOUNDARY) && c->contact_k_c2 > 0.0) {
        /* The pair's distance at rest, the mean of the two spacings (a solid may be
         * sampled finer or coarser than the fluid). */
        const double range = 0.5 * (prm->spacing + fluid_particle_side(p->volume[j]));
        if (r2 < range * range) {
            const double push = soft_contact_factor(sqrt(r2), range, c->contact_k_c2,
                                                    c->contact_inv_eta_scale);
            for (int d = 0; d < FSI_DIM; d++)
                out[d] -= push * rel[d];
        }
    }
}

/* delta h c0 times the diffusion of pair k of I's row (in the sums). */
static inline double pair_diffusion(const pair_context *c, int i, int64_t k)
{
    const fluid_particles *p = c->p;
    const int j = c->pl->pairs.neighbour[k];
    const double *rel = &c->pl->rel[k * FSI_DIM];
    double r2 = 0.0;
    for (int d = 0; d < FSI_DIM; d++)
        r2 += rel[d] * rel[d];
    const double v_f = p->volume[j] * c->pl->f[k], drho = p->density[j] - p->density[i];
    if (c->prm->antuono) {
        if (!(r2 > 0.0))
            return 0.0;
        /* psi . grad_I W = -F (2 (rho_J - rho_I) - (G_I + G_J) . x_IJ). A wall or
         * solid particle's own gradient is not the fluid's (its outer layers, beyond
         * the fluid's reach, hold rho0): the fluid particle's stands in for it. */
        const double *gi = &c->s->density_gradient[i * FSI_DIM];
        const double *gj = (p->flags[j] & FLUID_PARTICLE_FLUID)
                               ? &c->s->density_gradient[j * FSI_DIM] : gi;
        double proj = 0.0;
        for (int d = 0; d < FSI_DIM; d++)
            proj += (gi[d] + gj[d]) * rel[d];
        return -v_f * (2.0 * drho - proj);
    }
    /* 2 V_J (rho_I - rho_J) F r^2 / (r^2 + 0.01 h^2) */
    return -2.0 * v_f * drho * r2 / (r2 + c->eps2);
}

void wcsph_density_diffusion(const wcsph_pairs *pl, const wcsph_params *prm,
                             const fluid_particles *p, const wcsph_scratch *s, double *out)
{
    const pair_context c = make_context(pl, prm, p, NULL, s);
    const double scale = prm->delta * prm->h * prm->c0;
    const int n = p->n;
#pragma omp parallel for schedule(dynamic, FLUID_CHUNK) if (n >= FLUID_PARALLEL_MIN_PARTICLES)
    for (int i = 0; i < n; i++) {
        double sum = 0.0;
        if (p->flags[i] & FLUID_PARTICLE_FLUID)
            for (int64_t k = pl->pairs.offset[i]; k < pl->pairs.offset[i + 1]; k++)
                if (wcsph_in_sums(prm, p, pl->pairs.neighbour[k]))
                    sum += pair_diffusion(&c, i, k);
        out[i] = scale * sum;
    }
}

void wcsph_rates(const wcsph_pairs *pl, const wcsph_params *prm, const fluid_particles *p,
                 const double *u, const wcsph_scratch *s, double *drho_dt, double *dv_dt)
{
    const pair_context c = make_context(pl, prm, p, u, s);
    const double diffusion = prm->delta * prm->h * prm->c0;
    const int n = p->n;
#pragma omp parallel for schedule(dynamic, FLUID_CHUNK) if (n >= FLUID_PARALLEL_MIN_PARTICLES)
    for (int i = 0; i < n; i++) {
        double *a_i = &dv_dt[i * FSI_DIM];
        drho_dt[i] = 0.0;
        memset(a_i, 0, FSI_DIM * sizeof *a_i);
        if (!(p->flags[i] & FLUID_PARTICLE_FLUID))
            continue;
        double acc[FSI_DIM] = {0}, div = 0.0, diff = 0.0;
        for (int64_t k = pl->pairs.offset[i]; k < pl->pairs.offset[i + 1]; k++) {
            const int j = pl->pairs.neighbour[k];
            double a[FSI_DIM];
            pair_acceleration(&c, i, k, a);
            for (int d = 0; d < FSI_DIM; d++)
                acc[d] += a[d];
            if (!wcsph_in_sums(prm, p, j))
                continue;
            /* m_J (v_I - v_J) . grad_I W = m_J F (v_J - v_I) . x_IJ */
            const double *rel = &pl->rel[k * FSI_DIM];
            double vx = 0.0;
            for (int d = 0; d < FSI_DIM; d++)
                vx += (p->v[j * FSI_DIM + d] - p->v[i * FSI_DIM + d]) * rel[d];
            div += p->mass[j] * pl->f[k] * vx;
            if (diffusion > 0.0)
                diff += pair_diffusion(&c, i, k);
        }
        drho_dt[i] = div + diffusion * diff;
        for (int d = 0; d < FSI_DIM; d++)
            a_i[d] = acc[d] + prm->gravity[d];
    }
}

static void pair_term(const void *context, int i, int64_t k, double *out)
{
    pair_acceleration(context, i, k, out);
}

void wcsph_boundary_loads(const wcsph_pairs *pl, const wcsph_params *prm,
                          const fluid_particles *p, const double *u, const wcsph_scratch *s,
                          double *force)
{
    const pair_context c = make_context(pl, prm, p, u, s);
    fluid_pair_reaction(&pl->pairs, p, p->mass, pair_term, &c, force);
}

void wcsph_gradient(const wcsph_pairs *pl, const wcsph_params *prm, const fluid_particles *p,
                    const wcsph_scratch *s, const double *f, double *grad)
{
    const int n = p->n;
#pragma omp parallel for schedule(dynamic, FLUID_CHUNK) if (n >= FLUID_PARALLEL_MIN_PARTICLES)
    for (int i = 0; i < n; i++) {
        double raw[FSI_DIM] = {0};
        for (int64_t k = pl->pairs.offset[i]; k < pl->pairs.offset[i + 1]; k++) {
            const int j = pl->pairs.neighbour[k];
            if (!wcsph_in_sums(prm, p, j))
                continue;
            const double vf = -p->volume[j] * pl->f[k] * (f[j] - f[i]);
            for (int d = 0; d < FSI_DIM; d++)
                raw[d] += vf * pl->rel[k * FSI_DIM + d];
        }
        fsi_mat_vec(&s->renorm[(size_t)i * FSI_MAT_SIZE], raw, &grad[i * FSI_DIM]);
    }
}
