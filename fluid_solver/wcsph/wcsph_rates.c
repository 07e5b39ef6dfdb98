/* Walls, gradients, continuity, momentum, contact and boundary loads of WCSPH
 * (wcsph_rates.h), over the rows of fluid_rows.h. */
#include "wcsph_rates.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "fluid_parallel.h"
#include "ghost_walls.h"
#include "always_inline.h"
#include "small_tensor.h"
#include "soft_contact.h"


int wcsph_scratch_reserve(wcsph_scratch *s, int n)
{
    if (n <= s->capacity)
        return 0;
    wcsph_scratch_free(s);
    const size_t m = (size_t)(n > 0 ? n : 1);
    s->pressure_rho2 = malloc(m * sizeof(double));
    s->sound = malloc(m * sizeof(double));
    s->tau_rho2 = malloc(m * FSI_MAT_SIZE * sizeof(double));
    s->density_gradient = malloc(m * FSI_DIM * sizeof(double));
    s->renorm_sum = malloc(m * FSI_MAT_SIZE * sizeof(double));
    s->diffusion = malloc(m * sizeof(double));
    if (!s->pressure_rho2 || !s->sound || !s->tau_rho2 || !s->density_gradient ||
        !s->renorm_sum || !s->diffusion) {
        wcsph_scratch_free(s);
        return -1;
    }
    s->capacity = n;
    return 0;
}

void wcsph_scratch_free(wcsph_scratch *s)
{
    free(s->pressure_rho2);
    free(s->sound);
    free(s->tau_rho2);
    free(s->density_gradient);
    free(s->renorm_sum);
    free(s->diffusion);
    memset(s, 0, sizeof *s);
}

static const fsi_periodic *periodic_of(const wcsph_neighbours *nb)
{
    return fsi_periodic_any(&nb->list->periodic) ? &nb->list->periodic : NULL;
}

/* ---- the pairs ------------------------------------------------------------------- */

void wcsph_pairs(fluid_rows *rows, const wendland_c2_kernel *k, const fsi_periodic *per,
                 const fluid_particles *p)
{
    const int n = rows->n;
#pragma omp parallel for schedule(dynamic, FLUID_CHUNK) if (n >= FLUID_PARALLEL_MIN_PARTICLES)
    for (int i = 0; i < n; i++) {
        fluid_rows_filter_row(rows, k->support2, per, p->x, i);
        wendland_c2_f_row(k, rows->f + rows->offset[i], rows->fluid_end[i] - rows->offset[i]);
        wendland_c2_f_row(k, rows->f + rows->split[i], rows->boundary_end[i] - rows->split[i]);
    }
}

/* ---- pass 1: walls ------------------------------------------------------------- */

void wcsph_walls(const wcsph_neighbours *nb, const tait_eos *eos, const double *gravity,
                 const unsigned char *free_slip, fluid_particles *p, double *u)
{
    const fluid_verlet *list = nb->list;
    const wendland_c2_kernel *k = nb->kernel;
    const fsi_periodic *per = periodic_of(nb);
    const int n = p->n;
#pragma omp parallel for schedule(dynamic, FLUID_CHUNK) if (n >= FLUID_PARALLEL_MIN_PARTICLES)
    for (int s = 0; s < n; s++) {
        if (p->flags[s] & FLUID_PARTICLE_FLUID) {
            memcpy(&u[s * FSI_DIM], &p->v[s * FSI_DIM], FSI_DIM * sizeof *u);
            continue;
        }
        ghost_wall_sums g = {0};
        for (int64_t c = list->offset[s]; c < list->offset[s + 1]; c++) {
            const int f = list->candidate[c];
            if (!(p->flags[f] & FLUID_PARTICLE_FLUID))
                continue;
            double xsf[FSI_DIM], w, unused;
            wendland_c2_eval2(k, fluid_pair_vector_r2(per, p->x, s, f, xsf), &w, &unused);
            if (w > 0.0)
                ghost_wall_sums_add(&g, p, f, w, xsf);
        }
        ghost_wall_set(&g, s, eos, gravity, free_slip, p, u);
    }
}

/* ---- pass 2: state and gradients ------------------------------------------------- */

/* One side's share of the gradient sums of a pair: volume V of the other particle,
 * t = grad W (unweighted), du = u_J - u_I, drho = rho_J - rho_I. */
static FSI_ALWAYS_INLINE void gradient_share(double *grad_u, double *bsum, double *grad_rho,
                                         double vol, const double *t, const double *du,
                                         const double *rel, double drho, const int stress,
                                         const int antuono)
{
    for (int a = 0; a < FSI_DIM; a++) {
        const double ta = vol * t[a];
        for (int b = 0; b < FSI_DIM; b++) {
            if (stress)
                FSI_MAT(grad_u, b, a) += du[b] * ta;
            if (antuono)
                FSI_MAT(bsum, b, a) += rel[b] * ta;
        }
        if (antuono)
            grad_rho[a] += drho * ta;
    }
}

/* I's side of the gradient sums of the pair with boundary particle j (in the sums) at
 * rel, F = f (a fluid particle's boundary pair, or any pair of a wall's or solid
 * particle's row). */
static FSI_ALWAYS_INLINE void gradient_one_sided(const fluid_particles *p, const double *u, int i,
                                             int j, const double *rel, double f, double *gu,
                                             double *bs, double *gr, const int stress,
                                             const int antuono)
{
    double t[FSI_DIM], du[FSI_DIM];
    for (int d = 0; d < FSI_DIM; d++) {
        t[d] = -f * rel[d];
        du[d] = u[j * FSI_DIM + d] - u[i * FSI_DIM + d];
    }
    gradient_share(gu, bs, gr, p->volume[j], t, du, rel, p->density[j] - p->density[i],
                   stress, antuono);
}

/* The gradient sums of the pairs of the fluid particles of [lo, hi) (their filtered
 * rows: fluid pairs both ways, boundary pairs on I's side). */
static FSI_ALWAYS_INLINE void gradient_block(const wcsph_neighbours *nb, const wcsph_params *prm,
                                         const fluid_particles *p, const double *u,
                                         wcsph_scratch *s, int lo, int hi, const int stress,
                                         const int antuono, const int periodic)
{
    const fluid_rows *rows = nb->rows;
    const fsi_periodic *per = periodic_of(nb);
    /* Local restrict pointers: the stores into J's sums cannot alias the particles'
     * fields, so the loop keeps them in registers. */
    const double *restrict x = p->x, *restrict v = p->v, *restrict vol = p->volume;
    const double *restrict rho = p->density, *restrict pair_f = rows->f;
    const int32_t *restrict pair = rows->pair;
    double *restrict gu_all = s->tau_rho2, *restrict bs_all = s->renorm_sum;
    double *restrict gr_all = s->density_gradient;
    for (int i = lo; i < hi; i++) {
        if (!(p->flags[i] & FLUID_PARTICLE_FLUID))
            continue;
        double gu[FSI_MAT_SIZE] = {0}, bs[FSI_MAT_SIZE] = {0}, gr[FSI_DIM] = {0};
        const double v_i = vol[i], rho_i = rho[i];
        double x_i[FSI_DIM], u_i[FSI_DIM];
        for (int d = 0; d < FSI_DIM; d++)
            x_i[d] = x[i * FSI_DIM + d], u_i[d] = v[i * FSI_DIM + d];
        const int64_t end = rows->fluid_end[i];
        /* The J of a row are distinct: its pairs are independent (omp simd lets the
         * compiler overlap them; it pairs two of them per instruction). */
#pragma omp simd reduction(+ : gu[:FSI_MAT_SIZE], bs[:FSI_MAT_SIZE], gr[:FSI_DIM])
        for (int64_t e = rows->offset[i]; e < end; e++) {
            const int j = pair[e];
            const double f = pair_f[e];
            double rel[FSI_DIM], t[FSI_DIM], du[FSI_DIM];
            for (int d = 0; d < FSI_DIM; d++)
                rel[d] = x[j * FSI_DIM + d] - x_i[d];
            if (periodic)
                fsi_periodic_min_image(per, rel);
            for (int d = 0; d < FSI_DIM; d++) {
                t[d] = -f * rel[d];
                du[d] = v[j * FSI_DIM + d] - u_i[d];
            }
            const double drho = rho[j] - rho_i;
            gradient_share(gu, bs, gr, vol[j], t, du, rel, drho, stress, antuono);
            /* J's side: grad_J W_JI = -t, x_JI = -rel, u_I - u_J = -du. */
            gradient_share(&gu_all[(size_t)j * FSI_MAT_SIZE], &bs_all[(size_t)j * FSI_MAT_SIZE],
                           &gr_all[j * FSI_DIM], v_i, t, du, rel, drho, stress, antuono);
        }
        for (int64_t e = rows->split[i]; e < rows->boundary_end[i]; e++) {
            const int j = pair[e];
            if (!wcsph_in_sums(prm, p, j))
                continue;
            double rel[FSI_DIM];
            fluid_pair_vector_r2(per, x, i, j, rel);
            gradient_one_sided(p, u, i, j, rel, pair_f[e], gu, bs, gr, stress, antuono);
        }
        for (int a = 0; a < FSI_MAT_SIZE; a++) {
            gu_all[(size_t)i * FSI_MAT_SIZE + a] += gu[a];
            bs_all[(size_t)i * FSI_MAT_SIZE + a] += bs[a];
        }
        for (int d = 0; d < FSI_DIM; d++)
            gr_all[i * FSI_DIM + d] += gr[d];
    }
}

/* The gradient sums of wall or solid particle i (in the sums), over its full row. */
static void gradient_boundary_row(const wcsph_neighbours *nb, const wcsph_params *prm,
                                  const fluid_particles *p, const double *u, wcsph_scratch *s,
                                  int i, int stress, int antuono)
{
    const fluid_verlet *list = nb->list;
    const fsi_periodic *per = periodic_of(nb);
    for (int64_t c = list->offset[i]; c < list->offset[i + 1]; c++) {
        const int j = list->candidate[c];
        double rel[FSI_DIM];
        const double r2 = fluid_pair_vector_r2(per, p->x, i, j, rel);
        if (!(r2 < nb->kernel->support2) || !wcsph_in_sums(prm, p, j))
            continue;
        gradient_one_sided(p, u, i, j, rel, wendland_c2_f_inside(nb->kernel, r2),
                           &s->tau_rho2[(size_t)i * FSI_MAT_SIZE],
                           &s->renorm_sum[(size_t)i * FSI_MAT_SIZE],
                           &s->density_gradient[i * FSI_DIM], stress, antuono);
    }
}

static void gradient_block_any(const wcsph_neighbours *nb, const wcsph_params *prm,
                               const fluid_particles *p, const double *u, wcsph_scratch *s,
                               int lo, int hi, int stress, int antuono)
{
    if (periodic_of(nb)) /* the same code with each choice a constant */
        gradient_block(nb, prm, p, u, s, lo, hi, stress, antuono, 1);
    else if (stress && antuono)
        gradient_block(nb, prm, p, u, s, lo, hi, 1, 1, 0);
    else if (stress)
        gradient_block(nb, prm, p, u, s, lo, hi, 1, 0, 0);
    else
        gradient_block(nb, prm, p, u, s, lo, hi, 0, 1, 0);
}

void wcsph_gradients(const wcsph_neighbours *nb, const wcsph_params *prm,
                     const fluid_particles *p, const double *u, wcsph_scratch *s)
{
    const int n = p->n, stress = !prm->laplacian, antuono = prm->antuono;
    const int n_blocks = nb->rows->n_blocks;
    const int *start = nb->rows->block_start;
    const double sound_exponent = 0.5 * (prm->gamma - 1.0);
#pragma omp parallel if (n >= FLUID_PARALLEL_MIN_PARTICLES)
    {
#pragma omp for schedule(static)
        for (int i = 0; i < n; i++) {
            const double rho = p->density[i], ratio = rho / prm->rho0;
            s->pressure_rho2[i] = p->pressure[i] / (rho * rho);
            s->sound[i] = prm->c0 * (sound_exponent == 3.0 ? ratio * ratio * ratio
                                                           : pow(ratio, sound_exponent));
            memset(&s->tau_rho2[(size_t)i * FSI_MAT_SIZE], 0, FSI_MAT_SIZE * sizeof(double));
            memset(&s->renorm_sum[(size_t)i * FSI_MAT_SIZE], 0, FSI_MAT_SIZE * sizeof(double));
            memset(&s->density_gradient[i * FSI_DIM], 0, FSI_DIM * sizeof(double));
        }
        if (stress || antuono) {
            /* Even blocks, then odd ones (fluid_rows.h): no two running blocks share a
             * particle. Wall and solid rows write only their own sums. */
            for (int parity = 0; parity < 2; parity++) {
#pragma omp for schedule(dynamic, 1)
                for (int b = parity; b < n_blocks; b += 2)
                    gradient_block_any(nb, prm, p, u, s, start[b], start[b + 1], stress,
                                       antuono);
            }
#pragma omp for schedule(dynamic, FLUID_CHUNK)
            for (int i = 0; i < n; i++)
                if (!(p->flags[i] & FLUID_PARTICLE_FLUID) && wcsph_in_sums(prm, p, i))
                    gradient_boundary_row(nb, prm, p, u, s, i, stress, antuono);
#pragma omp for schedule(static)
            for (int i = 0; i < n; i++) {
                double *t = &s->tau_rho2[(size_t)i * FSI_MAT_SIZE];
                double grad_u[FSI_MAT_SIZE];
                memcpy(grad_u, t, sizeof grad_u);
                const double scale = stress ? prm->viscosity / (p->density[i] * p->density[i])
                                            : 0.0;
                for (int a = 0; a < FSI_DIM; a++)
                    for (int c = 0; c < FSI_DIM; c++)
                        FSI_MAT(t, a, c) =
                            scale * (FSI_MAT(grad_u, a, c) + FSI_MAT(grad_u, c, a));
                if (antuono) {
                    /* sum_J (rho_J - rho_I) L grad_I W V_J = L raw; for rho_J - rho_I =
                     * G . x_IJ, raw = B^T G = B G (B is symmetric: grad_I W is
                     * parallel to x_IJ), so it is G. */
                    double L[FSI_MAT_SIZE], raw[FSI_DIM];
                    if (fsi_mat_inverse(&s->renorm_sum[(size_t)i * FSI_MAT_SIZE], L,
                                        WCSPH_MAX_CONDITION) != 0)
                        fsi_mat_zero(L);
                    memcpy(raw, &s->density_gradient[i * FSI_DIM], sizeof raw);
                    fsi_mat_vec(L, raw, &s->density_gradient[i * FSI_DIM]);
                }
            }
        }
    }
}

/* ---- pass 3: rates ------------------------------------------------------------- */

/* What every boundary pair term reads. */
typedef struct {
    const wcsph_params *prm;
    const fluid_particles *p;
    const double *u;
    const wcsph_scratch *s;
    const wendland_c2_kernel *k;
    double eps2, contact_k_c2, contact_inv_eta_scale;
} pair_context;

static pair_context make_context(const wcsph_neighbours *nb, const wcsph_params *prm,
                                 const fluid_particles *p, const double *u,
                                 const wcsph_scratch *s)
{
    return (pair_context){prm, p, u, s, nb->kernel, 0.01 * prm->h * prm->h,
                          prm->contact * prm->c0 * prm->c0, 1.0 / (0.75 * prm->h)};
}

/* The acceleration of fluid particle I from boundary (wall or solid) particle J at
 * x_IJ = rel within the support (F = f), gravity excluded (the force on I is m_I times
 * it), and with J in the sums its continuity and diffusion terms (without delta h c0). */
static inline void boundary_pair(const pair_context *c, int i, int j, const double *rel,
                                 double r2, double f, double *out, double *div, double *diff)
{
    const fluid_particles *p = c->p;
    const wcsph_params *prm = c->prm;
    for (int d = 0; d < FSI_DIM; d++)
        out[d] = 0.0;
    *div = *diff = 0.0;
    if (wcsph_in_sums(prm, p, j)) {
        const double m_j = p->mass[j];
        const double rho_i = p->density[i], rho_j = p->density[j];
        /* a wall pushes, never pulls: max(p_I, 0) / rho_I^2 */
        const double p_i = fmax(c->s->pressure_rho2[i], 0.0);
        /* v_IJ . (x_I - x_J) = (u_J - u_I) . x_IJ */
        double vx = 0.0, cont = 0.0;
        for (int d = 0; d < FSI_DIM; d++) {
            vx += (c->u[j * FSI_DIM + d] - p->v[i * FSI_DIM + d]) * rel[d];
            cont += (p->v[j * FSI_DIM + d] - p->v[i * FSI_DIM + d]) * rel[d];
        }
        double pi_ij = 0.0;
        if (vx < 0.0) {
            const double mu = prm->h * vx / (r2 + c->eps2);
            pi_ij = (-prm->beta1 * 0.5 * (c->s->sound[i] + c->s->sound[j]) * mu +
                     prm->beta2 * mu * mu) / (0.5 * (rho_i + rho_j));
        }
        /* -m_J (P_I + P_J + pi_IJ) grad_I W = m_J (P_I + P_J + pi_IJ) F x_IJ */
        const double radial = m_j * f * (p_i + c->s->pressure_rho2[j] + pi_ij);
        for (int d = 0; d < FSI_DIM; d++)
            out[d] += radial * rel[d];
        if (prm->laplacian) {
            /* (x_I - x_J) . grad_I W = F r^2 */
            const double lap = m_j * 2.0 * prm->viscosity * f * r2 /
                               (rho_i * rho_j * (r2 + c->eps2));
            for (int d = 0; d < FSI_DIM; d++)
                out[d] += lap * (p->v[i * FSI_DIM + d] - c->u[j * FSI_DIM + d]);
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
        /* m_J (v_I - v_J) . grad_I W = m_J F (v_J - v_I) . x_IJ */
        *div = m_j * f * cont;
        const double v_f = p->volume[j] * f, drho = rho_j - rho_i;
        if (prm->antuono) {
            /* A wall or solid particle's own gradient is not the fluid's (its outer
             * layers, beyond the fluid's reach, hold rho0): the fluid particle's
             * stands in for it. psi . grad_I W = -F (2 (rho_J - rho_I) - 2 G_I . x_IJ) */
            const double *gi = &c->s->density_gradient[i * FSI_DIM];
            double proj = 0.0;
            for (int d = 0; d < FSI_DIM; d++)
                proj += 2.0 * gi[d] * rel[d];
            *diff = r2 > 0.0 ? -v_f * (2.0 * drho - proj) : 0.0;
        } else {
            /* 2 V_J (rho_I - rho_J) F r^2 / (r^2 + 0.01 h^2) */
            *diff = -2.0 * v_f * drho * r2 / (r2 + c->eps2);
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

/* The rates' sums of the fluid particles of [lo, hi): each fluid pair once, written to
 * both particles (antisymmetric terms, fluid_rows.h), each boundary pair on I's side.
 * Returns the pairs within the support. */
static FSI_ALWAYS_INLINE long long rates_block(const wcsph_neighbours *nb, const pair_context *c,
                                           double *drho_dt, double *dv_dt, double *diffusion,
                                           int lo, int hi, const int stress,
                                           const int antuono, const int periodic)
{
    const fluid_rows *rows = nb->rows;
    const fsi_periodic *per = periodic_of(nb);
    const fluid_particles *p = c->p;
    const wcsph_params *prm = c->prm;
    const wcsph_scratch *s = c->s;
    const double h = prm->h, beta1 = 0.5 * prm->beta1, beta2 = prm->beta2, eps2 = c->eps2;
    const double lap_scale = 2.0 * prm->viscosity;
    /* Local restrict pointers: the stores into J's rates cannot alias the particles'
     * fields, so the loop keeps them in registers. */
    const double *restrict xs = p->x, *restrict vs = p->v, *restrict vol = p->volume;
    const double *restrict rho = p->density, *restrict mass = p->mass;
    const double *restrict pr = s->pressure_rho2, *restrict snd = s->sound;
    const double *restrict tau = s->tau_rho2, *restrict grad = s->density_gradient;
    const double *restrict pair_f = rows->f;
    const int32_t *restrict pair = rows->pair;
    double *restrict out_v = dv_dt, *restrict out_rho = drho_dt, *restrict out_d = diffusion;
    long long pairs = 0;
    for (int i = lo; i < hi; i++) {
        if (!(p->flags[i] & FLUID_PARTICLE_FLUID))
            continue;
        const double rho_i = rho[i], m_i = mass[i], vol_i = vol[i];
        const double pr_i = pr[i], c_i = snd[i];
        double x_i[FSI_DIM], v_i[FSI_DIM], t_i[FSI_MAT_SIZE], g_i[FSI_DIM];
        for (int d = 0; d < FSI_DIM; d++) {
            x_i[d] = xs[i * FSI_DIM + d];
            v_i[d] = vs[i * FSI_DIM + d];
            g_i[d] = antuono ? grad[i * FSI_DIM + d] : 0.0;
        }
        for (int a = 0; a < FSI_MAT_SIZE; a++)
            t_i[a] = stress ? tau[(size_t)i * FSI_MAT_SIZE + a] : 0.0;
        double acc[FSI_DIM] = {0}, div = 0.0, diff = 0.0;
        const int64_t end = rows->fluid_end[i];
        pairs += end - rows->offset[i];
        /* The J of a row are distinct: its pairs are independent (as above). */
#pragma omp simd reduction(+ : acc[:FSI_DIM], div, diff)
        for (int64_t e = rows->offset[i]; e < end; e++) {
            const int j = pair[e];
            const double f = pair_f[e], rho_j = rho[j];
            double rel[FSI_DIM], dv[FSI_DIM], x[FSI_DIM], r2 = 0.0, vx = 0.0;
            for (int d = 0; d < FSI_DIM; d++)
                rel[d] = xs[j * FSI_DIM + d] - x_i[d];
            if (periodic)
                fsi_periodic_min_image(per, rel);
            for (int d = 0; d < FSI_DIM; d++) {
                r2 += rel[d] * rel[d];
                dv[d] = vs[j * FSI_DIM + d] - v_i[d];
                vx += dv[d] * rel[d];
            }
            /* 004 Eqs. 8-9: only approaching pairs (mu = 0 otherwise) */
            const double inv_r2 = 1.0 / (r2 + eps2);
            const double mu = h * (vx < 0.0 ? vx : 0.0) * inv_r2;
            const double pi_ij = (-beta1 * (c_i + snd[j]) * mu + beta2 * mu * mu) /
                                 (0.5 * (rho_i + rho_j));
            const double radial = f * (pr_i + pr[j] + pi_ij);
            for (int d = 0; d < FSI_DIM; d++)
                x[d] = radial * rel[d];
            if (stress) {
                const double *t_j = &tau[(size_t)j * FSI_MAT_SIZE];
                for (int a = 0; a < FSI_DIM; a++) {
                    double sum = 0.0;
                    for (int b = 0; b < FSI_DIM; b++)
                        sum += (FSI_MAT(t_i, a, b) + FSI_MAT(t_j, a, b)) * rel[b];
                    x[a] -= f * sum;
                }
            } else {
                const double lap = lap_scale * f * r2 * inv_r2 / (rho_i * rho_j);
                for (int d = 0; d < FSI_DIM; d++)
                    x[d] -= lap * dv[d];
            }
            const double m_j = mass[j];
            for (int d = 0; d < FSI_DIM; d++) {
                acc[d] += m_j * x[d];
                out_v[j * FSI_DIM + d] -= m_i * x[d];
            }
            const double cont = f * vx;
            div += m_j * cont;
            out_rho[j] += m_i * cont;
            const double drho = rho_j - rho_i;
            double t;
            if (antuono) {
                double proj = 0.0;
                for (int d = 0; d < FSI_DIM; d++)
                    proj += (g_i[d] + grad[j * FSI_DIM + d]) * rel[d];
                t = r2 > 0.0 ? -f * (2.0 * drho - proj) : 0.0;
            } else {
                t = -2.0 * f * drho * r2 * inv_r2;
            }
            diff += vol[j] * t;
            out_d[j] -= vol_i * t;
        }
        pairs += rows->boundary_end[i] - rows->split[i];
        for (int64_t e = rows->split[i]; e < rows->boundary_end[i]; e++) {
            const int j = pair[e];
            double rel[FSI_DIM], a[FSI_DIM], d_div, d_diff;
            const double r2 = fluid_pair_vector_r2(per, xs, i, j, rel);
            boundary_pair(c, i, j, rel, r2, pair_f[e], a, &d_div, &d_diff);
            for (int d = 0; d < FSI_DIM; d++)
                acc[d] += a[d];
            div += d_div;
            diff += d_diff;
        }
        for (int d = 0; d < FSI_DIM; d++)
            out_v[i * FSI_DIM + d] += acc[d];
        out_rho[i] += div;
        out_d[i] += diff;
    }
    return pairs;
}

static long long rates_block_any(const wcsph_neighbours *nb, const pair_context *c,
                                 double *drho_dt, double *dv_dt, double *diffusion, int lo,
                                 int hi)
{
    const int stress = !c->prm->laplacian, antuono = c->prm->antuono;
    if (periodic_of(nb)) /* the same code with each choice a constant */
        return rates_block(nb, c, drho_dt, dv_dt, diffusion, lo, hi, stress, antuono, 1);
    if (stress && antuono)
        return rates_block(nb, c, drho_dt, dv_dt, diffusion, lo, hi, 1, 1, 0);
    if (stress)
        return rates_block(nb, c, drho_dt, dv_dt, diffusion, lo, hi, 1, 0, 0);
    if (antuono)
        return rates_block(nb, c, drho_dt, dv_dt, diffusion, lo, hi, 0, 1, 0);
    return rates_block(nb, c, drho_dt, dv_dt, diffusion, lo, hi, 0, 0, 0);
}

void wcsph_rates(const wcsph_neighbours *nb, const wcsph_params *prm, const fluid_particles *p,
                 const double *u, wcsph_scratch *s, double *drho_dt, double *dv_dt)
{
    const pair_context c = make_context(nb, prm, p, u, s);
    const double scale = prm->delta * prm->h * prm->c0;
    const int n = p->n, n_blocks = nb->rows->n_blocks;
    const int *start = nb->rows->block_start;
    double *diffusion = s->diffusion;
    long long pairs = 0;
#pragma omp parallel if (n >= FLUID_PARALLEL_MIN_PARTICLES)
    {
#pragma omp for schedule(static)
        for (int i = 0; i < n; i++) {
            drho_dt[i] = diffusion[i] = 0.0;
            memset(&dv_dt[i * FSI_DIM], 0, FSI_DIM * sizeof *dv_dt);
        }
        /* Even blocks, then odd ones (fluid_rows.h). */
        for (int parity = 0; parity < 2; parity++) {
#pragma omp for schedule(dynamic, 1) reduction(+ : pairs)
            for (int b = parity; b < n_blocks; b += 2)
                pairs += rates_block_any(nb, &c, drho_dt, dv_dt, diffusion, start[b],
                                         start[b + 1]);
        }
#pragma omp for schedule(static)
        for (int i = 0; i < n; i++) {
            if (!(p->flags[i] & FLUID_PARTICLE_FLUID))
                continue;
            drho_dt[i] += scale * diffusion[i];
            for (int d = 0; d < FSI_DIM; d++)
                dv_dt[i * FSI_DIM + d] += prm->gravity[d];
        }
    }
    /* directed pairs, as the other schemes count them */
    s->pairs = 2 * pairs;
}

/* ---- reference sums and loads ---------------------------------------------------- */

void wcsph_density_diffusion(const wcsph_neighbours *nb, const wcsph_params *prm,
                             const fluid_particles *p, const wcsph_scratch *s, double *out)
{
    const pair_context c = make_context(nb, prm, p, NULL, s);
    const fluid_verlet *list = nb->list;
    const fsi_periodic *per = periodic_of(nb);
    const double scale = prm->delta * prm->h * prm->c0;
    const int n = p->n;
#pragma omp parallel for schedule(dynamic, FLUID_CHUNK) if (n >= FLUID_PARALLEL_MIN_PARTICLES)
    for (int i = 0; i < n; i++) {
        double sum = 0.0;
        for (int64_t e = list->offset[i];
             (p->flags[i] & FLUID_PARTICLE_FLUID) && e < list->offset[i + 1]; e++) {
            const int j = list->candidate[e];
            double rel[FSI_DIM];
            const double r2 = fluid_pair_vector_r2(per, p->x, i, j, rel);
            if (!(r2 < nb->kernel->support2) || !wcsph_in_sums(prm, p, j))
                continue;
            const double f = wendland_c2_f_inside(nb->kernel, r2), drho = p->density[j] - p->density[i];
            const double *gi = &s->density_gradient[i * FSI_DIM];
            const double *gj = (p->flags[j] & FLUID_PARTICLE_FLUID)
                                   ? &s->density_gradient[j * FSI_DIM] : gi;
            double proj = 0.0;
            for (int d = 0; d < FSI_DIM; d++)
                proj += (gi[d] + gj[d]) * rel[d];
            if (prm->antuono)
                sum += r2 > 0.0 ? -p->volume[j] * f * (2.0 * drho - proj) : 0.0;
            else
                sum += -2.0 * p->volume[j] * f * drho * r2 / (r2 + c.eps2);
        }
        out[i] = scale * sum;
    }
}

void wcsph_boundary_loads(const wcsph_neighbours *nb, const wcsph_params *prm,
                          const fluid_particles *p, const double *u, const wcsph_scratch *s,
                          double *force)
{
    const pair_context c = make_context(nb, prm, p, u, s);
    const fluid_verlet *list = nb->list;
    const fsi_periodic *per = periodic_of(nb);
    const int n = p->n;
#pragma omp parallel for schedule(dynamic, FLUID_CHUNK) if (n >= FLUID_PARALLEL_MIN_PARTICLES)
    for (int b = 0; b < n; b++) {
        double *f_b = &force[b * FSI_DIM];
        memset(f_b, 0, FSI_DIM * sizeof *f_b);
        if (!(p->flags[b] & FLUID_PARTICLE_MOVING_BOUNDARY))
            continue;
        for (int64_t e = list->offset[b]; e < list->offset[b + 1]; e++) {
            const int i = list->candidate[e];
            if (!(p->flags[i] & FLUID_PARTICLE_FLUID))
                continue;
            /* the pair as I's row sees it */
            double rel[FSI_DIM], a[FSI_DIM], d_div, d_diff;
            const double r2 = fluid_pair_vector_r2(per, p->x, i, b, rel);
            if (!(r2 < nb->kernel->support2))
                continue;
            boundary_pair(&c, i, b, rel, r2, wendland_c2_f_inside(nb->kernel, r2), a, &d_div, &d_diff);
            for (int d = 0; d < FSI_DIM; d++)
                f_b[d] -= p->mass[i] * a[d];
        }
    }
}

void wcsph_gradient(const wcsph_neighbours *nb, const wcsph_params *prm,
                    const fluid_particles *p, const double *f, double *grad)
{
    const fluid_verlet *list = nb->list;
    const fsi_periodic *per = periodic_of(nb);
    const int n = p->n;
#pragma omp parallel for schedule(dynamic, FLUID_CHUNK) if (n >= FLUID_PARALLEL_MIN_PARTICLES)
    for (int i = 0; i < n; i++) {
        double b[FSI_MAT_SIZE], L[FSI_MAT_SIZE], raw[FSI_DIM] = {0};
        fsi_mat_zero(b);
        for (int64_t e = list->offset[i]; e < list->offset[i + 1]; e++) {
            const int j = list->candidate[e];
            double rel[FSI_DIM];
            const double r2 = fluid_pair_vector_r2(per, p->x, i, j, rel);
            if (!(r2 < nb->kernel->support2) || !wcsph_in_sums(prm, p, j))
                continue;
            /* V_J grad_I W_IJ = -V_J F x_IJ */
            const double vf = -p->volume[j] * wendland_c2_f_inside(nb->kernel, r2);
            double gw[FSI_DIM];
            for (int d = 0; d < FSI_DIM; d++) {
                gw[d] = vf * rel[d];
                raw[d] += (f[j] - f[i]) * gw[d];
            }
            fsi_mat_add_outer(b, 1.0, rel, gw);
        }
        if (fsi_mat_inverse(b, L, WCSPH_MAX_CONDITION) != 0)
            fsi_mat_zero(L);
        fsi_mat_vec(L, raw, &grad[i * FSI_DIM]);
    }
}
