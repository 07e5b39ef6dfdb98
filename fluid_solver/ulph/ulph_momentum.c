/* Continuity and momentum of ULPH (ulph_momentum.h). */
#include "ulph_momentum.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "always_inline.h"
#include "cache_lines.h"
#include "small_tensor.h"
#include "soft_contact.h"

/* What a fluid pair reads of a particle, packed: two cache lines per neighbour in 2D
 * (four in 3D) instead of a line from each of six arrays; and what it adds to one,
 * the force density and div v, in one line. */
enum {
    PK_A = 0,                          /* sigma M^-1 */
    PK_MINV = PK_A + FSI_MAT_SIZE,     /* M^-1 */
    PK_X = PK_MINV + FSI_MAT_SIZE,
    PK_V = PK_X + FSI_DIM,
    PK_VOL = PK_V + FSI_DIM,
    PK_TR = PK_VOL + 1,                /* tr M */
    PK_SIZE = (PK_TR + 1 + 7) / 8 * 8, /* whole lines */
    SUM_DIV = FSI_DIM,
    SUM_SIZE = 4
};

int ulph_momentum_reserve(ulph_momentum_scratch *s, int n)
{
    if (n <= s->capacity)
        return 0;
    ulph_momentum_free(s);
    const size_t m = (size_t)(n > 0 ? n : 1);
    s->velocity_gradient = malloc(m * FSI_MAT_SIZE * sizeof(double));
    s->stress_shape = malloc(m * FSI_MAT_SIZE * sizeof(double));
    s->packed = fsi_alloc_lines(m * PK_SIZE);
    s->sums = fsi_alloc_lines(m * SUM_SIZE);
    if (!s->velocity_gradient || !s->stress_shape || !s->packed || !s->sums) {
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
    free(s->packed);
    free(s->sums);
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
    const double *packed;       /* the rates' packed copy (PK_*) */
    double *sums;               /* their sums (force density, div v: SUM_*) */
} pair_context;

/* The force density on fluid particle I from boundary (wall or solid) particle J at
 * x_IJ = rel, |x_IJ|^2 = r2, kernel w, and the pair's share of div v_I (the
 * walls' own velocity: a wall is no source of fluid). The force on I is V_I times it. */
static inline void boundary_pair(const pair_context *c, int i, int j, const double *rel,
                                 double r2, double w, double *out, double *div)
{
    const ulph_operators *ops = c->ops;
    const fluid_particles *p = c->p;
    const double *Ai = &c->A[(size_t)i * FSI_MAT_SIZE], *Aj = &c->A[(size_t)j * FSI_MAT_SIZE];
    const double *m_inv = &ops->shape_inv[(size_t)i * FSI_MAT_SIZE];
    double vx = 0.0, sum[FSI_MAT_SIZE], f[FSI_DIM], y[FSI_DIM], dv = 0.0;
    fsi_mat_vec(m_inv, rel, y);
    for (int d = 0; d < FSI_DIM; d++) {
        vx += (c->vv[j * FSI_DIM + d] - p->v[i * FSI_DIM + d]) * rel[d];
        dv += (p->v[j * FSI_DIM + d] - p->v[i * FSI_DIM + d]) * y[d];
    }
    for (int m = 0; m < FSI_MAT_SIZE; m++)
        sum[m] = Ai[m] + Aj[m];
    fsi_mat_vec(sum, rel, f);
    const double wv = w * p->volume[j];
    *div = wv * dv;
    /* 000 Eq. 26 per pair: pi_IJ g_IJ with g_IJ = w V_J M_I^-1 x_IJ. */
    const double approach = vx < 0.0 ? vx : 0.0;
    const double pi_ij = c->av * approach / (r2 + c->eps2);
    /* A wall pushes, never pulls: with p_I < 0 the pair's -p_I M_I^-1 term would draw I
     * into the wall, so p_I counts as 0 against a wall. */
    const double tension = p->pressure[i] < 0.0 ? p->pressure[i] : 0.0;
    for (int d = 0; d < FSI_DIM; d++)
        out[d] = wv * (f[d] + (pi_ij + tension) * y[d]);
    if (c->contact_k_c2 > 0.0) {
        /* The pair's distance at rest, the mean of the two spacings: a solid may be
         * sampled finer or coarser than the fluid (its spacing from its volume). */
        const double range = 0.5 * (c->spacing + fluid_particle_side(p->volume[j]));
        if (r2 < range * range) {
            /* 004 Eq. 21 as a force density on I: rho_I a_IJ, along x_I - x_J = -rel. */
            const double push = p->density[i] *
                                soft_contact_factor(sqrt(r2), range, c->contact_k_c2,
                                                    c->contact_inv_eta_scale);
            for (int d = 0; d < FSI_DIM; d++)
                out[d] -= push * rel[d];
        }
    }
    if (c->mu_laplacian > 0.0) {
        const double trace_i = fsi_mat_trace(&ops->shape[(size_t)i * FSI_MAT_SIZE]);
        const double trace_j = fsi_mat_trace(&ops->shape[(size_t)j * FSI_MAT_SIZE]);
        const double lap = c->mu_laplacian * 4.0 * FSI_DIM * wv / (trace_i + trace_j);
        for (int d = 0; d < FSI_DIM; d++)
            out[d] += lap * (c->vv[j * FSI_DIM + d] - c->vv[i * FSI_DIM + d]);
    }
}

/* The rates' sums of the fluid particles of [lo, hi): each fluid pair once, written to
 * both (antisymmetric terms), each boundary pair on I's side. For a fluid pair
 * (vv = v for fluid particles), with y_I = M_I^-1 x_IJ, y_J = M_J^-1 x_IJ,
 *   Q = w (A_I + A_J) x_IJ + mu_lap 4 DIM w / (tr M_I + tr M_J) (v_J - v_I),
 *   f_I += V_J (Q + pi_IJ y_I),  f_J -= V_I (Q + pi_IJ y_J)     (000 Eqs. 23, 26)
 *   div_I += w V_J (v_J - v_I) . y_I,  div_J += w V_I (v_J - v_I) . y_J   (000 Eq. 16)
 * (seen from J, x_JI = -x_IJ and v_I - v_J change sign together). */
static FSI_ALWAYS_INLINE void rates_rows(const pair_context *c, int lo, int hi,
                                         const int periodic, const int laplacian)
{
    const ulph_operators *ops = c->ops;
    const fluid_rows *rows = &ops->rows;
    const fluid_particles *p = c->p;
    const double *restrict pk = c->packed, *restrict pair_w = rows->f;
    const int32_t *restrict pair = rows->pair;
    double *restrict sums = c->sums;
    const double av = c->av, eps2 = c->eps2, lap_scale = c->mu_laplacian * 4.0 * FSI_DIM;
    for (int i = lo; i < hi; i++) {
        if (!(p->flags[i] & FLUID_PARTICLE_FLUID))
            continue;
        const double *pk_i = &pk[(size_t)i * PK_SIZE];
        double x_i[FSI_DIM], v_i[FSI_DIM], A_i[FSI_MAT_SIZE], Minv_i[FSI_MAT_SIZE];
        for (int d = 0; d < FSI_DIM; d++) {
            x_i[d] = pk_i[PK_X + d];
            v_i[d] = pk_i[PK_V + d];
        }
        for (int m = 0; m < FSI_MAT_SIZE; m++) {
            A_i[m] = pk_i[PK_A + m];
            Minv_i[m] = pk_i[PK_MINV + m];
        }
        const double vol_i = pk_i[PK_VOL], tr_i = pk_i[PK_TR];
        double f_i[FSI_DIM] = {0}, div_i = 0.0;
        const int64_t fluid_end = rows->fluid_end[i];
        for (int64_t e = rows->offset[i]; e < fluid_end; e++) {
            const int j = pair[e];
            const double w = pair_w[e];
            const double *pk_j = &pk[(size_t)j * PK_SIZE];
            double *sum_j = &sums[(size_t)j * SUM_SIZE];
            double rel[FSI_DIM], dv[FSI_DIM], r2 = 0.0, vx = 0.0;
            for (int d = 0; d < FSI_DIM; d++)
                rel[d] = pk_j[PK_X + d] - x_i[d];
            if (periodic)
                fsi_periodic_min_image(&ops->periodic, rel);
            for (int d = 0; d < FSI_DIM; d++) {
                r2 += rel[d] * rel[d];
                dv[d] = pk_j[PK_V + d] - v_i[d];
                vx += dv[d] * rel[d];
            }
            double q[FSI_DIM], y_i[FSI_DIM], y_j[FSI_DIM];
            for (int a = 0; a < FSI_DIM; a++) {
                double sq = 0.0, si = 0.0, sj = 0.0;
                for (int b = 0; b < FSI_DIM; b++) {
                    sq += (A_i[a * FSI_DIM + b] + pk_j[PK_A + a * FSI_DIM + b]) * rel[b];
                    si += Minv_i[a * FSI_DIM + b] * rel[b];
                    sj += pk_j[PK_MINV + a * FSI_DIM + b] * rel[b];
                }
                q[a] = w * sq;
                y_i[a] = si;
                y_j[a] = sj;
            }
            if (laplacian) {
                const double lap = lap_scale * w / (tr_i + pk_j[PK_TR]);
                for (int d = 0; d < FSI_DIM; d++)
                    q[d] += lap * dv[d];
            }
            /* 000 Eq. 27: only approaching pairs (a select, not a branch) */
            const double pi_w = w * av * (vx < 0.0 ? vx : 0.0) / (r2 + eps2);
            const double vol_j = pk_j[PK_VOL];
            double dvy_i = 0.0, dvy_j = 0.0;
            for (int d = 0; d < FSI_DIM; d++) {
                f_i[d] += vol_j * (q[d] + pi_w * y_i[d]);
                sum_j[d] -= vol_i * (q[d] + pi_w * y_j[d]);
                dvy_i += dv[d] * y_i[d];
                dvy_j += dv[d] * y_j[d];
            }
            div_i += w * vol_j * dvy_i;
            sum_j[SUM_DIV] += w * vol_i * dvy_j;
        }
        for (int64_t e = rows->split[i]; e < rows->boundary_end[i]; e++) {
            const int j = pair[e];
            double rel[FSI_DIM], out[FSI_DIM], d_div;
            const double r2 = ulph_pair_vector(ops, p->x, i, j, rel);
            boundary_pair(c, i, j, rel, r2, pair_w[e], out, &d_div);
            for (int d = 0; d < FSI_DIM; d++)
                f_i[d] += out[d];
            div_i += d_div;
        }
        double *sum_i = &sums[(size_t)i * SUM_SIZE];
        for (int d = 0; d < FSI_DIM; d++)
            sum_i[d] += f_i[d];
        sum_i[SUM_DIV] += div_i;
    }
}

static void rates_block(void *context, int lo, int hi)
{
    const pair_context *c = context;
    const int laplacian = c->mu_laplacian > 0.0;
    if (fsi_periodic_any(&c->ops->periodic)) /* the same code with each choice a constant */
        rates_rows(c, lo, hi, 1, laplacian);
    else if (laplacian)
        rates_rows(c, lo, hi, 0, 1);
    else
        rates_rows(c, lo, hi, 0, 0);
}

static pair_context make_context(const ulph_operators *ops, const ulph_momentum_params *prm,
                                 const fluid_particles *p, const double *vv, const double *A)
{
    return (pair_context){ops, p, vv, A,
                          prm->artificial_viscosity * prm->h * prm->c0 * prm->rho0,
                          0.01 * prm->h * prm->h,
                          prm->viscous_laplacian ? prm->viscosity : 0.0,
                          prm->contact * prm->c0 * prm->c0, prm->spacing,
                          1.0 / (0.75 * prm->h), NULL, NULL};
}

void ulph_momentum_rates(const ulph_operators *ops, const ulph_momentum_params *prm,
                         const fluid_particles *p, const double *velocity_for_viscosity,
                         ulph_momentum_scratch *scratch, double *drho_dt, double *dv_dt)
{
    const int n = p->n;
    double *L = scratch->velocity_gradient, *A = scratch->stress_shape;
    const double mu_stress = prm->viscous_laplacian ? 0.0 : prm->viscosity;
    if (!prm->viscous_laplacian)
        ulph_gradient_vector(ops, p, velocity_for_viscosity, L);
    double *restrict packed = scratch->packed, *restrict sums = scratch->sums;
#pragma omp parallel for schedule(static) if (n >= FLUID_PARALLEL_MIN_PARTICLES)
    for (int i = 0; i < n; i++) {
        if (prm->viscous_laplacian)
            fsi_mat_zero(&L[(size_t)i * FSI_MAT_SIZE]);
        stress_shape(ops, p, mu_stress, &L[(size_t)i * FSI_MAT_SIZE], i,
                     &A[(size_t)i * FSI_MAT_SIZE]);
        if (!(p->flags[i] & FLUID_PARTICLE_FLUID))
            continue; /* only fluid pairs read the packed copy and write the sums */
        memset(&sums[(size_t)i * SUM_SIZE], 0, SUM_SIZE * sizeof *sums);
        double *pk = &packed[(size_t)i * PK_SIZE];
        memcpy(pk + PK_A, &A[(size_t)i * FSI_MAT_SIZE], FSI_MAT_SIZE * sizeof *pk);
        memcpy(pk + PK_MINV, &ops->shape_inv[(size_t)i * FSI_MAT_SIZE],
               FSI_MAT_SIZE * sizeof *pk);
        memcpy(pk + PK_X, &p->x[i * FSI_DIM], FSI_DIM * sizeof *pk);
        memcpy(pk + PK_V, &p->v[i * FSI_DIM], FSI_DIM * sizeof *pk);
        pk[PK_VOL] = p->volume[i];
        pk[PK_TR] = fsi_mat_trace(&ops->shape[(size_t)i * FSI_MAT_SIZE]);
    }
    pair_context c = make_context(ops, prm, p, velocity_for_viscosity, A);
    c.packed = packed;
    c.sums = sums;
    ulph_for_blocks(ops, rates_block, &c);
#pragma omp parallel for schedule(static) if (n >= FLUID_PARALLEL_MIN_PARTICLES)
    for (int i = 0; i < n; i++) {
        double *a_i = &dv_dt[i * FSI_DIM];
        if (!(p->flags[i] & FLUID_PARTICLE_FLUID)) {
            drho_dt[i] = 0.0;
            memset(a_i, 0, FSI_DIM * sizeof *a_i);
            continue;
        }
        const double *sum_i = &sums[(size_t)i * SUM_SIZE];
        drho_dt[i] = -p->density[i] * sum_i[SUM_DIV];
        for (int d = 0; d < FSI_DIM; d++)
            a_i[d] = sum_i[d] / p->density[i] + prm->gravity[d];
    }
}

void ulph_boundary_loads(const ulph_operators *ops, const ulph_momentum_params *prm,
                         const fluid_particles *p, const double *velocity_for_viscosity,
                         const ulph_momentum_scratch *scratch, double *force)
{
    const pair_context c = make_context(ops, prm, p, velocity_for_viscosity,
                                        scratch->stress_shape);
    const fluid_rows *rows = &ops->rows;
    const int n = p->n;
#pragma omp parallel for schedule(dynamic, FLUID_CHUNK) if (n >= FLUID_PARALLEL_MIN_PARTICLES)
    for (int b = 0; b < n; b++) {
        double *f_b = &force[b * FSI_DIM];
        memset(f_b, 0, FSI_DIM * sizeof *f_b);
        if (!(p->flags[b] & FLUID_PARTICLE_MOVING_BOUNDARY))
            continue;
        /* B's own row holds its fluid neighbours I with the pair's w (w_IB = w_BI); the
         * pair as I's row sees it. */
        for (int64_t e = rows->split[b]; e < rows->boundary_end[b]; e++) {
            const int i = rows->pair[e];
            if (!(p->flags[i] & FLUID_PARTICLE_FLUID))
                continue;
            double rel[FSI_DIM], out[FSI_DIM], d_div;
            const double r2 = ulph_pair_vector(ops, p->x, i, b, rel);
            boundary_pair(&c, i, b, rel, r2, rows->f[e], out, &d_div);
            for (int d = 0; d < FSI_DIM; d++)
                f_b[d] -= p->volume[i] * out[d];
        }
    }
}
