/* The fluid participant: the main loop every fluid scheme shares (README.md in this
 * folder). Built once per scheme as fsi-fluid-<scheme>; the scheme behind
 * fluid_scheme.h supplies the rates (density rate, acceleration), wall particles and
 * its stable step, this file everything else:
 *
 *   setup   blocks and walls -> particles, the fluid's properties (c0 from 000 Eq. 7
 *           when not given), the initial pressure, the scheme, probes, output file
 *   window  read the solid's state into the moving boundary particles
 *           (fluid_coupling.h; empty in a fluid-only run), sub-cycle the
 *           scheme's step (fluid_scheme_step) with its length chosen at every step from
 *           the stable step, check health after every step and the energy after every
 *           window, publish the window's loads on the solid, probes, output; propose
 *           the stable step when coupled (the solid sub-cycles inside the fluid's
 *           step), DBL_MAX alone (the fluid sub-cycles any window)
 *
 * A failure anywhere stops everyone with fsi_abort naming what, the particle, where and
 * when; nothing non-finite is ever written or sent. */
#include <float.h>
#include <math.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "dim.h"
#include "fluid_coupling.h"
#include "fluid_diagnostics.h"
#include "fluid_geometry.h"
#include "fluid_leak.h"
#include "fluid_output_info.h"
#include "fluid_parallel.h"
#include "fluid_periodic.h"
#include "fluid_probes.h"
#include "fluid_scheme.h"
#include "fluid_state.h"
#include "fluid_step.h"
#include "grow.h"
#include "fluid_wall_motion.h"
#include "h5_output.h"
#include "log.h"
#include "neighbour_grid.h"
#include "participant.h"
#include "particle_health.h"
#include "permute_rows.h"
#include "small_tensor.h"
#include "timers.h"

#define ROLE "fluid"
/* More steps in one window than this means a broken stable step, not a run. */
#define MAX_SUBSTEPS 100000000L
/* A fluid particle farther than this many diagonals of the initial bounding box of
 * all particles (water and walls) outside it has left any plausible domain. */
#define ESCAPE_DIAGONALS 1.0
/* The energy check's floor in units of M c0^2: kinetic energy below it is noise of
 * the weak compressibility, not an instability. */
#define ENERGY_FLOOR 1e-6
/* Mach number Ma = |v|max / c0 of the fastest fluid particle. 000 Eq. 7 sets
 * c0 = 10 U_max, Ma = 0.1, because the density error of a weakly compressible fluid
 * grows as Ma^2 (1 % there). At 0.3 it is about 10 %: the pressure is no longer that of
 * a nearly incompressible liquid, so the run warns (once). At 1 the fluid outruns its
 * own pressure waves, which then cannot keep it out of walls or off other particles (F1
 * at c0 = 1 m/s, Ma 2.6: water fell through the floor): the method is invalid and
 * the run stops. */
#define MACH_WARN 0.3
#define MACH_STOP 1.0

typedef struct {
    const fsi_case *c;
    fluid_geometry geometry;
    fluid_particles p;
    unsigned char *free_slip;
    fluid_properties props;
    fluid_scheme *scheme;
    fluid_probes probes;
    fluid_wall_motion motion;
    fluid_coupling coupling;    /* the solid's particles at the tail of p (000 §3) */
    fluid_leak leak;            /* fluid particles that cross a wall (fluid_leak.h) */
    long held;                  /* particles put back on a wall's face (fluid_leak.h) */
    int mach_warned;            /* MACH_WARN was passed and said */
    int n_fixed;        /* fluid and wall particles of the case, before that tail */
    double t;           /* time of the current state (walls are put there) */
    double wall_work;   /* work of the moving walls on the fluid so far [J] */
    int n_fluid;
    double *drho, *accel, *grad_p;
    double energy_limit, kinetic0, compression0, potential0, energy_floor;
    double momentum0[FSI_DIM];  /* of the fluid particles at the start [N s]: with the
                                 * impulse sent to the solid and gravity's, the fluid's
                                 * momentum budget (tests/system/test_coupled_plate.sh) */
    double potential_wrapped;   /* -sum m g . x that periodic wraps took away */
    double box_min[FSI_DIM], box_max[FSI_DIM];
    fsi_h5_writer *out;
    fsi_timers timers;
    int t_rates, t_integrate, t_exchange, t_output;
    long steps;                 /* steps of the state (restored with it) */
    long steps_taken;           /* every step taken, a repeated window's again (the
                                 * performance line: repeated iterations are real work) */
    double stable_dt;           /* the stable step at the last evaluation [s] */
    /* The penetration check (fluid_coupling_count_inside), after every window. */
    long inside_windows;        /* windows with a fluid particle inside the solid */
    int inside_max;             /* most fluid particles inside at once */
    /* Diagnostics (fluid_diagnostics.h): the file, its length at the restored
     * checkpoint (-1: a fresh run), the steps at the window's start, the last step,
     * the fluid particles inside the solid at the window's end. */
    fluid_diagnostics diagnostics;
    off_t diagnostics_resume;
    long window_first_step;
    double last_step;
    int inside_last;
    double max_speed;   /* the fastest fluid particle at the window's end */
    int capacity;       /* particles drho .. grad_p hold */
    int *order;         /* original index (output row) of the particle at each index of
                         * the fixed part; they are sorted by cell now and then */
    long reorder_interval, reordered_at;
    fsi_state saved;            /* the state at the start of the window (save_state) */
    char window[64];            /* "window k" (", iteration i" when repeated), for messages */
    char msg[512];
} fluid_run;

/* "(x, y)" of particle i's current position, for messages. */
static const char *where_text(const fluid_run *s, int i, char *buf, size_t size)
{
    return fsi_point_text(&s->p.x[i * FSI_DIM], buf, size);
}

static void free_run(fluid_run *s)
{
    if (s->out)
        fsi_h5_close(s->out);
    fluid_scheme_free(s->scheme);
    fluid_probes_free(&s->probes);
    fluid_wall_motion_free(&s->motion);
    fluid_coupling_free(&s->coupling);
    fluid_leak_free(&s->leak);
    fluid_diagnostics_close(&s->diagnostics);
    fluid_particles_free(&s->p);
    free(s->order);
    fluid_geometry_free(&s->geometry);
    free(s->free_slip);
    free(s->drho);
    free(s->accel);
    free(s->grad_p);
    fsi_state_free(&s->saved);
}

/* sum m v of the fluid particles. */
static void fluid_momentum(const fluid_particles *p, double *momentum)
{
    for (int d = 0; d < FSI_DIM; d++)
        momentum[d] = 0.0;
    for (int i = 0; i < p->n; i++)
        if (p->flags[i] & FLUID_PARTICLE_FLUID)
            for (int d = 0; d < FSI_DIM; d++)
                momentum[d] += p->mass[i] * p->v[i * FSI_DIM + d];
}

/* initial_pressure = hydrostatic: p = rho0 |g| depth, the depth below the corner of the
 * particle's block highest against gravity; the density from the equation of state and
 * the mass rho V0 (the particle holds its lattice volume at that pressure). */
static void hydrostatic_start(fluid_run *s)
{
    const double *g = s->props.gravity;
    const double g_norm = fsi_vec_norm(g);
    if (!(g_norm > 0.0))
        return;
    int i = 0;
    for (int b = 0; b < s->geometry.n_boxes; b++) {
        const fluid_box *box = &s->geometry.boxes[b];
        const long count = (long)fluid_box_points(box);
        if (box->is_wall)
            continue;       /* blocks come first in the particle order */
        /* Highest corner: along each axis the end that gravity points away from. */
        double top[FSI_DIM], up[FSI_DIM];
        const int plain = fsi_shape_is_plain_box(&box->shape);
        for (int d = 0; d < FSI_DIM; d++) {
            top[d] = g[d] < 0.0 ? box->shape.max[d] : box->shape.min[d];
            up[d] = -g[d] / g_norm;
        }
        /* Another shape: the depth below its highest point. */
        const double height = plain ? 0.0 : fsi_shape_reach(&box->shape, up);
        for (long j = 0; j < count; j++, i++) {
            double depth = plain ? 0.0 : height;
            for (int d = 0; d < FSI_DIM; d++)
                depth += plain ? (s->p.x[i * FSI_DIM + d] - top[d]) * g[d] / g_norm
                               : -s->p.x[i * FSI_DIM + d] * up[d];
            double pressure = s->props.density * g_norm * depth;
            s->p.density[i] = fluid_scheme_density(s->scheme, pressure);
            s->p.mass[i] = s->p.density[i] * s->p.volume[i];
        }
    }
}

/* The kind flags as the int32 the HDF5 output takes (a new array, or NULL). */
static int32_t *flags_as_int32(const fluid_particles *p)
{
    int32_t *flags = malloc((size_t)(p->n > 0 ? p->n : 1) * sizeof *flags);
    if (flags)
        for (int i = 0; i < p->n; i++)
            flags[i] = p->flags[i];
    return flags;
}

static int write_static(fluid_run *s)
{
    const fluid_particles *p = &s->p;
    int32_t *flags = flags_as_int32(p);
    if (!flags)
        return -1;
    int rc = fsi_h5_write_static_int(s->out, "id", p->id, p->n, 1) |
             fsi_h5_write_static_real(s->out, "x0", p->x, p->n, FSI_DIM) |
             fsi_h5_write_static_int(s->out, "flags", flags, p->n, 1);
    free(flags);
    return rc ? -1 : 0;
}

/* Rates at the current state into drho, accel. */
static int evaluate(fluid_run *s)
{
    fluid_wall_motion_apply(&s->motion, s->t, &s->p);
    fluid_coupling_move(&s->coupling, &s->p, s->t);
    fsi_timer_start(&s->timers, s->t_rates);
    int rc = fluid_scheme_rates(s->scheme, &s->p, s->drho, s->accel, s->msg, sizeof s->msg);
    fsi_timer_stop(&s->timers, s->t_rates);
    return rc;
}

/* The run's per-particle arrays for p->n particles (the solid's set may change size
 * from one window to the next). 0, or -1 when memory runs out. */
static int reserve_run_arrays(fluid_run *s)
{
    const int n = s->p.n;
    if (n <= s->capacity)
        return 0;
    /* No zeroing: every step writes these before it reads them. */
    const size_t cap = fsi_grown_capacity((size_t)n), vec = cap * FSI_DIM * sizeof(double);
    int failed = 0;
    s->drho = fsi_grow(s->drho, cap * sizeof(double), &failed);
    s->accel = fsi_grow(s->accel, vec, &failed);
    s->grad_p = fsi_grow(s->grad_p, vec, &failed);
    if (failed)
        return -1;
    s->capacity = (int)cap;
    return 0;
}

/* Sorts the fluid and wall particles by cell (the neighbour grid's counting sort) so
 * that the neighbours of a particle sit close in memory: a flow mixes the initial
 * lattice order, and the pair loops then jump across the arrays. Everything indexed by
 * particle follows (the arrays of p, the free-slip flags, the moving walls' indices,
 * the output order); the scheme rebuilds what it keeps by index. The solid's particles
 * at the tail stay where they are. Returns 0, or -1 when memory runs out (nothing
 * changed). */
static int reorder_particles(fluid_run *s)
{
    fluid_particles *p = &s->p;
    const int n = s->n_fixed;
    fsi_neighbour_grid grid;
    fsi_grid_init(&grid);
    void *scratch = malloc((size_t)(n > 0 ? n : 1) * FSI_DIM * sizeof(double));
    int *inverse = malloc((size_t)(n > 0 ? n : 1) * sizeof *inverse);
    if (!scratch || !inverse ||
        fsi_grid_build(&grid, p->x, n, 2.0 * fluid_scheme_smoothing_length(s->scheme)) != 0) {
        free(scratch);
        free(inverse);
        fsi_grid_free(&grid);
        return -1;
    }
    const int *sorted = grid.sorted;
    if (fluid_leak_reorder(&s->leak, sorted) != 0) {
        free(scratch);
        free(inverse);
        fsi_grid_free(&grid);
        return -1;
    }
    const size_t vec = FSI_DIM * sizeof(double);
    fsi_permute_rows(p->id, sorted, n, sizeof *p->id, scratch);
    fsi_permute_rows(p->x, sorted, n, vec, scratch);
    fsi_permute_rows(p->v, sorted, n, vec, scratch);
    fsi_permute_rows(p->mass, sorted, n, sizeof *p->mass, scratch);
    fsi_permute_rows(p->volume, sorted, n, sizeof *p->volume, scratch);
    fsi_permute_rows(p->density, sorted, n, sizeof *p->density, scratch);
    fsi_permute_rows(p->pressure, sorted, n, sizeof *p->pressure, scratch);
    fsi_permute_rows(p->boundary_acceleration, sorted, n, vec, scratch);
    fsi_permute_rows(p->boundary_density, sorted, n, sizeof *p->boundary_density, scratch);
    fsi_permute_rows(p->flags, sorted, n, sizeof *p->flags, scratch);
    fsi_permute_rows(s->free_slip, sorted, n, sizeof *s->free_slip, scratch);
    fsi_permute_rows(s->order, sorted, n, sizeof *s->order, scratch);
    for (int k = 0; k < n; k++)
        inverse[sorted[k]] = k;
    fluid_wall_motion_renumber(&s->motion, inverse);
    fluid_scheme_particles_reordered(s->scheme, sorted, n, scratch);
    free(scratch);
    free(inverse);
    fsi_grid_free(&grid);
    return 0;
}

/* Everything before the first window. Returns 0, or -1 with s->msg set. */
static int setup(fluid_run *s, fsi_participant *part)
{
    const fsi_case *c = s->c;
    size_t ms = sizeof s->msg;
    if (fluid_geometry_read(&s->geometry, c, ROLE, s->msg, ms) != 0)
        return -1;
    fluid_properties *pr = &s->props;
    pr->density = fsi_case_get_real(c, ROLE, "density", 1000.0);
    pr->viscosity = fsi_case_get_real(c, ROLE, "viscosity", 1e-3);
    pr->sound_speed = fluid_sound_speed(c, ROLE, pr->density);
    pr->tait_exponent = fsi_case_get_real(c, ROLE, "tait_exponent", 7.0);
    if (fsi_case_get_vector(c, ROLE, "gravity", pr->gravity) != 0)
        memset(pr->gravity, 0, sizeof pr->gravity);
    if (fluid_periodic_read(c, ROLE, &pr->periodic, s->msg, ms) != 0)
        return -1;
    if (!(pr->sound_speed > 0.0)) {
        snprintf(s->msg, ms, "[fluid] sound_speed: 0 and no max_velocity or max_pressure to "
                 "derive it from (000 Eq. 7)");
        return -1;
    }
    if (fluid_geometry_build(&s->geometry, pr->density, &s->p, &s->free_slip, s->msg, ms) != 0)
        return -1;
    pr->free_slip = s->free_slip;
    if (fluid_wall_motion_init(&s->motion, &s->geometry, &s->p, s->msg, ms) != 0)
        return -1;
    fluid_particles *p = &s->p;
    for (int i = 0; i < p->n; i++)
        s->n_fluid += (p->flags[i] & FLUID_PARTICLE_FLUID) != 0;
    s->energy_limit = fsi_case_get_real(c, ROLE, "energy_growth_limit", 2.0);

    s->n_fixed = p->n;
    fluid_coupling_init(&s->coupling, p->n, pr->density * pr->sound_speed);
    s->coupling.boundary.acceleration_in_pressure =
        fsi_case_get_bool(c, ROLE, "solid_acceleration", 1);
    s->reorder_interval = fsi_case_get_int(c, ROLE, "reorder_interval", 200);
    s->order = malloc((size_t)(p->n > 0 ? p->n : 1) * sizeof *s->order);
    for (int i = 0; s->order && i < p->n; i++)
        s->order[i] = i;
    if (!s->order || reserve_run_arrays(s) != 0) {
        snprintf(s->msg, ms, "out of memory for %d fluid particles", p->n);
        return -1;
    }
    s->scheme = fluid_scheme_create(c, ROLE, pr, p, s->msg, ms);
    if (!s->scheme)
        return -1;
    fluid_scheme_use_timers(s->scheme, &s->timers);
    const char *start = fsi_case_get(c, ROLE, "initial_pressure");
    if (!start || strcmp(start, "zero") != 0)
        hydrostatic_start(s);
    if (fluid_probes_init(&s->probes, &s->geometry, part, s->msg, ms) != 0)
        return -1;
    fsi_escape_box(p->x, p->n, ESCAPE_DIAGONALS, p->spacing, s->box_min, s->box_max);
    if (fluid_leak_init(&s->leak, &s->geometry, &pr->periodic, fluid_scheme_support(s->scheme),
                        p, s->n_fixed, 0.0) != 0) {
        snprintf(s->msg, ms, "out of memory for the leak check of %d particles", p->n);
        return -1;
    }
    fluid_wall_motion_widen(&s->motion, s->box_min, s->box_max);
    if (evaluate(s) != 0)
        return -1;

    double mass = 0.0;
    for (int i = 0; i < p->n; i++)
        if (p->flags[i] & FLUID_PARTICLE_FLUID)
            mass += p->mass[i];
    s->energy_floor = ENERGY_FLOOR * mass * pr->sound_speed * pr->sound_speed;
    s->kinetic0 = fluid_kinetic_energy(p);
    fluid_momentum(p, s->momentum0);
    /* The energy the fluid's pressure stores (none in an incompressible fluid): a
     * fluid started at the hydrostatic pressure holds it, and it can turn into motion. */
    s->compression0 = fluid_compression_energy(p, s->scheme);
    s->potential0 = fluid_potential_energy(p, pr->gravity);

    s->out = fsi_h5_create(fsi_output_dir(part), fsi_participant_name(part),
                           fsi_case_get(c, ROLE, "solver"));
    if (!s->out) {
        snprintf(s->msg, ms, "cannot create the output file in %s", fsi_output_dir(part));
        return -1;
    }
    if (fluid_output_describe(s->out) != 0 || fluid_scheme_describe_fields(s->out) != 0 ||
        write_static(s) != 0 || fsi_h5_set_point_order(s->out, s->order, s->n_fixed) != 0) {
        snprintf(s->msg, ms, "cannot write the static particle data");
        return -1;
    }
    fsi_info("%d particles (%d fluid in %d boxes, %d wall), spacing %g m, h = %g m, "
             "fluid mass %g, c0 = %g m/s%s, stable step %g s", p->n, s->n_fluid,
             s->geometry.n_boxes, p->n - s->n_fluid, p->spacing,
             fluid_scheme_smoothing_length(s->scheme), mass, pr->sound_speed,
             fsi_case_get_real(c, ROLE, "sound_speed", 0.0) > 0.0 ? "" : " (000 Eq. 7)",
             fluid_scheme_stable_dt(s->scheme, p, 0.0));
    return 0;
}

/* Largest |a| of a fluid particle from the last rates. */
static double max_acceleration(const fluid_run *s)
{
    double amax = 0.0;
    const int n = s->p.n;
#pragma omp parallel for schedule(static) reduction(max : amax) \
    if (n >= FLUID_PARALLEL_MIN_PARTICLES)
    for (int i = 0; i < n; i++)
        if (s->p.flags[i] & FLUID_PARTICLE_FLUID)
            amax = fmax(amax, fsi_vec_norm(&s->accel[i * FSI_DIM]));
    return amax;
}

/* A non-finite position, velocity or density of a fluid particle after a step. */
static int check_finite(fluid_run *s, double t, const char *window)
{
    const fluid_particles *p = &s->p;
    const int n = p->n;
    int first = n; /* the first bad particle, the same on any number of threads */
#pragma omp parallel for schedule(static) reduction(min : first) \
    if (n >= FLUID_PARALLEL_MIN_PARTICLES)
    for (int i = 0; i < n; i++) {
        if (!(p->flags[i] & FLUID_PARTICLE_FLUID))
            continue;
        int ok = isfinite(p->density[i]) && p->density[i] > 0.0;
        for (int d = 0; d < FSI_DIM; d++)
            ok = ok && isfinite(p->x[i * FSI_DIM + d]) && isfinite(p->v[i * FSI_DIM + d]);
        if (!ok && i < first)
            first = i;
    }
    if (first == n)
        return 0;
    snprintf(s->msg, sizeof s->msg, "particle %d has a non-finite position, velocity or "
             "density (density %g) at t = %.9g s (%s, step %ld): the integration is "
             "unstable", p->id[first], p->density[first], t, window, s->steps);
    return -1;
}

static const char axis_name[3] = {'x', 'y', 'z'};

/* A fluid particle that went through a wall after a step, after those that went into one
 * are put back when the scheme asks for it (fluid_leak.h). */
static int check_leak(fluid_run *s, const char *window)
{
    fluid_leak_crossing c;
    const int found = fluid_scheme_holds_at_walls(s->scheme)
                          ? fluid_leak_hold_and_check(&s->leak, &s->p, s->t, &s->held, &c)
                          : fluid_leak_check(&s->leak, &s->p, s->t, &c);
    if (!found)
        return 0;
    const fluid_box *wall = &s->geometry.boxes[c.box];
    char at[128];
    snprintf(s->msg, sizeof s->msg, "particle %d leaked through [%s]: it went from %s the wall "
             "to %s it along %c, now at %s, %.6g m past its face %c = %.9g m (more than one "
             "kernel support, %.3g m), at t = %.9g s (%s, step %ld); the walls no "
             "longer hold the fluid (a sound speed too low for the flow, or walls too thin)",
             s->p.id[c.particle], wall->section, c.upward ? "below" : "above",
             c.upward ? "above" : "below", axis_name[c.axis],
             where_text(s, c.particle, at, sizeof at),
             fabs(s->p.x[c.particle * FSI_DIM + c.axis] - c.face), axis_name[c.axis], c.face,
             s->leak.tolerance, s->t, window, s->steps);
    return -1;
}

/* Fluid particles back into the period box. The potential energy of the energy check
 * is that of the unwrapped motion (gravity along a periodic axis keeps doing work). */
static void wrap_periodic(fluid_run *s)
{
    fluid_particles *p = &s->p;
    for (int i = 0; i < p->n; i++) {
        if (!(p->flags[i] & FLUID_PARTICLE_FLUID))
            continue;
        double *x = &p->x[i * FSI_DIM], before[FSI_DIM];
        memcpy(before, x, sizeof before);
        fsi_periodic_wrap(&s->props.periodic, x);
        for (int d = 0; d < FSI_DIM; d++)
            s->potential_wrapped += p->mass[i] * s->props.gravity[d] * (x[d] - before[d]);
    }
}

/* The step's hooks (fluid_scheme.h): walls and boundary at time t, then the rates. */
static int evaluate_at(void *owner, double t)
{
    fluid_run *s = owner;
    s->t = t;
    return evaluate(s);
}

/* The work of moving walls over a step (the energy check's budget) and the impulse on
 * the solid's particles (the loads sent back), from the rates the step moves with (the
 * midpoint rule for the predictor-corrector). */
static int step_loads(void *owner, double dt)
{
    fluid_run *s = owner;
    s->wall_work += dt * fluid_wall_motion_power(&s->motion, s->t, &s->p, s->accel,
                                                 s->props.gravity);
    if (fluid_coupling_accumulate(&s->coupling, s->scheme, &s->p, dt) != 0) {
        snprintf(s->msg, sizeof s->msg, "out of memory for the loads on the solid");
        return -1;
    }
    return 0;
}

/* One step of the scheme (rates at the start state already in drho, accel). */
static int step(fluid_run *s, double dt)
{
    const fluid_step_hooks hooks = {s, evaluate_at, step_loads, s->drho, s->accel,
                                    &s->timers, s->t_integrate};
    const double t_start = s->t;
    if (fluid_scheme_step(s->scheme, &s->p, t_start, dt, &hooks, s->msg, sizeof s->msg) != 0)
        return -1;
    s->t = t_start + dt;
    s->last_step = dt;
    fsi_timer_start(&s->timers, s->t_integrate);
    if (fsi_periodic_any(&s->props.periodic))
        wrap_periodic(s);
    s->steps++;
    s->steps_taken++;
    fluid_scheme_after_step(s->scheme, &s->p, s->steps);
    fsi_timer_stop(&s->timers, s->t_integrate);
    return 0;
}

/* The window [t0, t0 + dt] in steps chosen at every step from the rates at its start
 * (fluid_scheme_stable_dt: acoustic, viscous and force limits), the remaining time cut
 * into equal parts no longer than that, so that the window's end is met exactly. */
static int advance(fluid_run *s, double t0, double dt, const char *window)
{
    s->t = t0;
    if (s->reorder_interval > 0 && s->steps - s->reordered_at >= s->reorder_interval) {
        if (reorder_particles(s) != 0) {
            snprintf(s->msg, sizeof s->msg, "out of memory sorting %d particles", s->n_fixed);
            return -1;
        }
        s->reordered_at = s->steps;
    }
    if (evaluate(s) != 0)
        return -1;
    const double t_end = t0 + dt;
    for (long j = 0;; j++) {
        const double remaining = t_end - s->t;
        if (j > 0 && !(remaining > 1e-12 * dt))
            break;
        if (j > 0 && evaluate(s) != 0)
            return -1;
        const double stable = fluid_scheme_stable_dt(s->scheme, &s->p, max_acceleration(s));
        s->stable_dt = stable;
        if (!(remaining > 1e-12 * dt))
            break;      /* a window of length zero: only the stable step */
        if (!(stable > 0.0) || !isfinite(stable) || j >= MAX_SUBSTEPS ||
            remaining / stable > (double)MAX_SUBSTEPS) {
            snprintf(s->msg, sizeof s->msg, "the stable step is %g s at t = %.9g s (%s, "
                     "%ld steps into it): the window of %g s cannot be sub-cycled",
                     stable, s->t, window, j, dt);
            return -1;
        }
        /* 1e-9: a remainder equal to a whole number of steps up to round-off gets no
         * more. */
        long m = (long)ceil(remaining / stable - 1e-9);
        if (m < 1)
            m = 1;
        const double h = m == 1 ? remaining : remaining / (double)m;
        if (step(s, h) != 0 || check_finite(s, s->t, window) != 0 || check_leak(s, window) != 0)
            return -1;
        if (m == 1)
            s->t = t_end;
    }
    return 0;
}

/* The Mach number of the fastest fluid particle after a window: a warning past
 * MACH_WARN (once), a stop past MACH_STOP. */
static int check_mach(fluid_run *s, double t, const char *window)
{
    if (!fluid_scheme_compressible(s->scheme))
        return 0;   /* no sound speed: a projection scheme's step follows the flow */
    const fluid_particles *p = &s->p;
    double vmax = 0.0;
    int fastest = -1;
    for (int i = 0; i < s->n_fixed; i++)
        if (p->flags[i] & FLUID_PARTICLE_FLUID) {
            const double v = fsi_vec_norm(&p->v[i * FSI_DIM]);
            if (v > vmax) {
                vmax = v;
                fastest = i;
            }
        }
    const double c0 = s->props.sound_speed, mach = vmax / c0;
    if (fastest < 0 || mach <= MACH_WARN)
        return 0;
    char at[128];
    where_text(s, fastest, at, sizeof at);
    if (mach > MACH_STOP) {
        snprintf(s->msg, sizeof s->msg, "particle %d at %s moves at %.4g m/s, Mach %.3g against "
                 "c0 = %g m/s, at t = %.9g s (%s): a fluid faster than its sound speed is "
                 "outside the weakly compressible method (000 Eq. 7 asks for Mach 0.1: raise "
                 "sound_speed or max_velocity)", p->id[fastest], at, vmax, mach, c0, t, window);
        return -1;
    }
    if (!s->mach_warned)
        fsi_warn("particle %d at %s moves at %.4g m/s, Mach %.3g against c0 = %g m/s, at "
                 "t = %.9g s (%s): above %g the density errors of the weakly "
                 "compressible fluid (~ Mach^2) pass 10 %% (000 Eq. 7 asks for Mach 0.1: raise "
                 "sound_speed or max_velocity)", p->id[fastest], at, vmax, mach, c0, t, window,
                 MACH_WARN);
    s->mach_warned = 1;
    return 0;
}

/* After a window: every fluid particle inside the generous box, the kinetic energy
 * within what gravity has released. */
static int check_health(fluid_run *s, double t, const char *window)
{
    const fluid_particles *p = &s->p;
    /* The box includes the reach of moving walls: only fluid particles can leave. */
    const int i = fsi_outside_box(p->x, s->n_fixed, s->box_min, s->box_max);
    if (i >= 0) {
        char at[128];
        snprintf(s->msg, sizeof s->msg, "particle %d left the domain: at %s, more than %g "
                 "diagonals outside the initial box of water and walls, at t = %.9g s "
                 "(%s)", p->id[i], where_text(s, i, at, sizeof at), ESCAPE_DIAGONALS,
                 t, window);
        return -1;
    }
    if (check_mach(s, t, window) != 0)
        return -1;
    /* Without inflow K + P + E_c = K0 + P0 + E_c0 - (dissipation), with the potential
     * energy P and the compression energy E_c >= 0, so K(t) <= K0 + E_c0 + (P0 - P(t));
     * an unstable integration makes energy from nothing. */
    double kinetic = fluid_kinetic_energy(p), released = s->potential0 -
                                                   (fluid_potential_energy(p, s->props.gravity) +
                                                    s->potential_wrapped);
    /* Moving walls and the solid add their work; unknown (NAN: walls with different
     * motions) lifts the bound. */
    double budget = isnan(s->wall_work)
                        ? INFINITY
                        : fmax(s->kinetic0 + s->compression0 + released + s->wall_work +
                                   s->coupling.work_on_fluid,
                               0.0);
    if (!isfinite(kinetic) || kinetic > s->energy_limit * budget + s->energy_floor) {
        /* Walls move slower than an unstable fluid: the fastest of the case's particles
         * (not the solid's, at the tail) is a fluid one. */
        double speed;
        const int fastest = fsi_fastest(p->v, s->n_fixed, &speed);
        char at[128];
        snprintf(s->msg, sizeof s->msg,
                 "kinetic energy grew to %.6g J, more than "
                 "energy_growth_limit = %g times the initial kinetic and compression energy "
                 "plus the potential energy released and the work of moving walls and solid "
                 "(%.6g J) plus the floor %.3g J; fastest: "
                 "particle %d at %s "
                 "at %.3g m/s; at t = %.9g s (%s): the integration is unstable",
                 kinetic, s->energy_limit, budget, s->energy_floor, p->id[fastest],
                 where_text(s, fastest, at, sizeof at), speed, t, window);
        return -1;
    }
    return 0;
}

static int write_frame(fluid_run *s, int frame, double t, long window)
{
    const fluid_particles *p = &s->p;
    int32_t *flags = flags_as_int32(p);
    if (!flags)
        return -1;
    /* The case's fluid and walls; the solid's particles are in the solid's output. */
    int rc = fsi_h5_begin_frame(s->out, frame, t, window, s->n_fixed, p->x) != 0 ||
             fsi_h5_write_field_real(s->out, "velocity", p->v, FSI_DIM) != 0 ||
             fsi_h5_write_field_real(s->out, "acceleration", s->accel, FSI_DIM) != 0 ||
             fsi_h5_write_field_real(s->out, "density", p->density, 1) != 0 ||
             fsi_h5_write_field_real(s->out, "pressure", p->pressure, 1) != 0 ||
             fsi_h5_write_field_int(s->out, "flags", flags, 1) != 0 ||
             /* what ParaView's SPH interpolators take: mass, density and h */
             fsi_h5_write_field_real(s->out, "mass", p->mass, 1) != 0 ||
             fsi_h5_write_frame_constant(s->out, "smoothing_length",
                                         fluid_scheme_smoothing_length(s->scheme)) != 0 ||
             fluid_scheme_write_fields(s->scheme, s->out) != 0;
    free(flags);
    return rc ? -1 : fsi_h5_end_frame(s->out);
}

/* Reads the solid's state at the window's start: its particles become the moving
 * boundary (000 §3, fluid_coupling.h). A fluid-only run reads an empty interface. */
static int receive(fluid_run *s, fsi_participant *part, double t0)
{
    if (fluid_coupling_receive(&s->coupling, part, &s->p, s->props.density, t0, s->msg,
                               sizeof s->msg) != 0)
        return -1;
    if (reserve_run_arrays(s) != 0) {
        snprintf(s->msg, sizeof s->msg, "out of memory for %d particles", s->p.n);
        return -1;
    }
    return 0;
}

/* Counts the fluid particles inside the solid after a window (fluid_coupling.h); the
 * first window with any gets a warning naming one, the end of the run the totals. */
static int check_penetration(fluid_run *s, double t, const char *window)
{
    int first;
    const int inside = fluid_coupling_count_inside(&s->coupling, &s->p, &first);
    if (inside < 0) {
        snprintf(s->msg, sizeof s->msg, "out of memory for the penetration check");
        return -1;
    }
    if (inside > 0 && s->inside_windows == 0) {
        char at[128];
        fsi_warn("%d fluid particle(s) inside the solid (closer than half the solid's "
                 "spacing to a solid particle) at t = %.9g s (%s), e.g. particle %d at %s",
                 inside, t, window, s->p.id[first], where_text(s, first, at, sizeof at));
    }
    s->inside_windows += inside > 0;
    s->inside_last = inside;
    if (inside > s->inside_max)
        s->inside_max = inside;
    return 0;
}

/* The main loop's scalars in the saved state (no padding: the state is compared and
 * written byte for byte). */
typedef struct {
    int64_t n, n_fixed, steps, reordered_at, inside_windows, inside_max, mach_warned;
    int64_t diagnostics_bytes;  /* the complete rows of the diagnostics file */
    double t, wall_work, potential_wrapped, stable_dt;
} run_header;

/* The fluid's state at the start of a window (implicit coupling, docs/coupling.md), for
 * restore_state when the coupler repeats the window: the particles (the solid's at the
 * tail too, though the window's start replaces them: restored in the same number, the
 * arrays need no reallocation), the per-particle arrays that follow the particle order
 * (free-slip flags, output order, the moving walls' indices, the leak check's sides),
 * the counters and totals the run goes on from (time, steps, the last sort, the walls'
 * work, the potential energy periodic wraps took, the Mach warning, the stable step
 * proposed, the penetration counts, the coupling's totals) and the scheme's own state
 * (fluid_scheme_save_state). Probes keep no state. 0, or -1 with s->msg when memory
 * runs out. */
static int save_state(fluid_run *s)
{
    fsi_state *st = &s->saved;
    const fluid_particles *p = &s->p;
    const size_t n = (size_t)p->n, vec = n * FSI_DIM * sizeof(double);
    const size_t n_fixed = (size_t)s->n_fixed;
    const run_header h = {p->n, s->n_fixed, s->steps, s->reordered_at, s->inside_windows,
                          s->inside_max, s->mach_warned,
                          (int64_t)fluid_diagnostics_bytes(&s->diagnostics), s->t,
                          s->wall_work, s->potential_wrapped, s->stable_dt};
    fsi_state_clear(st);
    fsi_state_put(st, "run.header", &h, sizeof h);
    fsi_state_put(st, "particles.id", p->id, n * sizeof *p->id);
    fsi_state_put(st, "particles.x", p->x, vec);
    fsi_state_put(st, "particles.v", p->v, vec);
    fsi_state_put(st, "particles.mass", p->mass, n * sizeof *p->mass);
    fsi_state_put(st, "particles.volume", p->volume, n * sizeof *p->volume);
    fsi_state_put(st, "particles.density", p->density, n * sizeof *p->density);
    fsi_state_put(st, "particles.pressure", p->pressure, n * sizeof *p->pressure);
    fsi_state_put(st, "particles.boundary_acceleration", p->boundary_acceleration, vec);
    fsi_state_put(st, "particles.boundary_density", p->boundary_density,
                  n * sizeof *p->boundary_density);
    fsi_state_put(st, "particles.flags", p->flags, n * sizeof *p->flags);
    fsi_state_put(st, "run.free_slip", s->free_slip, n_fixed * sizeof *s->free_slip);
    fsi_state_put(st, "run.order", s->order, n_fixed * sizeof *s->order);
    if (st->failed || fluid_coupling_save_state(&s->coupling, st, "coupling") != 0 ||
        fluid_leak_save_state(&s->leak, st, "leak") != 0 ||
        fluid_wall_motion_save_state(&s->motion, st, "wall_motion") != 0 ||
        fluid_scheme_save_state(s->scheme, p, st) != 0) {
        snprintf(s->msg, sizeof s->msg, "out of memory saving the state of %d particles", p->n);
        return -1;
    }
    return 0;
}

/* A state save_state saved (s->saved, or a checkpoint's), back: the run goes on as from
 * the start of the window it was saved at, bit for bit, once the window's start has put
 * the solid's particles in the tail again (the moving boundary, fluid_coupling_receive).
 * 0, or -1 with s->msg. */
static int restore_state(fluid_run *s, const fsi_state *st)
{
    fluid_particles *p = &s->p;
    run_header h;
    if (fsi_state_get(st, "run.header", &h, sizeof h) != 0 || h.n_fixed != s->n_fixed ||
        h.n < h.n_fixed || h.n > INT32_MAX) {
        snprintf(s->msg, sizeof s->msg, "no saved state of %d particles to restore", s->n_fixed);
        return -1;
    }
    if (fluid_particles_resize(p, (int)h.n) != 0) {
        snprintf(s->msg, sizeof s->msg, "out of memory restoring %d particles", (int)h.n);
        return -1;
    }
    const size_t n = (size_t)h.n, vec = n * FSI_DIM * sizeof(double);
    const size_t n_fixed = (size_t)s->n_fixed;
    int rc = fsi_state_get(st, "particles.id", p->id, n * sizeof *p->id) |
             fsi_state_get(st, "particles.x", p->x, vec) |
             fsi_state_get(st, "particles.v", p->v, vec) |
             fsi_state_get(st, "particles.mass", p->mass, n * sizeof *p->mass) |
             fsi_state_get(st, "particles.volume", p->volume, n * sizeof *p->volume) |
             fsi_state_get(st, "particles.density", p->density, n * sizeof *p->density) |
             fsi_state_get(st, "particles.pressure", p->pressure, n * sizeof *p->pressure) |
             fsi_state_get(st, "particles.boundary_acceleration", p->boundary_acceleration,
                           vec) |
             fsi_state_get(st, "particles.boundary_density", p->boundary_density,
                           n * sizeof *p->boundary_density) |
             fsi_state_get(st, "particles.flags", p->flags, n * sizeof *p->flags) |
             fsi_state_get(st, "run.free_slip", s->free_slip, n_fixed * sizeof *s->free_slip) |
             fsi_state_get(st, "run.order", s->order, n_fixed * sizeof *s->order);
    if (rc != 0 || fluid_coupling_restore_state(&s->coupling, st, "coupling") != 0 ||
        fluid_leak_restore_state(&s->leak, st, "leak") != 0 ||
        fluid_wall_motion_restore_state(&s->motion, st, "wall_motion") != 0 ||
        fluid_scheme_restore_state(s->scheme, p, st) != 0) {
        snprintf(s->msg, sizeof s->msg, "cannot restore the state saved at the window's start "
                 "(an entry missing or of another size, or memory ran out)");
        return -1;
    }
    s->steps = (long)h.steps;
    s->reordered_at = (long)h.reordered_at;
    s->inside_windows = (long)h.inside_windows;
    s->inside_max = (int)h.inside_max;
    s->mach_warned = (int)h.mach_warned;
    s->diagnostics_resume = (off_t)h.diagnostics_bytes;
    s->t = h.t;
    s->wall_work = h.wall_work;
    s->potential_wrapped = h.potential_wrapped;
    s->stable_dt = h.stable_dt;
    return 0;
}

/* The diagnostics row of an accepted window (fluid_diagnostics.h), timed as output. */
static int write_diagnostics(fluid_run *s, double t, int window, double dt)
{
    const fluid_window_summary w = {window, dt, s->steps - s->window_first_step,
                                    s->last_step, s->wall_work, s->potential_wrapped,
                                    s->coupling.work_at_sent, 0.0 - s->coupling.work_on_fluid,
                                    s->inside_last, s->max_speed};
    fsi_timer_start(&s->timers, s->t_output);
    const int rc = fluid_diagnostics_write(&s->diagnostics, t, &s->p, s->scheme,
                                           s->props.gravity, &w, s->msg, sizeof s->msg);
    fsi_timer_stop(&s->timers, s->t_output);
    return rc;
}

/* Every phase's seconds and share of the busy time (the main loop's own phases; the
 * scheme's "rates: ..." split its "rates"), for docs/performance.md. */
static void log_phases(const fsi_timers *t)
{
    double busy = 0.0;
    for (int i = 0; i < t->n; i++)
        busy += strchr(t->name[i], ':') ? 0.0 : t->seconds[i];
    char line[1024];
    size_t len = 0;
    for (int i = 0; i < t->n && len < sizeof line; i++)
        len += (size_t)snprintf(line + len, sizeof line - len, "%s%s %.3f s (%.1f %%)",
                                i > 0 ? ", " : "", t->name[i], t->seconds[i],
                                busy > 0.0 ? 100.0 * t->seconds[i] / busy : 0.0);
    fsi_info("performance: phases: %s", line);
}

int main(void)
{
    fsi_participant *part = fsi_open(NULL, ROLE, NULL, DBL_MAX);
    if (!part)
        return FSI_EXIT_RUN_FAILURE;
    fluid_run s;
    memset(&s, 0, sizeof s);
    s.c = fsi_participant_case(part);
    s.t_rates = fsi_timer_index(&s.timers, "rates");
    s.t_integrate = fsi_timer_index(&s.timers, "integration");
    s.t_exchange = fsi_timer_index(&s.timers, "exchange");
    s.t_output = fsi_timer_index(&s.timers, "output");
    if (setup(&s, part) != 0) {
        fsi_abort(part, "%s", s.msg);
        free_run(&s);
        return FSI_EXIT_RUN_FAILURE;
    }
    /* A restarted run goes on from the checkpoint's state (docs/checkpoints.md). */
    s.diagnostics_resume = -1;
    if (fsi_restart_state(part) && restore_state(&s, fsi_restart_state(part)) != 0) {
        fsi_abort(part, "restart: %s", s.msg);
        free_run(&s);
        return FSI_EXIT_RUN_FAILURE;
    }
    /* Cut back to the checkpoint's window at a restart, as probes.csv. */
    if (fluid_diagnostics_open(&s.diagnostics, fsi_output_dir(part), fsi_participant_name(part),
                               s.diagnostics_resume, s.msg, sizeof s.msg) != 0) {
        fsi_abort(part, "%s", s.msg);
        free_run(&s);
        return FSI_EXIT_RUN_FAILURE;
    }

    while (fsi_ongoing(part)) {
        double dt = fsi_window(part), t0 = fsi_time(part);
        int window = fsi_window_index(part);
        if (fsi_iteration(part) > 0)
            snprintf(s.window, sizeof s.window, "window %d, iteration %d", window,
                     fsi_iteration(part));
        else
            snprintf(s.window, sizeof s.window, "window %d", window);

        /* Implicit coupling: the state at the window's start, saved at its first
         * iteration and restored whenever the coupler repeats the window. */
        if ((fsi_requires_reading_checkpoint(part) && restore_state(&s, &s.saved) != 0) ||
            (fsi_requires_writing_checkpoint(part) && save_state(&s) != 0)) {
            fsi_abort(part, "%s: %s", s.window, s.msg);
            break;
        }
        /* A coupled checkpoint is this state on disk (docs/checkpoints.md). */
        if (fsi_requires_writing_checkpoint(part) && fsi_write_checkpoint(part, &s.saved) != 0) {
            fsi_abort(part, "%s: cannot write the fluid's checkpoint", s.window);
            break;
        }
        s.window_first_step = s.steps;
        fsi_timer_start(&s.timers, s.t_exchange);
        int rc = receive(&s, part, t0);
        fsi_timer_stop(&s.timers, s.t_exchange);
        if (rc != 0) {
            fsi_abort(part, "%s: %s", s.window, s.msg);
            break;
        }
        if (advance(&s, t0, dt, s.window) != 0 || check_health(&s, t0 + dt, s.window) != 0) {
            fsi_abort(part, "%s", s.msg);
            break;
        }
        if (check_penetration(&s, t0 + dt, s.window) != 0) {
            fsi_abort(part, "%s", s.msg);
            break;
        }
        fsi_timer_start(&s.timers, s.t_exchange);
        rc = fluid_coupling_publish(&s.coupling, part, s.scheme, &s.p, dt, s.msg,
                                    sizeof s.msg);
        fsi_timer_stop(&s.timers, s.t_exchange);
        if (rc != 0) {
            fsi_abort(part, "%s: %s", s.window, s.msg);
            break;
        }
        int frame = fsi_output_frame(part);
        if (frame >= 0 || fsi_probe_window(part)) {
            /* Pressures, walls and gradients of the state at the window's end; before
             * fsi_advance, which carries the probes. */
            if (evaluate(&s) != 0) {
                fsi_abort(part, "%s", s.msg);
                break;
            }
            fluid_scheme_pressure_gradient(s.scheme, &s.p, s.grad_p);
            fluid_probes_set(&s.probes, &s.p, s.grad_p, t0 + dt, part);
        }
        s.max_speed = fluid_max_speed(&s.p);    /* for the progress line and the row */
        fsi_set_progress(part, s.last_step, s.max_speed);
        /* Coupled, the window is the fluid's step: the solid's motion it sees and the
         * loads it returns are then as fresh as the fluid's own state. */
        fsi_advance(part, fsi_coupled(part) && s.stable_dt > 0.0 ? s.stable_dt : DBL_MAX);
        /* The frame only of a window the coupler accepts (a repeated one is computed
         * again). */
        if (frame >= 0 && fsi_window_complete(part)) {
            fsi_timer_start(&s.timers, s.t_output);
            rc = write_frame(&s, frame, t0 + dt, window);
            fsi_timer_stop(&s.timers, s.t_output);
            if (rc != 0) {
                fsi_abort(part, "cannot write output frame %d at t = %.9g s (window %d): %s",
                          frame, t0 + dt, window, fsi_h5_last_error());
                break;
            }
        }
        if (fsi_window_complete(part) && write_diagnostics(&s, t0 + dt, window, dt) != 0) {
            fsi_abort(part, "%s: %s", s.window, s.msg);
            break;
        }
    }
    if (s.scheme) {
        fsi_info("energy at the end: kinetic %.6g J (initial %.6g J), compression %.6g J "
                 "(initial %.6g J), potential energy released %.6g J; largest fluid speed "
                 "%.4g m/s", fluid_kinetic_energy(&s.p), s.kinetic0,
                 fluid_compression_energy(&s.p, s.scheme), s.compression0,
                 s.potential0 - fluid_potential_energy(&s.p, s.props.gravity),
                 fluid_max_speed(&s.p));
        if (fluid_scheme_holds_at_walls(s.scheme))
            fsi_info("walls: %ld times a fluid particle was put back on the face of a wall "
                     "it had entered (fluid_leak_hold_and_check; since this process "
                     "started, every iteration of an implicit window counted)", s.held);
        /* One particle-step is one fluid particle through one predictor-corrector step
         * (two evaluations of the rates), the unit docs/performance.md uses. */
        const double busy = s.timers.seconds[s.t_rates] + s.timers.seconds[s.t_integrate];
        fsi_info("performance: %ld steps of %d fluid particles (%d in all, %lld neighbour "
                 "pairs) on %d thread(s); rates %.3f s, integration %.3f s (%.4g "
                 "particle-steps/s)", s.steps_taken, s.n_fluid, s.p.n,
                 fluid_scheme_pair_count(s.scheme), omp_get_max_threads(),
                 s.timers.seconds[s.t_rates], s.timers.seconds[s.t_integrate],
                 busy > 0.0 ? (double)s.n_fluid * (double)s.steps_taken / busy : 0.0);
        log_phases(&s.timers);
        if (s.coupling.n_windows > 0)
            fsi_info("interface: %d windows with solid particles; fluid particles inside the "
                     "solid (closer than half the solid's spacing to a solid particle): "
                     "at most %d at once, in %ld windows; work of the solid on the fluid %.6g J",
                     s.coupling.n_windows, s.inside_max, s.inside_windows,
                     s.coupling.work_on_fluid);
        if (s.coupling.n_windows > 0) {
            /* All 17 digits: the solid logs what it sent, and the two must be equal. */
            fsi_info("interface: solid density received %.17g to %.17g kg/m^3",
                     s.coupling.density_min, s.coupling.density_max);
            char j[FSI_VECTOR_TEXT_SIZE], p0[FSI_VECTOR_TEXT_SIZE], p1[FSI_VECTOR_TEXT_SIZE];
            double momentum[FSI_DIM];
            fluid_momentum(&s.p, momentum);
            fsi_info("loads sent to the solid: impulse (%s) N s, work at the velocity the "
                     "solid sent %.9g J, work on the moving boundary %.9g J; fluid momentum "
                     "(%s) N s at the start, (%s) N s at the end",
                     fsi_vector_text(j, sizeof j, s.coupling.impulse_sent),
                     s.coupling.work_at_sent, -s.coupling.work_on_fluid,
                     fsi_vector_text(p0, sizeof p0, s.momentum0),
                     fsi_vector_text(p1, sizeof p1, momentum));
        }
    }
    free_run(&s);
    return fsi_close(part, &s.timers);
}
