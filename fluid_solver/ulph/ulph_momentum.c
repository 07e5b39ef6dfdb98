/* Continuity and momentum of ULPH (ulph_momentum.h). */
#include "ulph_momentum.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "small_tensor.h"
#include "pair_reaction.h"
#include "soft_contact.h"

int ulph_momentum_reserve(ulph_momentum_scratch *s, int n)
{
    if (n <= s->capacity)
        return 0;
    ulph_momentum_free(s);
    const size_t m = (size_t)(n > 0 ? n : 1);
    s->velocity_gradient = malloc(m * FSI_MAT_SIZE * sizeof(double));
    s->stress_shape = malloc(m * FSI_MAT_SIZE * sizeof(double));
    s->divergence = malloc(m * sizeof(double));
    if (!s->velocity_gradient || !s->stress_shape || !s->divergence) {
        ulph_momentum_free(s);
        return -1;
    }
    s->capacity = n;
    return 0;
}

void ulph_momentum_free(ulph_momentum_scratch *s)
{
    free(s->velocity_gradient);
    free(s->stress_shape);
    free(s->divergence);
    memset(s, 0, sizeof *s);
}

/* sigma M^-1 of particle i: sigma = -p I + 2 mu (sym L - tr L / 3 I) (000 Eqs. 3-5). */
static void stress_shape(const ulph_operators *ops, const fluid_particles *p, double mu,
                         const double *L, int i, double *out)
{
    double sigma[FSI_MAT_SIZE];
    fsi_mat_sym(L, sigma);
    double trace = 0.0;
    for (int a = 0; a < FSI_DIM; a++)
        trace += FSI_MAT(L, a, a);
    fsi_mat_scale(sigma, 2.0 * mu);
    for (int a = 0; a < FSI_DIM; a++)
        FSI_MAT(sigma, a, a) -= 2.0 * mu * trace / 3.0 + p->pressure[i];
    fsi_mat_mul(sigma, &ops->shape_inv[(size_t)i * FSI_MAT_SIZE], out);
}

/* What every pair term needs (the rates and the boundary loads share it, so that the
 * load on a boundary particle is the exact reaction of the force on the fluid). */
typedef struct {
    const ulph_operators *ops;
    const fluid_particles *p;
    const double *vv;           /* velocity_for_viscosity */
    const double *A;            /* sigma M^-1 per particle */
    double av, eps2, mu_laplacian;
    double contact_k_c2, spacing, contact_inv_eta_scale; /* soft_contact.h */
} pair_context;

/* The force density on fluid particle I from neighbour J (entry k of I's row); the
 * force on I is V_I times it. trace_i = tr M_I, taken once per row by the caller. */
static inline void pair_force(const pair_context *c, int i, int64_t k, double trace_i,
                              double *out)
{
    const ulph_operators *ops = c->ops;
    const fluid_particles *p = c->p;
    const int j = ops->pairs.neighbour[k];
    const double *Ai = &c->A[(size_t)i * FSI_MAT_SIZE], *Aj = &c->A[(size_t)j * FSI_MAT_SIZE];
    double xij[FSI_DIM], vx = 0.0, r2 = 0.0, sum[FSI_MAT_SIZE];
    ulph_pair_vector(ops, p->x, i, j, xij);
    for (int d = 0; d < FSI_DIM; d++) {
        vx += (c->vv[j * FSI_DIM + d] - p->v[i * FSI_DIM + d]) * xij[d];
        r2 += xij[d] * xij[d];
    }
    for (int m = 0; m < FSI_MAT_SIZE; m++)
        sum[m] = Ai[m] + Aj[m];
    double f[FSI_DIM];
    fsi_mat_vec(sum, xij, f);
    const double wv = ops->pairs.w[k] * p->volume[j];
    /* g_IJ = w V_J M_I^-1 x_IJ (ulph_operators.h): 000 Eq. 26 per pair. */
    /* min(vx, 0) rather than a branch around the division: the sign of vx is a coin
     * toss per pair (a mispredicted branch each time), and av * 0 / (r2 + eps2) is 0. */
    const double approach = vx < 0.0 ? vx : 0.0;
    const double pi_ij = c->av * approach / (r2 + c->eps2);
    /* A wall pushes, never pulls: with p_I < 0 the pair's -p_I M_I^-1 term would draw I
     * into the wall, so p_I counts as 0 against a wall. */
    const int against_wall = !(p->flags[j] & FLUID_PARTICLE_FLUID);
    const double tension = against_wall && p->pressure[i] < 0.0 ? p->pressure[i] : 0.0;
    for (int d = 0; d < FSI_DIM; d++)
        out[d] = wv * f[d] + (pi_ij + tension) * ops->g[k * FSI_DIM + d];
    if (against_wall && c->contact_k_c2 > 0.0) {
        /* The pair's distance at rest, the mean of the two spacings: a solid may be
         * sampled finer or coarser than the fluid (its spacing from its volume). */
        const double range = 0.5 * (c->spacing + fluid_particle_side(p->volume[j]));
        if (r2 < range * range) {
            /* 004 Eq. 21 as a force density on I: rho_I a_IJ, along x_I - x_J = -xij. */
            const double push = p->density[i] *
                                soft_contact_factor(sqrt(r2), range, c->contact_k_c2,
                                                    c->contact_inv_eta_scale);
            for (int d = 0; d < FSI_DIM; d++)
                out[d] -= push * xij[d];
        }
    }
    if (c->mu_laplacian > 0.0) {
        const double trace_j = fsi_mat_trace(&ops->shape[(size_t)j * FSI_MAT_SIZE]);
        const double lap = c->mu_laplacian * 4.0 * FSI_DIM * wv / (trace_i + trace_j);
        for (int d = 0; d < FSI_DIM; d++)
            out[d] += lap * (c->vv[j * FSI_DIM + d] - c->vv[i * FSI_DIM + d]);
    }
}

static pair_context make_context(const ulph_operators *ops, const ulph_momentum_params *prm,
                                 const fluid_particles *p, const double *vv, const double *A)
{
    return (pair_context){ops, p, vv, A,
                          prm->artificial_viscosity * prm->h * prm->c0 * prm->rho0,
                          0.01 * prm->h * prm->h,
                          prm->viscous_laplacian ? prm->viscosity : 0.0,
                          prm->contact * prm->c0 * prm->c0, prm->spacing,
                          1.0 / (0.75 * prm->h)};
}

void ulph_momentum_rates(const ulph_operators *ops, const ulph_momentum_params *prm,
                         const fluid_particles *p, const double *velocity_for_viscosity,
                         ulph_momentum_scratch *scratch, double *drho_dt, double *dv_dt)
{
    const int n = p->n;
    double *L = scratch->velocity_gradient, *A = scratch->stress_shape;
    const double mu_stress = prm->viscous_laplacian ? 0.0 : prm->viscosity;
    if (prm->viscous_laplacian)
        memset(L, 0, (size_t)n * FSI_MAT_SIZE * sizeof *L);
    else
        ulph_gradient_vector(ops, velocity_for_viscosity, L);
    /* Continuity sees the walls' own velocity (no penetration), not the virtual one. */
    ulph_divergence(ops, p->v, scratch->divergence);
#pragma omp parallel for schedule(dynamic, FLUID_CHUNK) if (n >= FLUID_PARALLEL_MIN_PARTICLES)
    for (int i = 0; i < n; i++)
        stress_shape(ops, p, mu_stress, &L[(size_t)i * FSI_MAT_SIZE], i,
                     &A[(size_t)i * FSI_MAT_SIZE]);

    const pair_context c = make_context(ops, prm, p, velocity_for_viscosity, A);
#pragma omp parallel for schedule(dynamic, FLUID_CHUNK) if (n >= FLUID_PARALLEL_MIN_PARTICLES)
    for (int i = 0; i < n; i++) {
        double *a_i = &dv_dt[i * FSI_DIM];
        if (!(p->flags[i] & FLUID_PARTICLE_FLUID)) {
            drho_dt[i] = 0.0;
            memset(a_i, 0, FSI_DIM * sizeof *a_i);
            continue;
        }
        drho_dt[i] = -p->density[i] * scratch->divergence[i];
        double force[FSI_DIM] = {0};
        const double trace_i = fsi_mat_trace(&ops->shape[(size_t)i * FSI_MAT_SIZE]);
        for (int64_t k = ops->pairs.offset[i]; k < ops->pairs.offset[i + 1]; k++) {
            double f[FSI_DIM];
            pair_force(&c, i, k, trace_i, f);
            for (int d = 0; d < FSI_DIM; d++)
                force[d] += f[d];
        }
        for (int d = 0; d < FSI_DIM; d++)
            a_i[d] = force[d] / p->density[i] + prm->gravity[d];
    }
}

/* The force density on I from entry k of its row, for fluid_pair_reaction. */
static void pair_term(const void *context, int i, int64_t k, double *out)
{
    const pair_context *c = context;
    pair_force(c, i, k, fsi_mat_trace(&c->ops->shape[(size_t)i * FSI_MAT_SIZE]), out);
}

void ulph_boundary_loads(const ulph_operators *ops, const ulph_momentum_params *prm,
                         const fluid_particles *p, const double *velocity_for_viscosity,
                         const ulph_momentum_scratch *scratch, double *force)
{
    const pair_context c = make_context(ops, prm, p, velocity_for_viscosity,
                                        scratch->stress_shape);
    fluid_pair_reaction(&ops->pairs, p, p->volume, pair_term, &c, force);
}
