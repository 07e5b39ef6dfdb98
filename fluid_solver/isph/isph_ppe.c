/* The pressure Poisson equation (isph_ppe.h): the coefficients of every row in parallel
 * into per-pair storage, then the rows appended in order, the preconditioner, the
 * solve. */
#include "isph_ppe.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fluid_parallel.h"
#include "fluid_state.h"
#include "grow.h"
#include "permute_rows.h"
#include "small_tensor.h"

#define ISPH_GMRES_RESTART 30
/* Solves per projection at most while the walls' active set changes. */
#define ISPH_WALL_PASSES 4
/* The surface condition's diagonal below which it falls back to p = 0. */
#define ISPH_SURFACE_MIN_DIAGONAL 0.25

void isph_ppe_init(isph_ppe *s, fsi_krylov_settings settings, fsi_precond_kind preconditioner,
                   int gmres, double surface_offset)
{
    memset(s, 0, sizeof *s);
    s->settings = settings;
    s->preconditioner = preconditioner;
    s->gmres = gmres;
    s->surface_offset = surface_offset;
    fsi_csr_init(&s->a);
    fsi_precond_init(&s->m);
}

void isph_ppe_free(isph_ppe *s)
{
    fsi_csr_free(&s->a);
    fsi_precond_free(&s->m);
    free(s->rhs);
    free(s->coef);
    free(s->diag);
    free(s->cols);
    free(s->vals);
    free(s->held);
    isph_ppe_init(s, s->settings, s->preconditioner, s->gmres, s->surface_offset);
}

static int reserve(isph_ppe *s, const isph_pairs *q, int n)
{
    int failed = 0;
    if (n > s->capacity || !s->rhs) {
        const size_t cap = fsi_grown_capacity((size_t)n);
        s->rhs = fsi_grow(s->rhs, cap * sizeof *s->rhs, &failed);
        s->diag = fsi_grow(s->diag, cap * sizeof *s->diag, &failed);
        if (failed)
            return -1;
        s->capacity = (int)cap;
    }
    const int64_t pairs = q->start[n];
    if (pairs > s->coef_capacity || !s->coef) {
        const size_t cap = fsi_grown_capacity((size_t)(pairs > 0 ? pairs : 1));
        s->coef = fsi_grow(s->coef, cap * sizeof *s->coef, &failed);
        if (failed)
            return -1;
        s->coef_capacity = (int64_t)cap;
    }
    int64_t longest = 0;
    for (int i = 0; i < n; i++)
        if (q->start[i + 1] - q->start[i] > longest)
            longest = q->start[i + 1] - q->start[i];
    if (longest + 1 > s->row_capacity || !s->cols) {
        const size_t cap = fsi_grown_capacity((size_t)longest + 1);
        s->cols = fsi_grow(s->cols, cap * sizeof *s->cols, &failed);
        s->vals = fsi_grow(s->vals, cap * sizeof *s->vals, &failed);
        if (failed)
            return -1;
        s->row_capacity = (int)cap;
    }
    return 0;
}

/* The mass of solid particle j in the equation when its inertia is in it (last_load
 * set), else 0: rho_S V_S, times the structure's depth behind it in its own spacings
 * when inertia_depth is set. */
static double solid_mass(const isph_ppe *s, const fluid_particles *p, int j)
{
    if (!s->last_load || !(p->flags[j] & FLUID_PARTICLE_MOVING_BOUNDARY))
        return 0.0;
    const double mass = p->boundary_density[j] * p->volume[j];
    if (!(s->inertia_depth > 0.0))
        return mass;
    return mass * fmax(1.0, s->inertia_depth / fluid_particle_side(p->volume[j]));
}

/* Component d of the acceleration of wall or solid particle j without the fluid's last
 * load when its inertia is in the equation (boundary_row), as received otherwise. */
static double own_acceleration(const isph_ppe *s, const fluid_particles *p, int j, int d)
{
    const double a = p->boundary_acceleration[j * FSI_DIM + d];
    const double mass = solid_mass(s, p, j);
    return mass > 0.0 ? a - s->last_load[j * FSI_DIM + d] / mass : a;
}

static void zero_row(isph_ppe *s, const isph_pairs *q, int i)
{
    s->diag[i] = 1.0;
    s->rhs[i] = 0.0;
    for (int64_t e = q->start[i]; e < q->start[i + 1]; e++)
        s->coef[e] = 0.0;
}

/* B_a grad_a W_ab of pair e of row i. */
static void corrected_gradient(const isph_pairs *q, const isph_fields *f, int i, int64_t e,
                               double *bg)
{
    double gw[FSI_DIM];
    for (int d = 0; d < FSI_DIM; d++)
        gw[d] = -q->f[e] * q->xij[e * FSI_DIM + d];
    fsi_mat_vec(&f->b[i * FSI_MAT_SIZE], gw, bg);
}

/* Row i of a fluid particle, scaled to a unit diagonal: alpha_a times the Poisson
 * equation (003 Eqs. 15-16) plus (1 - alpha_a) times the free-surface condition at
 * offset outside the particle along its normal n, p_a + offset n . <grad p>_a = 0 with
 * 003 Eq. 2's gradient (p = 0 when offset is 0 or the particle has no normal). */
static void fluid_row(isph_ppe *s, const isph_pairs *q, const fluid_particles *p,
                      const isph_fields *f, const double *u_star, double dt, double rho0,
                      const double *gravity, double offset, int i)
{
    const double alpha = f->alpha[i];
    if (f->where[i] == ISPH_SPLASH) {
        zero_row(s, q, i);
        return;
    }
    const double *ui = &u_star[i * FSI_DIM];
    double diag = 0.0, div = 0.0;
    for (int64_t e = q->start[i]; e < q->start[i + 1]; e++) {
        const int j = q->j[e];
        const double *x = &q->xij[e * FSI_DIM];
        double bg[FSI_DIM];
        corrected_gradient(q, f, i, e, bg);
        /* x_ab = -x (x = x_b - x_a) */
        /* a pair of the wrong sign (B_a far from the identity at a cut support) is
         * dropped: every row keeps negative neighbours summing to minus its diagonal,
         * which keeps the matrix an M-matrix and the Krylov solve robust */
        const double c =
            fmin(0.0, -2.0 * p->volume[j] * fsi_vec_dot(x, bg) / (rho0 * fsi_vec_dot(x, x)));
        diag += c;
        s->coef[e] = -c;
        /* a wall or solid particle: u*_S = v_S + dt (g - a_S), v_S its velocity at
         * t + dt and a_S the received acceleration that took it there (for a solid,
         * the fluid's last load included). Corrected by its row's gradient
         * rho0 (g - a'), a' = a_int + F_S(p) / m_S for a solid in the equation, it
         * ends at v_S(t) + dt a': the load counted once. With a_int in place of a_S
         * it would end at v_S(t) + dt (a_S + F_S / m_S), the load counted twice, and
         * water on a floor at rest would follow it down (docs/isph.md). */
        double uj[FSI_DIM];
        for (int d = 0; d < FSI_DIM; d++)
            uj[d] = (p->flags[j] & FLUID_PARTICLE_FLUID)
                        ? u_star[j * FSI_DIM + d]
                        : p->v[j * FSI_DIM + d] +
                              dt * (gravity[d] - p->boundary_acceleration[j * FSI_DIM + d]);
        for (int d = 0; d < FSI_DIM; d++)
            div += p->volume[j] * (uj[d] - ui[d]) * bg[d];
    }
    if (!(fabs(diag) > 0.0) || !(alpha > 0.0 || offset > 0.0)) {
        zero_row(s, q, i);
        return;
    }
    const double scale = 1.0 / diag;
    s->diag[i] = 1.0;
    s->rhs[i] = alpha * scale * div / dt;
    for (int64_t e = q->start[i]; e < q->start[i + 1]; e++)
        s->coef[e] *= alpha * scale;
    if (alpha >= 1.0)
        return;
    /* the surface condition's row: 1 - sum_b t_b on the diagonal, t_b off it,
     * t_b = offset V_b n . B_a grad_a W_ab (negative for a neighbour inside; the few
     * positive ones of a tilted normal are dropped, as above) */
    const double *n = &f->normal[i * FSI_DIM];
    if (!(offset > 0.0) || !(fsi_vec_dot(n, n) > 0.0))
        return;     /* (1 - alpha) p_a = 0 */
    double robin = 1.0;
    for (int64_t e = q->start[i]; e < q->start[i + 1]; e++) {
        if (s->held[q->j[e]])
            continue;   /* a dry wall's p = 0 is not the water's */
        double bg[FSI_DIM];
        corrected_gradient(q, f, i, e, bg);
        robin -= fmin(0.0, offset * p->volume[q->j[e]] * fsi_vec_dot(n, bg));
    }
    /* a weak diagonal (a particle whose neighbours lie along its normal): p = 0 */
    if (!(robin > ISPH_SURFACE_MIN_DIAGONAL))
        return;
    for (int64_t e = q->start[i]; e < q->start[i + 1]; e++) {
        if (s->held[q->j[e]])
            continue;
        double bg[FSI_DIM];
        corrected_gradient(q, f, i, e, bg);
        s->coef[e] += (1.0 - alpha) * fmin(0.0, offset * p->volume[q->j[e]] * fsi_vec_dot(n, bg)) /
                      robin;
    }
}

/* Row i of a wall or solid particle: Adami et al. 2012, Eq. 27, between unknowns,
 * scaled to a unit diagonal. A solid particle of known mass m_S (isph_ppe_inertia) has
 * its acceleration in the condition taken implicitly, a_S = a_int + F_S(p) / m_S, F_S
 * the pressure pair terms' reaction on it (isph_pressure_loads), a_int its received
 * acceleration without the load of the last step: the fluid then moves the interface
 * with the structure's inertia inside the solve (003 §2.3's structure particles as
 * unknowns), the remedy of the added-mass instability of explicit coupling. */
static void boundary_row(isph_ppe *s, const isph_pairs *q, const fluid_particles *p,
                         const isph_fields *f, double rho0, const double *gravity, int i)
{
    s->diag[i] = 1.0;
    s->rhs[i] = 0.0;
    const double sw = f->sum_w[i];
    const double mass = solid_mass(s, p, i);
    const int implicit = mass > 0.0;
    double g_rel[FSI_DIM], lever[FSI_DIM] = {0};
    for (int d = 0; d < FSI_DIM; d++)
        g_rel[d] = gravity[d] - own_acceleration(s, p, i, d);
    for (int64_t e = q->start[i]; e < q->start[i + 1]; e++) {
        const int j = q->j[e];
        if (!(sw > 0.0) || !(p->flags[j] & FLUID_PARTICLE_FLUID)) {
            s->coef[e] = 0.0;
            continue;
        }
        const double w = q->w[e] / sw;
        s->coef[e] = -w;
        for (int d = 0; d < FSI_DIM; d++)
            lever[d] -= w * q->xij[e * FSI_DIM + d];                /* x_S - x_f */
    }
    s->rhs[i] = rho0 * fsi_vec_dot(g_rel, lever);
    if (!implicit || !(sw > 0.0))
        return;
    /* + (rho0 / m_S) lever . F_S(p), F_S = sum_a V_a V_S F (p_a + p_S) x_Sa */
    double diag = 1.0;
    for (int64_t e = q->start[i]; e < q->start[i + 1]; e++) {
        const int j = q->j[e];
        if (!(p->flags[j] & FLUID_PARTICLE_FLUID))
            continue;
        const double c = rho0 / mass * p->volume[j] * p->volume[i] * q->f[e] *
                         fsi_vec_dot(lever, &q->xij[e * FSI_DIM]);
        s->coef[e] += c;
        diag += c;
    }
    if (!(diag > 0.0))
        return;     /* cannot happen for a wetted face; keep the explicit row's sense */
    for (int64_t e = q->start[i]; e < q->start[i + 1]; e++)
        s->coef[e] /= diag;
    s->rhs[i] /= diag;
}

/* Rows of every particle (walls held at p = 0 get p = 0); the number of rows without a
 * Poisson part, i.e. at p = 0 in effect. */
static int assemble(isph_ppe *s, const isph_pairs *q, const fluid_particles *p,
                    const isph_fields *f, const double *u_star, double dt, double rho0,
                    const double *gravity)
{
    const int n = p->n;
    int dirichlet = 0;
#pragma omp parallel for schedule(static) reduction(+ : dirichlet) \
    if (n >= FLUID_PARALLEL_MIN_PARTICLES)
    for (int i = 0; i < n; i++) {
        if (p->flags[i] & FLUID_PARTICLE_FLUID) {
            fluid_row(s, q, p, f, u_star, dt, rho0, gravity, s->surface_offset, i);
            dirichlet += !(f->alpha[i] > 0.0) || f->where[i] == ISPH_SPLASH;
        } else if (s->held[i]) {
            zero_row(s, q, i);
        } else {
            boundary_row(s, q, p, f, rho0, gravity, i);
        }
    }
    return dirichlet;
}

/* The walls' active set: a wall or solid particle whose pressure came out negative is
 * held at 0 and the equation solved again ("a wall pushes, never pulls", as
 * walls/ghost_walls.h bounds it: the wall above a free surface would otherwise continue
 * the hydrostatic field into suction and draw the water up along it); a held one whose
 * condition now asks for a positive pressure is released. Returns how many changed. */
static int update_held(isph_ppe *s, const isph_pairs *q, const fluid_particles *p,
                       const isph_fields *f, double rho0, const double *gravity)
{
    const int n = p->n;
    int changed = 0;
#pragma omp parallel for schedule(static) reduction(+ : changed) \
    if (n >= FLUID_PARALLEL_MIN_PARTICLES)
    for (int i = 0; i < n; i++) {
        if ((p->flags[i] & FLUID_PARTICLE_FLUID) || !(f->sum_w[i] > 0.0))
            continue;
        if (!s->held[i]) {
            if (p->pressure[i] < 0.0) {
                s->held[i] = 1;
                changed++;
            }
            continue;
        }
        boundary_row(s, q, p, f, rho0, gravity, i);
        double wanted = s->rhs[i];
        for (int64_t e = q->start[i]; e < q->start[i + 1]; e++)
            wanted -= s->coef[e] * p->pressure[q->j[e]];
        if (wanted > 0.0) {
            s->held[i] = 0;
            changed++;
        }
    }
    return changed;
}

static int reserve_held(isph_ppe *s, int n)
{
    if (n <= s->held_capacity && s->held)
        return 0;
    const size_t cap = fsi_grown_capacity((size_t)n);
    int failed = 0;
    s->held = fsi_grow(s->held, cap, &failed);
    if (failed)
        return -1;
    memset(s->held + s->held_capacity, 0, cap - (size_t)s->held_capacity);
    s->held_capacity = (int)cap;
    return 0;
}

/* The matrix of the rows in s, appended in order. 0, or -1 when memory runs out. */
static int build_matrix(isph_ppe *s, const isph_pairs *q, int n)
{
    if (fsi_csr_begin(&s->a, n, n, q->start[n] + n) != 0)
        return -1;
    for (int i = 0; i < n; i++) {
        int32_t count = 0;
        s->cols[count] = i;
        s->vals[count++] = s->diag[i];
        for (int64_t e = q->start[i]; e < q->start[i + 1]; e++)
            if (s->coef[e] != 0.0) {
                s->cols[count] = q->j[e];
                s->vals[count++] = s->coef[e];
            }
        if (fsi_csr_append_row(&s->a, count, s->cols, s->vals) != 0)
            return -1;
    }
    return 0;
}

int isph_ppe_solve(isph_ppe *s, const isph_pairs *q, fluid_particles *p, const isph_fields *f,
                   const double *u_star, double dt, double rho0, const double *gravity,
                   fsi_krylov_result *res, char *msg, size_t msg_size)
{
    const int n = p->n;
    *res = (fsi_krylov_result){0};
    if (reserve(s, q, n) != 0 || reserve_held(s, n) != 0) {
        snprintf(msg, msg_size, "out of memory for the pressure Poisson equation of %d "
                 "particles", n);
        return -1;
    }
    for (int pass = 0; pass < ISPH_WALL_PASSES; pass++) {
        const int dirichlet = assemble(s, q, p, f, u_star, dt, rho0, gravity);
        /* No particle at p = 0 (a closed or periodic box): hold one at its pressure. */
        int pinned = -1;
        for (int i = 0; !dirichlet && i < n && pinned < 0; i++)
            if (p->flags[i] & FLUID_PARTICLE_FLUID)
                pinned = i;
        if (pinned >= 0) {
            s->rhs[pinned] = p->pressure[pinned];
            for (int64_t e = q->start[pinned]; e < q->start[pinned + 1]; e++)
                s->coef[e] = 0.0;
            s->pinned += pass == 0;
        }
        if (build_matrix(s, q, n) != 0) {
            snprintf(msg, msg_size, "out of memory for the pressure Poisson equation of %d "
                     "particles", n);
            return -1;
        }
        char err[256];
        if (fsi_precond_setup(&s->m, s->preconditioner, &s->a, err, sizeof err) != 0) {
            snprintf(msg, msg_size, "the pressure Poisson equation's preconditioner (%s): %s",
                     fsi_precond_name(s->preconditioner), err);
            return -1;
        }
        const fsi_krylov_result r =
            s->gmres ? fsi_gmres(&s->a, &s->m, s->rhs, p->pressure, &s->settings,
                                 ISPH_GMRES_RESTART)
                     : fsi_bicgstab(&s->a, &s->m, s->rhs, p->pressure, &s->settings);
        const int before = res->iterations;
        *res = r;
        res->iterations += before;
        s->solves += pass == 0;
        s->extra_passes += pass > 0;
        s->iterations += r.iterations;
        if (!r.converged) {
            snprintf(msg, msg_size, "the pressure Poisson equation of %d unknowns did not "
                     "converge: relative residual %.3g after %d iterations (%s; ppe_tolerance "
                     "%g, ppe_max_iterations %d)", n, r.rel_residual, r.iterations, r.reason,
                     s->settings.tol, s->settings.max_iter);
            return -1;
        }
        if (update_held(s, q, p, f, rho0, gravity) == 0)
            break;
    }
    if (res->iterations > s->worst_iterations)
        s->worst_iterations = res->iterations;
    if (res->rel_residual > s->worst_residual)
        s->worst_residual = res->rel_residual;
    /* a wall the last pass left negative (the passes ran out) */
    for (int i = 0; i < n; i++)
        if (!(p->flags[i] & FLUID_PARTICLE_FLUID) && p->pressure[i] < 0.0)
            p->pressure[i] = 0.0;
    return 0;
}

void isph_ppe_reordered(isph_ppe *s, const int *sorted, int n, void *scratch)
{
    if (n <= s->held_capacity && s->held)
        fsi_permute_rows(s->held, sorted, n, 1, scratch);
}

/* The scalars (no padding: the state is compared byte for byte). */
typedef struct {
    int64_t solves, extra_passes, iterations, worst_iterations, pinned, held_rows;
    double worst_residual;
} ppe_header;

int isph_ppe_save_state(const isph_ppe *s, fsi_state *st, const char *prefix)
{
    const ppe_header h = {s->solves, s->extra_passes, s->iterations, s->worst_iterations,
                          s->pinned, s->held ? s->held_capacity : 0, s->worst_residual};
    fluid_state_put(st, prefix, "header", &h, sizeof h);
    /* Every row the set holds (zero beyond the particles a projection saw): a row past
     * today's particles is read again when the solid's set grows. */
    if (h.held_rows > 0)
        fluid_state_put(st, prefix, "held", s->held, (size_t)h.held_rows);
    return st->failed ? -1 : 0;
}

int isph_ppe_restore_state(isph_ppe *s, const fsi_state *st, const char *prefix)
{
    ppe_header h;
    if (fluid_state_get(st, prefix, "header", &h, sizeof h) != 0 || h.held_rows < 0 ||
        h.held_rows > INT32_MAX)
        return -1;
    const int rows = (int)h.held_rows;
    if (rows > 0 && (reserve_held(s, rows) != 0 ||
                     fluid_state_get(st, prefix, "held", s->held, (size_t)rows) != 0))
        return -1;
    /* Rows the set did not hold then were zero when it grew to them. */
    if (s->held && s->held_capacity > rows)
        memset(s->held + rows, 0, (size_t)(s->held_capacity - rows));
    s->solves = (long)h.solves;
    s->extra_passes = (long)h.extra_passes;
    s->iterations = (long long)h.iterations;
    s->worst_iterations = (int)h.worst_iterations;
    s->pinned = (int)h.pinned;
    s->worst_residual = h.worst_residual;
    return 0;
}
