/* The ISPH scheme behind fluid_scheme.h (003 §2.1, docs/isph.md). A projection scheme
 * owns its step; one step of length dt from the state n (whose rates the main loop has
 * evaluated: neighbours, operators, the viscous acceleration a_v^n) is
 *   1. u* = u^n + dt (g + a_v^n), r* = r^n + dt u^n                  (003 Eqs. 11-13);
 *   2. the walls and the solid at t + dt, the neighbours and operators at r*, the
 *      free surface, the pressure Poisson equation for p^{n+1} (Eqs. 14-17): the
 *      main loop's evaluate hook, during which rates solves instead of reading;
 *   3. u^{n+1} = u* + dt a_p(p^{n+1}), r^{n+1} = r^n + dt (u^n + u^{n+1}) / 2
 *      (Eqs. 18-19), the loads on the solid from the same terms;
 *   4. shifting with the Taylor correction of u and p (Eqs. 20-32).
 * Between steps the pressure is the last projection's; rates at a state the scheme did
 * not leave (the start, a caller's own stepping: fluid positions or pressures changed)
 * first solves the projection of the current velocity over the last step (or the
 * stable one), so that rates always return the acceleration of a consistent pressure.
 * A solid or wall that moved alone keeps the last projection's pressure.
 * The fluid's density is rho0 throughout: there is no equation of state. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cubic_spline.h"
#include "fluid_parallel.h"
#include "fluid_phases.h"
#include "fluid_scheme.h"
#include "fluid_state.h"
#include "fluid_step.h"
#include "grow.h"
#include "isph_keys.h"
#include "isph_operators.h"
#include "isph_pairs.h"
#include "isph_ppe.h"
#include "isph_shifting.h"
#include "log.h"
#include "permute_rows.h"
#include "small_tensor.h"

/* The step over the soft contact's time scale dx / (sqrt(k) c0). */
#define ISPH_CONTACT_STEP 0.5
/* How often the pressure solver's statistics go to the log (steps). */
#define ISPH_LOG_INTERVAL 500

enum { PHASE_SEARCH, PHASE_OPERATORS, PHASE_PPE, PHASE_FORCES, PHASE_SHIFTING, N_PHASES };
static const char *const phase_name[N_PHASES] = {
    "rates: neighbour search", "rates: operators and free surface", "rates: pressure solve",
    "rates: forces", "step: shifting"};

struct fluid_scheme {
    cubic_spline_kernel kernel;
    double rho0, nu0, gravity[FSI_DIM];
    double courant, smagorinsky, surface_lower, surface_upper;
    double spacing;             /* dx [m] */
    const unsigned char *free_slip;
    fluid_verlet list;
    double skin;
    isph_pairs pairs;
    isph_fields fields;
    isph_ppe ppe;
    isph_shifting shifting;
    isph_contact contact;
    int wall_hold;              /* fluid_scheme_holds_at_walls */
    int capacity;
    double *viscous;            /* a_v of the last rates at a state of the scheme's own */
    double *pressure_acc;       /* a_p of the last rates */
    double *viscous_loads;      /* the reaction of a_v's pair terms on the solid */
    double *u_star, *x_start, *v_start, *shift, *grad;
    double *last_load;          /* the pressure load of the last step on the solid */
    int explicit_solid;         /* 1: the solid's received acceleration as it is */
    double *x_fresh, *p_fresh;  /* positions and pressures of the last solve or step */
    int32_t *id_fresh;          /* and the particles' ids */
    int n_fresh;                /* their count; 0: none */
    int projecting;             /* 1 inside step 2 */
    double dt_project, dt_last, t_project;
    long steps;
    fsi_krylov_result last;
    fluid_phases phases;
};

void fluid_scheme_use_timers(fluid_scheme *s, fsi_timers *t)
{
    fluid_phases_use(&s->phases, t, phase_name, N_PHASES);
}

static int reserve(fluid_scheme *s, int n)
{
    if (isph_fields_reserve(&s->fields, n) != 0)
        return -1;
    if (n <= s->capacity && s->viscous)
        return 0;
    const size_t cap = fsi_grown_capacity((size_t)n), vec = cap * FSI_DIM * sizeof(double);
    int failed = 0;
    double **arrays[] = {&s->viscous, &s->pressure_acc, &s->viscous_loads, &s->u_star,
                         &s->x_start, &s->v_start, &s->shift, &s->grad, &s->x_fresh,
                         &s->last_load};
    for (size_t k = 0; k < sizeof arrays / sizeof arrays[0]; k++)
        *arrays[k] = fsi_grow(*arrays[k], vec, &failed);
    s->p_fresh = fsi_grow(s->p_fresh, cap * sizeof(double), &failed);
    s->id_fresh = fsi_grow(s->id_fresh, cap * sizeof *s->id_fresh, &failed);
    if (!failed && s->last_load)
        memset(s->last_load + (size_t)s->capacity * FSI_DIM, 0,
               (cap - (size_t)s->capacity) * FSI_DIM * sizeof(double));
    if (failed)
        return -1;
    s->capacity = (int)cap;
    return 0;
}

fluid_scheme *fluid_scheme_create(const fsi_case *c, const char *role,
                                  const fluid_properties *props, const fluid_particles *p,
                                  char *msg, size_t msg_size)
{
    const char *own = fsi_case_solver_section(c, role);    /* [fluid.isph] */
    fluid_scheme *s = calloc(1, sizeof *s);
    if (!s) {
        snprintf(msg, msg_size, "out of memory for the ISPH scheme");
        return NULL;
    }
    const double h_over_dx = fsi_case_get_real(c, own, "smoothing_factor", ISPH_H_OVER_DX);
    if (cubic_spline_init(&s->kernel, h_over_dx * p->spacing) != 0) {
        snprintf(msg, msg_size, "[%s] smoothing_factor: no kernel with h = %g m", own,
                 h_over_dx * p->spacing);
        free(s);
        return NULL;
    }
    s->spacing = p->spacing;
    s->rho0 = props->density;
    s->explicit_solid = fsi_case_choice_is(c, own, "solid_inertia", "explicit");
    s->nu0 = props->viscosity / props->density;
    memcpy(s->gravity, props->gravity, sizeof s->gravity);
    s->free_slip = props->free_slip;
    s->courant = fsi_case_get_real(c, own, "courant_number", ISPH_COURANT);
    s->smagorinsky = fsi_case_get_real(c, own, "smagorinsky", ISPH_SMAGORINSKY);
    s->surface_lower = fsi_case_get_real(c, own, "free_surface_lower", ISPH_SURFACE_LOWER);
    s->surface_upper = fsi_case_get_real(c, own, "free_surface_upper", ISPH_SURFACE_UPPER);
    if (!(s->surface_upper > s->surface_lower)) {
        snprintf(msg, msg_size, "[%s] free_surface_upper: %g is not above free_surface_lower "
                 "(%g)", own, s->surface_upper, s->surface_lower);
        free(s);
        return NULL;
    }
    s->shifting = (isph_shifting){
        fsi_case_get_real(c, own, "shifting", ISPH_SHIFTING), ISPH_SHIFT_CAP * s->kernel.h,
        fsi_case_get_real(c, own, "fsi_shifting_layer", ISPH_FSI_LAYER)};
    const fsi_krylov_settings settings = {
        fsi_case_get_real(c, own, "ppe_tolerance", ISPH_PPE_TOLERANCE),
        (int)fsi_case_get_int(c, own, "ppe_max_iterations", ISPH_PPE_MAX_ITERATIONS)};
    isph_ppe_init(&s->ppe, settings,
                  fsi_case_choice_is(c, own, "ppe_preconditioner", "jacobi") ? FSI_PRECOND_JACOBI
                                                                    : FSI_PRECOND_ILU0,
                  fsi_case_choice_is(c, own, "ppe_solver", "gmres"),
                  fsi_case_get_real(c, own, "free_surface_offset", ISPH_SURFACE_OFFSET) *
                      p->spacing);
    s->ppe.inertia_depth = fsi_case_get_real(c, own, "solid_inertia_depth", 0.0);
    s->contact = (isph_contact){
        fsi_case_get_real(c, own, "wall_contact", ISPH_WALL_CONTACT) * props->sound_speed *
            props->sound_speed,
        1.0 / (0.75 * s->kernel.h)};
    s->wall_hold = fsi_case_get_bool(c, own, "wall_hold", 1);
    s->skin = fsi_case_get_real(c, own, "neighbour_skin", FLUID_VERLET_SKIN) * s->kernel.support;
    fluid_verlet_init(&s->list);
    fsi_grid_set_periodic(&s->list.grid, &props->periodic);
    isph_pairs_init(&s->pairs);
    isph_fields_init(&s->fields);
    s->fields.correct = !fsi_case_choice_is(c, own, "gradient_correction", "none");
    if (reserve(s, p->n) != 0) {
        fluid_scheme_free(s);
        snprintf(msg, msg_size, "out of memory for the ISPH scheme of %d particles", p->n);
        return NULL;
    }
    return s;
}

void fluid_scheme_free(fluid_scheme *s)
{
    if (!s)
        return;
    if (s->ppe.solves > 0)
        fsi_info("pressure solves: %ld (and %ld again for the walls held at p = 0), %.1f "
                 "iterations each on average, at most %d; largest relative residual %.3g%s",
                 s->ppe.solves, s->ppe.extra_passes,
                 (double)s->ppe.iterations / (double)s->ppe.solves, s->ppe.worst_iterations,
                 s->ppe.worst_residual, s->ppe.pinned ? " (some without a free surface: one "
                 "particle held at its pressure)" : "");
    fluid_verlet_free(&s->list);
    isph_pairs_free(&s->pairs);
    isph_fields_free(&s->fields);
    isph_ppe_free(&s->ppe);
    double *arrays[] = {s->viscous, s->pressure_acc, s->viscous_loads, s->u_star, s->x_start,
                        s->v_start, s->shift, s->grad, s->x_fresh, s->p_fresh,
                        s->last_load};
    for (size_t k = 0; k < sizeof arrays / sizeof arrays[0]; k++)
        free(arrays[k]);
    free(s->id_fresh);
    free(s);
}

int fluid_scheme_compressible(const fluid_scheme *s)
{
    (void)s;
    return 0;
}

int fluid_scheme_holds_at_walls(const fluid_scheme *s)
{
    return s->wall_hold;
}

double fluid_scheme_pressure(const fluid_scheme *s, double density)
{
    (void)s;
    (void)density;
    return 0.0;     /* no equation of state: the pressure solves a Poisson equation */
}

double fluid_scheme_density(const fluid_scheme *s, double pressure)
{
    (void)pressure;
    return s->rho0;
}

double fluid_scheme_compression_energy(const fluid_scheme *s, double density)
{
    (void)s;
    (void)density;
    return 0.0;     /* incompressible: the pressure does no work on the particles' volume */
}

double fluid_scheme_smoothing_length(const fluid_scheme *s)
{
    return s->kernel.h;
}

double fluid_scheme_support(const fluid_scheme *s)
{
    return s->kernel.support;
}

/* Step limits (003 Eq. 49 and the force and viscous limits). */
static double stable_step(const fluid_scheme *s, double vmax, double amax)
{
    const double h = s->kernel.h;
    double dt = INFINITY;
    if (vmax > 0.0)
        dt = s->courant * h / vmax;
    const double g = fsi_vec_norm(s->gravity), a = amax > g ? amax : g;
    if (a > 0.0)
        dt = fmin(dt, 0.25 * sqrt(h / a));
    /* the soft contact is a spring of speed sqrt(k) c0 over a spacing */
    if (s->contact.k_c2 > 0.0)
        dt = fmin(dt, ISPH_CONTACT_STEP * s->spacing / sqrt(s->contact.k_c2));
    double nu = s->nu0;
    for (int i = 0; i < s->pairs.n && i < s->fields.capacity; i++)
        nu = fmax(nu, s->fields.nu[i]);
    if (nu > 0.0)
        dt = fmin(dt, 0.125 * h * h / nu);
    return dt;
}

/* The walls held at p = 0 (isph_ppe.h) when the set covers n particles, else NULL. */
static const unsigned char *held_walls(const fluid_scheme *s, int n)
{
    return s->ppe.held && s->ppe.held_capacity >= n ? s->ppe.held : NULL;
}

/* 1 when the particles are those of the scheme's last solve or step (the same ids) and
 * the fluid particles' positions and pressures are those it left: the pressure is then
 * the projection's for this state, and the walls' and solid's pressures are put back
 * from it. Their positions are not compared: between coupling windows the solid's
 * received positions replace those the projection put at t + dt, which differ by the
 * coupling's own error, and the solid's pressures come back as 0 (fluid_boundary.c);
 * solving again for them, a whole second PPE per window when a window is one step,
 * would move the pressure by that error only. */
static int pressure_fresh(const fluid_scheme *s, fluid_particles *p)
{
    const int n = p->n;
    if (s->n_fresh != n || n == 0 || memcmp(s->id_fresh, p->id, (size_t)n * sizeof *p->id) != 0)
        return 0;
    for (int i = 0; i < n; i++)
        if ((p->flags[i] & FLUID_PARTICLE_FLUID) &&
            (s->p_fresh[i] != p->pressure[i] ||
             memcmp(&s->x_fresh[i * FSI_DIM], &p->x[i * FSI_DIM], FSI_DIM * sizeof *p->x) != 0))
            return 0;
    for (int i = 0; i < n; i++)
        if (!(p->flags[i] & FLUID_PARTICLE_FLUID))
            p->pressure[i] = s->p_fresh[i];
    return 1;
}

static void remember_state(fluid_scheme *s, const fluid_particles *p)
{
    memcpy(s->x_fresh, p->x, (size_t)p->n * FSI_DIM * sizeof *p->x);
    memcpy(s->p_fresh, p->pressure, (size_t)p->n * sizeof *p->pressure);
    memcpy(s->id_fresh, p->id, (size_t)p->n * sizeof *p->id);
    s->n_fresh = p->n;
}

static int solve(fluid_scheme *s, fluid_particles *p, const double *u_star, double dt, char *msg,
                 size_t msg_size)
{
    /* the solid's inertia in the equation: m_S = rho_S V_S as the solid sent them
     * (protocol version 3) */
    s->ppe.last_load = s->explicit_solid ? NULL : s->last_load;
    fluid_phase_start(&s->phases, PHASE_PPE);
    const int rc = isph_ppe_solve(&s->ppe, &s->pairs, p, &s->fields, u_star, dt, s->rho0,
                                  s->gravity, &s->last, msg, msg_size);
    fluid_phase_stop(&s->phases, PHASE_PPE);
    if (rc == 0) {
        remember_state(s, p);
        return 0;
    }
    if (s->projecting) {
        const size_t used = strlen(msg);
        snprintf(msg + used, msg_size - used, ", in the projection to t = %.9g s (step %ld, "
                 "dt = %.3g s)", s->t_project, s->steps + 1, dt);
    }
    return -1;
}

int fluid_scheme_rates(fluid_scheme *s, fluid_particles *p, double *drho_dt, double *dv_dt,
                       char *msg, size_t msg_size)
{
    const int n = p->n;
    if (reserve(s, n) != 0) {
        snprintf(msg, msg_size, "out of memory for the ISPH scheme of %d particles", n);
        return -1;
    }
    for (int i = 0; i < n; i++)
        if (p->flags[i] & FLUID_PARTICLE_FLUID) {
            p->density[i] = s->rho0;
            p->volume[i] = p->mass[i] / s->rho0;
        }
    fluid_phase_start(&s->phases, PHASE_SEARCH);
    int rc = fluid_verlet_update(&s->list, p, s->kernel.support, s->skin);
    if (rc >= 0)
        rc = isph_pairs_build(&s->pairs, &s->list, &s->kernel, p);
    fluid_phase_stop(&s->phases, PHASE_SEARCH);
    if (rc < 0) {
        snprintf(msg, msg_size, "cannot build the neighbour lists of %d particles (a position "
                 "is not finite, or memory ran out)", n);
        return -1;
    }
    fluid_phase_start(&s->phases, PHASE_OPERATORS);
    isph_fields *f = &s->fields;
    isph_geometry(&s->pairs, p, f);
    isph_free_surface(&s->pairs, p, held_walls(s, n), s->surface_lower, s->surface_upper, s->kernel.h, f);
    isph_wall_velocity(&s->pairs, p, s->free_slip, f);
    isph_velocity_gradient(&s->pairs, p, s->nu0, s->smagorinsky, s->kernel.h, f);
    fluid_phase_stop(&s->phases, PHASE_OPERATORS);
    fluid_phase_start(&s->phases, PHASE_FORCES);
    if (!s->projecting) {
        isph_viscous_acceleration(&s->pairs, p, s->free_slip, f, &s->contact, s->viscous);
        isph_viscous_loads(&s->pairs, p, f, &s->contact, s->rho0, s->viscous_loads);
    }
    fluid_phase_stop(&s->phases, PHASE_FORCES);
    if (s->projecting) {
        if (solve(s, p, s->u_star, s->dt_project, msg, msg_size) != 0)
            return -1;
    } else if (!pressure_fresh(s, p)) {
        /* The projection of the current velocity: u* = u + dt (g + a_v). */
        double dt = s->dt_last;
        if (!(dt > 0.0))
            dt = stable_step(s, 0.0, 0.0);  /* not the velocity's: Galilean invariance */
        for (int i = 0; i < n; i++)
            for (int d = 0; d < FSI_DIM; d++) {
                const int k = i * FSI_DIM + d;
                s->u_star[k] = (p->flags[i] & FLUID_PARTICLE_FLUID)
                                   ? p->v[k] + dt * (s->gravity[d] + s->viscous[k])
                                   : p->v[k];
            }
        if (solve(s, p, s->u_star, dt, msg, msg_size) != 0)
            return -1;
    }
    fluid_phase_start(&s->phases, PHASE_FORCES);
    memset(s->pressure_acc, 0, (size_t)n * FSI_DIM * sizeof *s->pressure_acc);
    isph_pressure_acceleration(&s->pairs, p, held_walls(s, n), s->rho0, s->pressure_acc);
    for (int i = 0; i < n; i++) {
        drho_dt[i] = 0.0;
        const int fluid = (p->flags[i] & FLUID_PARTICLE_FLUID) != 0;
        for (int d = 0; d < FSI_DIM; d++) {
            const int k = i * FSI_DIM + d;
            dv_dt[k] = fluid ? s->gravity[d] + s->viscous[k] + s->pressure_acc[k] : 0.0;
        }
    }
    fluid_phase_stop(&s->phases, PHASE_FORCES);
    return 0;
}

/* Shifting (003 Eqs. 20-32): u and p follow by Taylor's first order with the corrected
 * gradients at the projection's positions. */
static void shift_particles(fluid_scheme *s, fluid_particles *p, double dt)
{
    const int n = p->n;
    isph_fields *f = &s->fields;
    const double zeta = fluid_largest_speed(p) * dt;
    isph_shifting_compute(&s->shifting, &s->pairs, p, f, zeta, s->shift);
    isph_scalar_gradient(&s->pairs, p, f, p->pressure, s->grad);
    isph_wall_velocity(&s->pairs, p, s->free_slip, f);
    isph_velocity_gradient(&s->pairs, p, s->nu0, s->smagorinsky, s->kernel.h, f);
#pragma omp parallel for schedule(static) if (n >= FLUID_PARALLEL_MIN_PARTICLES)
    for (int i = 0; i < n; i++) {
        if (!(p->flags[i] & FLUID_PARTICLE_FLUID))
            continue;
        const double *dr = &s->shift[i * FSI_DIM];
        double du[FSI_DIM];
        fsi_mat_vec(&f->grad_u[i * FSI_MAT_SIZE], dr, du);
        /* a surface particle keeps the pressure of its surface condition */
        if (f->where[i] != ISPH_SURFACE && f->where[i] != ISPH_SPLASH)
            p->pressure[i] += fsi_vec_dot(dr, &s->grad[i * FSI_DIM]);
        for (int d = 0; d < FSI_DIM; d++) {
            p->v[i * FSI_DIM + d] += du[d];
            p->x[i * FSI_DIM + d] += dr[d];
        }
    }
}

int fluid_scheme_step(fluid_scheme *s, fluid_particles *p, double t, double dt,
                      const fluid_step_hooks *hooks, char *msg, size_t msg_size)
{
    const int n = p->n;
    if (reserve(s, n) != 0) {
        snprintf(msg, msg_size, "out of memory for the ISPH step of %d particles", n);
        return -1;
    }
    if (hooks->timers)
        fsi_timer_start(hooks->timers, hooks->integrate_timer);
    /* 1. predictor (003 Eqs. 11-13) */
    memcpy(s->x_start, p->x, (size_t)n * FSI_DIM * sizeof *p->x);
    memcpy(s->v_start, p->v, (size_t)n * FSI_DIM * sizeof *p->v);
    for (int i = 0; i < n; i++) {
        const int fluid = (p->flags[i] & FLUID_PARTICLE_FLUID) != 0;
        for (int d = 0; d < FSI_DIM; d++) {
            const int k = i * FSI_DIM + d;
            s->u_star[k] = fluid ? p->v[k] + dt * (s->gravity[d] + s->viscous[k]) : p->v[k];
            if (fluid)
                p->x[k] += dt * p->v[k];
        }
    }
    if (hooks->timers)
        fsi_timer_stop(hooks->timers, hooks->integrate_timer);
    /* 2. the projection at r*, the walls and solid at t + dt */
    s->projecting = 1;
    s->dt_project = dt;
    s->t_project = t + dt;
    const int rc = hooks->evaluate(hooks->owner, t + dt);
    s->projecting = 0;
    if (rc != 0)
        return -1;  /* the owner keeps the message */
    if (hooks->timers)
        fsi_timer_start(hooks->timers, hooks->integrate_timer);
    /* 3. correction and position (003 Eqs. 18-19) */
    for (int i = 0; i < n; i++) {
        const int fluid = (p->flags[i] & FLUID_PARTICLE_FLUID) != 0;
        for (int d = 0; d < FSI_DIM; d++) {
            const int k = i * FSI_DIM + d;
            if (!fluid) {
                hooks->accel[k] = 0.0;
                continue;
            }
            const double u1 = s->u_star[k] + dt * s->pressure_acc[k];
            p->x[k] = s->x_start[k] + 0.5 * dt * (s->v_start[k] + u1);
            p->v[k] = u1;
            hooks->accel[k] = (u1 - s->v_start[k]) / dt;
        }
        hooks->drho[i] = 0.0;
    }
    if (hooks->timers)
        fsi_timer_stop(hooks->timers, hooks->integrate_timer);
    /* The loads of the step are the projection's pair terms (their impulse is what the
     * fluid's momentum changed by); the owner weighs their work with the boundary's
     * velocity at the call, which is here the mean of the step's two ends. */
    for (int i = 0; i < n; i++)
        if (p->flags[i] & FLUID_PARTICLE_MOVING_BOUNDARY)
            for (int d = 0; d < FSI_DIM; d++) {
                const int k = i * FSI_DIM + d;
                const double end = p->v[k];
                p->v[k] = 0.5 * (s->v_start[k] + end);
                s->v_start[k] = end;
            }
    const int loads = hooks->loads(hooks->owner, dt);
    isph_pressure_loads(&s->pairs, p, held_walls(s, n), s->last_load);
    for (int i = 0; i < n; i++)
        if (p->flags[i] & FLUID_PARTICLE_MOVING_BOUNDARY)
            for (int d = 0; d < FSI_DIM; d++)
                p->v[i * FSI_DIM + d] = s->v_start[i * FSI_DIM + d];
    if (loads != 0)
        return -1;
    /* 4. shifting */
    fluid_phase_start(&s->phases, PHASE_SHIFTING);
    if (s->shifting.coefficient > 0.0)
        shift_particles(s, p, dt);
    fluid_phase_stop(&s->phases, PHASE_SHIFTING);
    remember_state(s, p);
    s->dt_last = dt;
    s->steps++;
    if (s->steps % ISPH_LOG_INTERVAL == 0)
        fsi_info("pressure solve at t = %.6g s (step %ld): %d iterations, relative residual "
                 "%.3g; %.1f iterations on average so far, at most %d", t + dt, s->steps,
                 s->last.iterations, s->last.rel_residual,
                 (double)s->ppe.iterations / (double)(s->ppe.solves ? s->ppe.solves : 1),
                 s->ppe.worst_iterations);
    return 0;
}

void fluid_scheme_after_step(fluid_scheme *s, fluid_particles *p, long count)
{
    (void)s;
    (void)p;
    (void)count;    /* the shifting is part of the step */
}

double fluid_scheme_stable_dt(const fluid_scheme *s, const fluid_particles *p, double amax)
{
    return stable_step(s, fluid_largest_speed(p), amax);
}

void fluid_scheme_pressure_gradient(const fluid_scheme *s, const fluid_particles *p,
                                    double *grad)
{
    isph_scalar_gradient(&s->pairs, p, &s->fields, p->pressure, grad);
}

void fluid_scheme_boundary_loads(const fluid_scheme *s, const fluid_particles *p,
                                 double *force)
{
    /* the pressure terms of the last projection, the viscous terms of the state the
     * step started from: what the step moved the fluid with */
    isph_pressure_loads(&s->pairs, p, held_walls(s, p->n), force);
    const int n = p->n < s->pairs.n ? p->n : s->pairs.n;
    for (int k = 0; k < n * FSI_DIM; k++)
        force[k] += s->viscous_loads[k];
}

/* The free surface as the scheme saw it at the last evaluation: div r, Skillen's alpha
 * and the class (isph_operators.h: 0 interior, 1 near the surface, 2 surface, 3 splash;
 * -1 for walls and solid). */
int fluid_scheme_write_fields(const fluid_scheme *s, fsi_h5_writer *out)
{
    const int n = s->pairs.n;
    int32_t *where = malloc((size_t)(n > 0 ? n : 1) * sizeof *where);
    if (!where)
        return -1;
    for (int i = 0; i < n; i++)
        where[i] = s->fields.div_r[i] > 0.0 ? s->fields.where[i] : -1;
    int rc = fsi_h5_write_field_int(out, "surface_class", where, 1) |
             fsi_h5_write_field_real(out, "div_r", s->fields.div_r, 1) |
             fsi_h5_write_field_real(out, "surface_alpha", s->fields.alpha, 1);
    free(where);
    return rc ? -1 : 0;
}

int fluid_scheme_describe_fields(fsi_h5_writer *out)
{
    static const fsi_h5_field_info info[] = {
        {"surface_class", "1", "Where the particle is relative to the free surface "
                               "(003 Fig. 2; flag_values, flag_meanings; walls and solid "
                               "are not_fluid)."},
        {"div_r", "1", "Divergence of the position with the uncorrected kernel, the "
                       "free-surface detector (about the dimension inside the fluid)."},
        {"surface_alpha", "1", "Skillen's coefficient of the shifting near the surface "
                               "(003 Eq. 17)."},
    };
    static const int32_t values[] = {-1, ISPH_INTERIOR, ISPH_NEAR_SURFACE, ISPH_SURFACE,
                                     ISPH_SPLASH};
    return fsi_h5_describe_fields(out, info, (int)(sizeof info / sizeof info[0])) ||
                   fsi_h5_name_flags(out, "surface_class", FSI_H5_FLAG_VALUES, 5, values,
                                     "not_fluid interior near_surface surface splash")
               ? -1
               : 0;
}

void fluid_scheme_particles_reordered(fluid_scheme *s, const int *sorted, int n, void *scratch)
{
    fluid_verlet_invalidate(&s->list);
    isph_ppe_reordered(&s->ppe, sorted, n, scratch);
    if (n <= s->n_fresh) {
        fsi_permute_rows(s->x_fresh, sorted, n, FSI_DIM * sizeof(double), scratch);
        fsi_permute_rows(s->p_fresh, sorted, n, sizeof(double), scratch);
        fsi_permute_rows(s->id_fresh, sorted, n, sizeof *s->id_fresh, scratch);
    } else {
        s->n_fresh = 0;
    }
}

/* The scalars of the state (no padding: the state is compared byte for byte). */
typedef struct {
    int64_t n_fresh, steps, last_iterations, load_rows;
    double dt_last, last_residual;
} isph_header;

/* State between steps: the candidate lists, the Poisson equation's walls held at p = 0
 * and statistics, the pressure load of the last step on the solid (the solid's inertia
 * in the next projection; every row, since rows past today's solid particles are read
 * again when its set grows), the positions, pressures and ids of the last solve or
 * step (whether the next rates solve again), the last step's length (that solve's) and
 * the step count. The pressure the solver starts from is the particles'. Pair rows, fields
 * and forces are rebuilt by every rates call. */
int fluid_scheme_save_state(const fluid_scheme *s, const fluid_particles *p, fsi_state *st)
{
    (void)p;
    const isph_header h = {s->n_fresh, s->steps, s->last.iterations,
                           s->last_load ? s->capacity : 0, s->dt_last, s->last.rel_residual};
    fsi_state_put(st, "isph.header", &h, sizeof h);
    const size_t vec = FSI_DIM * sizeof(double);
    if (h.load_rows > 0)
        fsi_state_put(st, "isph.last_load", s->last_load, (size_t)h.load_rows * vec);
    if (h.n_fresh > 0) {
        fsi_state_put(st, "isph.x_fresh", s->x_fresh, (size_t)h.n_fresh * vec);
        fsi_state_put(st, "isph.p_fresh", s->p_fresh, (size_t)h.n_fresh * sizeof(double));
        fsi_state_put(st, "isph.id_fresh", s->id_fresh, (size_t)h.n_fresh * sizeof *s->id_fresh);
    }
    if (fluid_verlet_save(&s->list, st, "isph.list") != 0 ||
        isph_ppe_save_state(&s->ppe, st, "isph.ppe") != 0)
        return -1;
    return st->failed ? -1 : 0;
}

int fluid_scheme_restore_state(fluid_scheme *s, fluid_particles *p, const fsi_state *st)
{
    isph_header h;
    if (fsi_state_get(st, "isph.header", &h, sizeof h) != 0 || h.n_fresh < 0 ||
        h.load_rows < 0 || h.n_fresh > INT32_MAX || h.load_rows > INT32_MAX)
        return -1;
    const int rows = (int)(h.load_rows > h.n_fresh ? h.load_rows : h.n_fresh);
    if (reserve(s, rows > p->n ? rows : p->n) != 0)
        return -1;
    const size_t vec = FSI_DIM * sizeof(double);
    /* last_load: the saved rows, zero beyond (as a growth leaves them) */
    memset(s->last_load, 0, (size_t)s->capacity * vec);
    if ((h.load_rows > 0 &&
         fsi_state_get(st, "isph.last_load", s->last_load, (size_t)h.load_rows * vec) != 0) ||
        (h.n_fresh > 0 &&
         (fsi_state_get(st, "isph.x_fresh", s->x_fresh, (size_t)h.n_fresh * vec) != 0 ||
          fsi_state_get(st, "isph.p_fresh", s->p_fresh, (size_t)h.n_fresh * sizeof(double)) != 0 ||
          fsi_state_get(st, "isph.id_fresh", s->id_fresh,
                        (size_t)h.n_fresh * sizeof *s->id_fresh) != 0)) ||
        fluid_verlet_restore(&s->list, st, "isph.list") != 0 ||
        isph_ppe_restore_state(&s->ppe, st, "isph.ppe") != 0)
        return -1;
    s->n_fresh = (int)h.n_fresh;
    s->steps = (long)h.steps;
    s->dt_last = h.dt_last;
    s->last = (fsi_krylov_result){.iterations = (int)h.last_iterations,
                                  .rel_residual = h.last_residual,
                                  .converged = 1,
                                  .reason = "converged"};
    return 0;
}

long long fluid_scheme_pair_count(const fluid_scheme *s)
{
    return s->pairs.n > 0 ? (long long)s->pairs.start[s->pairs.n] : 0;
}
