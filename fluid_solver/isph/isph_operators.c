/* ISPH's operators (isph_operators.h). Every loop runs over particles in parallel, each
 * writing only its own entries, so results are the same on any thread count. */
#include "isph_operators.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "fluid_parallel.h"
#include "grow.h"
#include "small_tensor.h"
#include "soft_contact.h"

/* B_a is taken when its condition number stays below this; beyond it (a particle with
 * its neighbours nearly on a line) the uncorrected gradient is used. */
#define ISPH_B_MAX_CONDITION 50.0
/* Fewer neighbours than this and a fluid particle is splash. */
#define ISPH_SPLASH_NEIGHBOURS (FSI_DIM + 2)

void isph_fields_init(isph_fields *f)
{
    *f = (isph_fields){0};
}

void isph_fields_free(isph_fields *f)
{
    free(f->b);
    free(f->div_r);
    free(f->alpha);
    free(f->where);
    free(f->normal);
    free(f->v_visc);
    free(f->sum_w);
    free(f->grad_u);
    free(f->nu);
    free(f->solid_normal);
    isph_fields_init(f);
}

int isph_fields_reserve(isph_fields *f, int n)
{
    if (n <= f->capacity && f->b)
        return 0;
    const size_t cap = fsi_grown_capacity((size_t)n), vec = cap * FSI_DIM * sizeof(double);
    int failed = 0;
    f->b = fsi_grow(f->b, cap * FSI_MAT_SIZE * sizeof(double), &failed);
    f->div_r = fsi_grow(f->div_r, cap * sizeof(double), &failed);
    f->alpha = fsi_grow(f->alpha, cap * sizeof(double), &failed);
    f->where = fsi_grow(f->where, cap, &failed);
    f->normal = fsi_grow(f->normal, vec, &failed);
    f->v_visc = fsi_grow(f->v_visc, vec, &failed);
    f->sum_w = fsi_grow(f->sum_w, cap * sizeof(double), &failed);
    f->grad_u = fsi_grow(f->grad_u, cap * FSI_MAT_SIZE * sizeof(double), &failed);
    f->nu = fsi_grow(f->nu, cap * sizeof(double), &failed);
    f->solid_normal = fsi_grow(f->solid_normal, vec, &failed);
    if (failed)
        return -1;
    f->capacity = (int)cap;
    return 0;
}

static int is_fluid(const fluid_particles *p, int i)
{
    return (p->flags[i] & FLUID_PARTICLE_FLUID) != 0;
}

/* free_slip covers the fixed particles only: ask it about fixed walls alone. */
static int slip_wall(const fluid_particles *p, const unsigned char *free_slip, int i)
{
    return free_slip && (p->flags[i] & FLUID_PARTICLE_WALL) && free_slip[i];
}

void isph_geometry(const isph_pairs *q, const fluid_particles *p, isph_fields *f)
{
    const int n = p->n;
#pragma omp parallel for schedule(static) if (n >= FLUID_PARALLEL_MIN_PARTICLES)
    for (int i = 0; i < n; i++) {
        double *b = &f->b[i * FSI_MAT_SIZE];
        fsi_mat_identity(b);
        f->div_r[i] = 0.0;
        if (!is_fluid(p, i))
            continue;
        /* sum_b V_b (x_b - x_a) (x) grad_a W_ab = -sum_b V_b F x_ab (x) x_ab */
        double m[FSI_MAT_SIZE] = {0};
        for (int64_t e = q->start[i]; e < q->start[i + 1]; e++) {
            const double *x = &q->xij[e * FSI_DIM];
            fsi_mat_add_outer(m, -p->volume[q->j[e]] * q->f[e], x, x);
        }
        f->div_r[i] = fsi_mat_trace(m);
        double inv[FSI_MAT_SIZE];
        if (f->correct && fsi_mat_inverse(m, inv, ISPH_B_MAX_CONDITION) == 0)
            fsi_mat_copy(inv, b);
    }
}

/* 003 Eq. 17 with the pi the extraction lost. */
static double skillen_alpha(double div_r, double lower, double upper)
{
    if (div_r >= upper)
        return 1.0;
    if (div_r <= lower)
        return 0.0;
    return 0.5 * (1.0 - cos(M_PI * (div_r - lower) / (upper - lower)));
}

void isph_free_surface(const isph_pairs *q, const fluid_particles *p, const unsigned char *held,
                       double lower, double upper, double h, isph_fields *f)
{
    const int n = p->n;
#pragma omp parallel for schedule(static) if (n >= FLUID_PARALLEL_MIN_PARTICLES)
    for (int i = 0; i < n; i++) {
        double *nrm = &f->normal[i * FSI_DIM];
        memset(nrm, 0, FSI_DIM * sizeof *nrm);
        f->alpha[i] = 0.0;
        f->where[i] = ISPH_INTERIOR;
        if (!is_fluid(p, i))
            continue;
        /* too few neighbours for a gradient, or none of them fluid (a particle that
         * has entered a wall: its Poisson equation would close on the wall's alone) */
        int fluid_neighbours = 0;
        for (int64_t e = q->start[i]; e < q->start[i + 1]; e++)
            fluid_neighbours += is_fluid(p, q->j[e]);
        if (q->start[i + 1] - q->start[i] < ISPH_SPLASH_NEIGHBOURS || fluid_neighbours == 0) {
            f->where[i] = ISPH_SPLASH;
            continue;
        }
        f->alpha[i] = skillen_alpha(f->div_r[i], lower, upper);
        if (f->div_r[i] > lower)
            continue;
        f->where[i] = ISPH_SURFACE;
        /* 003 Eqs. 25-26: n = -grad Psi / |grad Psi|, grad Psi = sum_b V_b B_a grad W */
        double g[FSI_DIM] = {0}, bg[FSI_DIM];
        for (int64_t e = q->start[i]; e < q->start[i + 1]; e++)
            for (int d = 0; d < FSI_DIM && !(held && held[q->j[e]]); d++)
                g[d] -= p->volume[q->j[e]] * q->f[e] * q->xij[e * FSI_DIM + d];
        fsi_mat_vec(&f->b[i * FSI_MAT_SIZE], g, bg);
        const double len = fsi_vec_norm(bg);
        if (len > 0.0)
            for (int d = 0; d < FSI_DIM; d++)
                nrm[d] = -bg[d] / len;
    }
    /* Near-surface particles take the normal of their nearest surface neighbour within
     * h (003 §2.1, after Fig. 2). */
    const double h2 = h * h;
#pragma omp parallel for schedule(static) if (n >= FLUID_PARALLEL_MIN_PARTICLES)
    for (int i = 0; i < n; i++) {
        if (!is_fluid(p, i) || f->where[i] != ISPH_INTERIOR)
            continue;
        double best = h2;
        int nearest = -1;
        for (int64_t e = q->start[i]; e < q->start[i + 1]; e++) {
            const int j = q->j[e];
            if (!is_fluid(p, j) || f->where[j] != ISPH_SURFACE)
                continue;
            const double r2 = fsi_vec_dot(&q->xij[e * FSI_DIM], &q->xij[e * FSI_DIM]);
            if (r2 < best) {
                best = r2;
                nearest = j;
            }
        }
        if (nearest >= 0) {
            f->where[i] = ISPH_NEAR_SURFACE;
            memcpy(&f->normal[i * FSI_DIM], &f->normal[nearest * FSI_DIM],
                   FSI_DIM * sizeof(double));
        }
    }
}

void isph_wall_velocity(const isph_pairs *q, const fluid_particles *p,
                        const unsigned char *free_slip, isph_fields *f)
{
    const int n = p->n;
#pragma omp parallel for schedule(static) if (n >= FLUID_PARALLEL_MIN_PARTICLES)
    for (int i = 0; i < n; i++) {
        const double *v = &p->v[i * FSI_DIM];
        double *vv = &f->v_visc[i * FSI_DIM], *sn = &f->solid_normal[i * FSI_DIM];
        memcpy(vv, v, FSI_DIM * sizeof *vv);
        memset(sn, 0, FSI_DIM * sizeof *sn);
        f->sum_w[i] = 0.0;
        if (is_fluid(p, i)) {
            /* the direction from the nearest solid particle (003 Eqs. 27-30's normal) */
            double best = INFINITY;
            for (int64_t e = q->start[i]; e < q->start[i + 1]; e++) {
                if (!(p->flags[q->j[e]] & FLUID_PARTICLE_MOVING_BOUNDARY))
                    continue;
                const double *x = &q->xij[e * FSI_DIM];
                const double r2 = fsi_vec_dot(x, x);
                if (r2 < best && r2 > 0.0) {
                    best = r2;
                    for (int d = 0; d < FSI_DIM; d++)
                        sn[d] = -x[d] / sqrt(r2);
                }
            }
            continue;
        }
        double sw = 0.0, mean[FSI_DIM] = {0};
        for (int64_t e = q->start[i]; e < q->start[i + 1]; e++) {
            const int j = q->j[e];
            if (!is_fluid(p, j))
                continue;
            sw += q->w[e];
            for (int d = 0; d < FSI_DIM; d++)
                mean[d] += q->w[e] * p->v[j * FSI_DIM + d];
        }
        f->sum_w[i] = sw;
        if (sw > 0.0 && !slip_wall(p, free_slip, i))
            for (int d = 0; d < FSI_DIM; d++)
                vv[d] = 2.0 * v[d] - mean[d] / sw;  /* no-slip, Adami et al. 2012 */
    }
}

void isph_velocity_gradient(const isph_pairs *q, const fluid_particles *p, double nu0,
                            double cs, double h, isph_fields *f)
{
    const int n = p->n;
    const double l2 = cs * h * cs * h;
#pragma omp parallel for schedule(static) if (n >= FLUID_PARALLEL_MIN_PARTICLES)
    for (int i = 0; i < n; i++) {
        double *g = &f->grad_u[i * FSI_MAT_SIZE];
        fsi_mat_zero(g);
        f->nu[i] = nu0;
        if (!is_fluid(p, i))
            continue;
        /* 003 Eq. 3 on each component: sum_b V_b (u_b - u_a) (x) (B_a grad_a W_ab) */
        double raw[FSI_MAT_SIZE] = {0};
        const double *ua = &f->v_visc[i * FSI_DIM];
        for (int64_t e = q->start[i]; e < q->start[i + 1]; e++) {
            const int j = q->j[e];
            double du[FSI_DIM], gw[FSI_DIM];
            for (int d = 0; d < FSI_DIM; d++) {
                du[d] = f->v_visc[j * FSI_DIM + d] - ua[d];
                gw[d] = -q->f[e] * q->xij[e * FSI_DIM + d];
            }
            fsi_mat_add_outer(raw, p->volume[j], du, gw);
        }
        /* (du (x) gw) B^T = du (x) (B gw) */
        fsi_mat_mul_transpose(raw, &f->b[i * FSI_MAT_SIZE], g);
        double s[FSI_MAT_SIZE];
        fsi_mat_sym(g, s);
        f->nu[i] = nu0 + l2 * sqrt(2.0 * fsi_mat_ddot(s, s));   /* 003 Eq. 10 */
    }
}

/* The soft contact's factor for fluid particle a and wall or solid particle s at
 * distance r (soft_contact.h), 0 without contact. */
static double contact_factor(const isph_contact *c, const fluid_particles *p, int s, double r)
{
    if (!c || !(c->k_c2 > 0.0))
        return 0.0;
    const double dx = 0.5 * (p->spacing + fluid_particle_side(p->volume[s]));
    return soft_contact_factor(r, dx, c->k_c2, c->inv_eta_scale);
}

void isph_viscous_acceleration(const isph_pairs *q, const fluid_particles *p,
                               const unsigned char *free_slip, const isph_fields *f,
                               const isph_contact *contact, double *acc)
{
    const int n = p->n;
#pragma omp parallel for schedule(static) if (n >= FLUID_PARALLEL_MIN_PARTICLES)
    for (int i = 0; i < n; i++) {
        double *a = &acc[i * FSI_DIM];
        memset(a, 0, FSI_DIM * sizeof *a);
        if (!is_fluid(p, i))
            continue;
        const double *ua = &p->v[i * FSI_DIM];
        for (int64_t e = q->start[i]; e < q->start[i + 1]; e++) {
            const int j = q->j[e];
            if (!is_fluid(p, j)) {
                const double *x = &q->xij[e * FSI_DIM];
                const double k = contact_factor(contact, p, j, sqrt(fsi_vec_dot(x, x)));
                for (int d = 0; d < FSI_DIM; d++)
                    a[d] -= k * x[d];   /* away from j: x_a - x_j = -x */
            }
            if (slip_wall(p, free_slip, j))
                continue;
            const double c = p->volume[j] * (f->nu[i] + f->nu[j]) * q->f[e];
            for (int d = 0; d < FSI_DIM; d++)
                a[d] += c * (ua[d] - f->v_visc[j * FSI_DIM + d]);
        }
    }
}

void isph_pressure_acceleration(const isph_pairs *q, const fluid_particles *p,
                                const unsigned char *held, double rho0, double *acc)
{
    const int n = p->n;
    const double r = 1.0 / rho0;
#pragma omp parallel for schedule(static) if (n >= FLUID_PARALLEL_MIN_PARTICLES)
    for (int i = 0; i < n; i++) {
        if (!is_fluid(p, i))
            continue;
        double a[FSI_DIM] = {0};
        for (int64_t e = q->start[i]; e < q->start[i + 1]; e++) {
            const int j = q->j[e];
            if (held && held[j])
                continue;
            /* -(p_a + p_b) grad_a W_ab = (p_a + p_b) F x_ab */
            const double c = p->volume[j] * (p->pressure[i] + p->pressure[j]) * q->f[e];
            for (int d = 0; d < FSI_DIM; d++)
                a[d] += c * q->xij[e * FSI_DIM + d];
        }
        for (int d = 0; d < FSI_DIM; d++)
            acc[i * FSI_DIM + d] += r * a[d];
    }
}

void isph_scalar_gradient(const isph_pairs *q, const fluid_particles *p, const isph_fields *f,
                          const double *s, double *grad)
{
    const int n = p->n;
#pragma omp parallel for schedule(static) if (n >= FLUID_PARALLEL_MIN_PARTICLES)
    for (int i = 0; i < n; i++) {
        double g[FSI_DIM] = {0};
        if (is_fluid(p, i))
            for (int64_t e = q->start[i]; e < q->start[i + 1]; e++) {
                const int j = q->j[e];
                const double c = -p->volume[j] * (s[j] - s[i]) * q->f[e];
                for (int d = 0; d < FSI_DIM; d++)
                    g[d] += c * q->xij[e * FSI_DIM + d];
            }
        fsi_mat_vec(&f->b[i * FSI_MAT_SIZE], g, &grad[i * FSI_DIM]);
        if (!is_fluid(p, i))
            memset(&grad[i * FSI_DIM], 0, FSI_DIM * sizeof *grad);
    }
}

void isph_pressure_loads(const isph_pairs *q, const fluid_particles *p,
                         const unsigned char *held, double *force)
{
    const int n = p->n;
#pragma omp parallel for schedule(static) if (n >= FLUID_PARALLEL_MIN_PARTICLES)
    for (int s = 0; s < n; s++) {
        double *out = &force[s * FSI_DIM];
        memset(out, 0, FSI_DIM * sizeof *out);
        if (!(p->flags[s] & FLUID_PARTICLE_MOVING_BOUNDARY) || (held && held[s]))
            continue;
        for (int64_t e = q->start[s]; e < q->start[s + 1]; e++) {
            const int a = q->j[e];
            if (!is_fluid(p, a))
                continue;
            /* a gets V_a V_s (p_a + p_s) F x_as from s; seen from s's row x_sa = -x_as */
            const double c = p->volume[a] * p->volume[s] * q->f[e] *
                             (p->pressure[a] + p->pressure[s]);
            for (int d = 0; d < FSI_DIM; d++)
                out[d] += c * q->xij[e * FSI_DIM + d];
        }
    }
}

void isph_viscous_loads(const isph_pairs *q, const fluid_particles *p, const isph_fields *f,
                        const isph_contact *contact, double rho0, double *force)
{
    const int n = p->n;
#pragma omp parallel for schedule(static) if (n >= FLUID_PARALLEL_MIN_PARTICLES)
    for (int s = 0; s < n; s++) {
        double *out = &force[s * FSI_DIM];
        memset(out, 0, FSI_DIM * sizeof *out);
        if (!(p->flags[s] & FLUID_PARTICLE_MOVING_BOUNDARY))
            continue;
        for (int64_t e = q->start[s]; e < q->start[s + 1]; e++) {
            const int a = q->j[e];
            if (!is_fluid(p, a))
                continue;
            /* a gets rho0 V_a V_s (nu_a + nu_s) F (u_a - u_s) from s, and the contact
             * rho0 V_a k (x_a - x_s), x_a - x_s = x seen from s's row */
            const double *x = &q->xij[e * FSI_DIM];
            const double c = rho0 * p->volume[a] * p->volume[s] * q->f[e] * (f->nu[a] + f->nu[s]);
            const double k = rho0 * p->volume[a] *
                             contact_factor(contact, p, s, sqrt(fsi_vec_dot(x, x)));
            for (int d = 0; d < FSI_DIM; d++)
                out[d] -= c * (p->v[a * FSI_DIM + d] - f->v_visc[s * FSI_DIM + d]) + k * x[d];
        }
    }
}
