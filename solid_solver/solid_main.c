/* The solid participant: the main loop every solid model shares (README.md in this
 * folder). Built once per model as fsi-solid-<model>; the model behind
 * solid_model.h supplies internal forces, the stable step, the surface and its own
 * output fields, this file everything else:
 *
 *   setup   geometry (blocks, regions) -> particles, material density, the model,
 *           prescribed loads, initial velocity, probes, output file
 *   window  restore the state saved at the window's start when the coupler repeats
 *           the window, save it at a window's first iteration (implicit coupling),
 *           publish the surface state at t_k, read the fluid's loads (held over the
 *           window, serial-staggered), sub-cycle the integrator (velocity Verlet, 000
 *           Eq. 55, or RK4, 003 Eqs. 43-45, for models that allow trial evaluations)
 *           in n = ceil(window / (safety * stable step)) equal sub-steps, check health
 *           after every sub-step and the energy after every window, probes, the sent
 *           particles' positions at the window's end, propose DBL_MAX (sub-cycling:
 *           the solid never limits the window), output once the window is accepted
 *
 * A failure anywhere stops everyone with fsi_abort naming what, the particle, where
 * and when; nothing non-finite is ever written or sent. */
#include <float.h>
#include <math.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "dim.h"
#include "geometry.h"
#include "h5_output.h"
#include "initial_velocity.h"
#include "log.h"
#include "material.h"
#include "participant.h"
#include "particle_health.h"
#include "solid_diagnostics.h"
#include "solid_integrate.h"
#include "solid_interface.h"
#include "solid_loads.h"
#include "solid_model.h"
#include "solid_output_info.h"
#include "solid_probes.h"
#include "solid_rk4.h"
#include "state_store.h"
#include "state_store.h"
#include "timers.h"

#define ROLE "solid"
/* More sub-steps in one window than this means a broken stable step, not a run. */
#define MAX_SUBSTEPS 100000000L
/* A point farther than this many body diagonals outside the initial bounding box
 * has left any plausible domain. */
#define ESCAPE_DIAGONALS 10.0

typedef struct {
    const fsi_case *c;
    solid_geometry geometry;
    solid_particles p;
    material mat;
    solid_model *model;
    solid_loads loads;
    solid_probes probes;
    solid_interface_buffers iface;
    solid_integrator integrator;
    int rk4;                        /* [solid] integrator = rk4 */
    solid_rk4_state rk4_state;
    double safety, energy_limit;
    int interface_impedance;        /* [solid] interface_impedance */
    double *f_int, *f_ext, *f_ext_prev, *f_fluid, *p_fluid, *x_prev, *scratch;
    double *interface_damping;      /* per particle: z A / m [1/s] (solid_interface.h) */
    double *f_held;                 /* the force held over the window: the fluid's load
                                     * plus the impedance's m c u (set once per window) */
    /* energy check */
    double energy0, work, work_in, energy_floor;
    /* The fluid's loads as received (f_fluid, without the impedance term the solid adds
     * itself): sum of F dt over the windows [N s]; their work at the window-mean
     * velocity u sent to the fluid, sum of F . u dt [J] (the fluid moves its boundary at
     * u, so this is the work it computes from its own forces); and their work over the
     * solid's own motion, sum of F . (x - x_prev) over the sub-steps [J], which differs
     * from the other by the one-window lag of u. The fluid logs what it sent;
     * tests/system/test_coupled_plate.sh compares them. */
    double fluid_impulse[FSI_DIM], fluid_work_at_sent, fluid_work;
    /* The interface impedance's work, sum m c (u - v) . (x - x_prev) over the sub-steps
     * with v the sub-step's mean velocity, as the integrator counts it in 'work' [J]:
     * what the solid's answer for the fluid inside the window took (docs/coupling.md). */
    double impedance_work;
    double dt_last;                 /* the last window's length (what v_mean spans) */
    double box_min[FSI_DIM], box_max[FSI_DIM];
    fsi_h5_writer *out;
    fsi_timers timers;
    int t_force, t_integrate, t_exchange, t_output;
    long substeps;                  /* integrator sub-steps of the run so far */
    /* Performance counts, never restored: every sub-step and internal-force
     * evaluation computed, those of repeated windows included (as the timers). */
    long substeps_computed, force_calls;
    fsi_state saved;                /* the state at the window's start (save_state) */
    /* Diagnostics (solid_diagnostics.h): the file, the length of its complete rows at
     * the window's start (saved with the state: a restart cuts it back to that), the
     * sub-steps at the window's start, the energies check_health computed. */
    solid_diagnostics diagnostics;
    int64_t diagnostics_bytes;
    double max_speed;           /* the fastest point at the window's end */
    long window_first_substep;
    double kinetic, strain;
    char msg[512];
} solid_run;

static double *new_vector(int n, int ncomp)
{
    return calloc((size_t)n * (size_t)ncomp, sizeof(double));
}

/* "(x, y)" of particle i's reference position, for messages. */
static const char *where_text(const solid_run *s, int i, char *buf, size_t size)
{
    return fsi_point_text(&s->p.x0[i * FSI_DIM], buf, size);
}

static void free_run(solid_run *s)
{
    if (s->out)
        fsi_h5_close(s->out);
    if (s->model)
        solid_model_free(s->model);
    solid_probes_free(&s->probes);
    solid_loads_free(&s->loads);
    solid_interface_free(&s->iface);
    solid_rk4_free(&s->rk4_state);
    solid_diagnostics_close(&s->diagnostics);
    solid_particles_free(&s->p);
    solid_geometry_free(&s->geometry);
    free(s->f_int);
    free(s->f_ext);
    free(s->f_ext_prev);
    free(s->f_fluid);
    free(s->p_fluid);
    free(s->x_prev);
    free(s->interface_damping);
    free(s->f_held);
    free(s->scratch);
    fsi_state_free(&s->saved);
}

/* The main loop's state, what a repeated window starts from besides the model's: the
 * particles' positions, velocities and accelerations, the internal force at their
 * positions (the integrator's first acceleration of the next window uses it), the
 * window means the next gather builds on, the last window's length, and the totals of
 * the energy check, the fluid's loads, the density sent and the sub-steps. Everything
 * else is set within each window before it is read: the surface set, the fluid's
 * loads and the impedance (exchange), the held force, the external forces, x_prev
 * and the RK4 stages (advance); the prescribed loads and the probes are functions of
 * the time and the particles. */
enum { RUN_STATE_FIELDS = 19 };

static int run_state_fields(solid_run *s, fsi_state_field *f)
{
    const size_t v = (size_t)s->p.n * FSI_DIM * sizeof(double);
    int k = 0;
    f[k++] = (fsi_state_field){"solid.x", s->p.x, v};
    f[k++] = (fsi_state_field){"solid.v", s->p.v, v};
    f[k++] = (fsi_state_field){"solid.a", s->p.a, v};
    f[k++] = (fsi_state_field){"solid.f_int", s->f_int, v};
    f[k++] = (fsi_state_field){"solid.x_window", s->iface.x_window, v};
    f[k++] = (fsi_state_field){"solid.v_mean", s->iface.v_mean, v};
    f[k++] = (fsi_state_field){"solid.have_x_window", &s->iface.have_x_window,
                                 sizeof s->iface.have_x_window};
    f[k++] = (fsi_state_field){"solid.dt_mean", &s->iface.dt_mean, sizeof s->iface.dt_mean};
    f[k++] = (fsi_state_field){"solid.dt_last", &s->dt_last, sizeof s->dt_last};
    f[k++] = (fsi_state_field){"solid.density_min", &s->iface.density_min,
                                 sizeof s->iface.density_min};
    f[k++] = (fsi_state_field){"solid.density_max", &s->iface.density_max,
                                 sizeof s->iface.density_max};
    f[k++] = (fsi_state_field){"solid.work", &s->work, sizeof s->work};
    f[k++] = (fsi_state_field){"solid.work_in", &s->work_in, sizeof s->work_in};
    f[k++] = (fsi_state_field){"solid.fluid_impulse", s->fluid_impulse,
                                 sizeof s->fluid_impulse};
    f[k++] = (fsi_state_field){"solid.fluid_work_at_sent", &s->fluid_work_at_sent,
                                 sizeof s->fluid_work_at_sent};
    f[k++] = (fsi_state_field){"solid.fluid_work", &s->fluid_work, sizeof s->fluid_work};
    f[k++] = (fsi_state_field){"solid.impedance_work", &s->impedance_work,
                                 sizeof s->impedance_work};
    f[k++] = (fsi_state_field){"solid.substeps", &s->substeps, sizeof s->substeps};
    f[k++] = (fsi_state_field){"solid.diagnostics_bytes", &s->diagnostics_bytes,
                                 sizeof s->diagnostics_bytes};
    return k;
}

/* Saves the state at the start of a window (s->saved, its memory reused). Returns 0,
 * or -1 with s->msg set. */
static int save_state(solid_run *s)
{
    fsi_state_field f[RUN_STATE_FIELDS];
    s->diagnostics_bytes = (int64_t)solid_diagnostics_bytes(&s->diagnostics);
    fsi_state_clear(&s->saved);
    if (fsi_state_put_fields(&s->saved, f, run_state_fields(s, f)) != 0 ||
        solid_model_save_state(s->model, &s->p, &s->saved) != 0) {
        snprintf(s->msg, sizeof s->msg, "out of memory saving the state of %d solid "
                 "particles", s->p.n);
        return -1;
    }
    return 0;
}

/* Restores a state save_state saved (s->saved, or a checkpoint's). Returns 0, or -1
 * with s->msg set. */
static int restore_state(solid_run *s, const fsi_state *st)
{
    fsi_state_field f[RUN_STATE_FIELDS];
    const int count = run_state_fields(s, f);
    if (!fsi_state_fields_match(st, f, count) ||
        solid_model_restore_state(s->model, &s->p, st) != 0 ||
        fsi_state_get_fields(st, f, count) != 0) {
        snprintf(s->msg, sizeof s->msg, "the state saved at the window's start is missing "
                 "or does not fit the %d solid particles", s->p.n);
        return -1;
    }
    return 0;
}

static int write_static(solid_run *s)
{
    const solid_particles *p = &s->p;
    int32_t *flags = malloc((size_t)p->n * sizeof *flags);
    if (!flags)
        return -1;
    for (int i = 0; i < p->n; i++)
        flags[i] = p->flags[i];
    int rc = fsi_h5_write_static_int(s->out, "id", p->id, p->n, 1) |
             fsi_h5_write_static_real(s->out, "x0", p->x0, p->n, FSI_DIM) |
             fsi_h5_write_static_real(s->out, "volume", p->volume, p->n, 1) |
             fsi_h5_write_static_real(s->out, "density", p->density, p->n, 1) |
             fsi_h5_write_static_int(s->out, "block", p->block, p->n, 1) |
             fsi_h5_write_static_int(s->out, "flags", flags, p->n, 1);
    free(flags);
    return rc ? -1 : 0;
}

/* Everything before the first window. Returns 0, or -1 with s->msg set. */
static int setup(solid_run *s, fsi_participant *part)
{
    const fsi_case *c = s->c;
    size_t ms = sizeof s->msg;
    if (solid_geometry_read(&s->geometry, c, ROLE, s->msg, ms) != 0)
        return -1;
    if (material_from_case(&s->mat, c, ROLE, s->msg, ms) != 0)
        return -1;
    int unmirrored = 0;
    if (solid_geometry_build(&s->geometry, s->mat.density, &s->p, &unmirrored, s->msg, ms) != 0)
        return -1;
    solid_particles *p = &s->p;
    if (unmirrored > 0)
        fsi_info("warning: %d points of clamp regions with a clamp_face have no unclamped "
                 "particle at their mirror image; they stay fixed at x0", unmirrored);

    s->safety = fsi_case_get_real(c, ROLE, "time_step_safety", 0.8);
    s->energy_limit = fsi_case_get_real(c, ROLE, "energy_growth_limit", 2.0);
    s->interface_impedance = fsi_case_get_bool(c, ROLE, "interface_impedance", 1);
    s->integrator.damping = fsi_case_get_real(c, ROLE, "damping", 0.0);
    if (fsi_case_get_vector(c, ROLE, "gravity", s->integrator.gravity) != 0)
        memset(s->integrator.gravity, 0, sizeof s->integrator.gravity);
    s->integrator.max_step = p->spacing;
    const char *integrator = fsi_case_get(c, ROLE, "integrator");
    s->rk4 = integrator && strcmp(integrator, "rk4") == 0;
    if (s->rk4 && solid_rk4_init(&s->rk4_state, p->n) != 0) {
        snprintf(s->msg, ms, "out of memory for the RK4 stages of %d solid particles", p->n);
        return -1;
    }

    s->f_int = new_vector(p->n, FSI_DIM);
    s->f_ext = new_vector(p->n, FSI_DIM);
    s->f_ext_prev = new_vector(p->n, FSI_DIM);
    s->f_fluid = new_vector(p->n, FSI_DIM);
    s->p_fluid = new_vector(p->n, 1);
    s->x_prev = new_vector(p->n, FSI_DIM);
    s->scratch = new_vector(p->n, FSI_DIM);
    s->interface_damping = new_vector(p->n, 1);
    s->f_held = new_vector(p->n, FSI_DIM);
    s->integrator.particle_damping = s->interface_damping;
    if (!s->f_int || !s->f_ext || !s->f_ext_prev || !s->f_fluid || !s->p_fluid ||
        !s->x_prev || !s->scratch || !s->interface_damping || !s->f_held ||
        solid_interface_init(&s->iface, p->n) != 0) {
        snprintf(s->msg, ms, "out of memory for %d solid particles", p->n);
        return -1;
    }
    /* The fluid's reach below the surface (docs/coupling.md, Unequal spacings). */
    const double reach = solid_interface_fluid_reach(c, &s->iface.fluid_spacing);
    const double depth = solid_interface_depth(c);
    const int in_band = solid_interface_band(&s->iface, p, depth);
    if (in_band < 0) {
        snprintf(s->msg, ms, "out of memory marking the points within %g m of the surface",
                 depth);
        return -1;
    }
    if (depth > 0.0)
        fsi_info("interface: %d points within %g m of the surface are sent to the fluid "
                 "(its reach %g m, spacing %g m; the solid's spacing %g m)", in_band, depth,
                 reach, s->iface.fluid_spacing, p->spacing);
    if (solid_loads_init(&s->loads, &s->geometry, p, s->msg, ms) != 0)
        return -1;
    /* c0 = sqrt(K / rho) as Gray et al. 2001 define it for the mode's amplitude
     * (initial_velocity.h). */
    double c0 = sqrt(s->mat.bulk_modulus / s->mat.density);
    if (solid_initial_velocity(c, ROLE, c0, p, s->msg, ms) != 0)
        return -1;
    if (solid_probes_init(&s->probes, &s->geometry, p, part, s->msg, ms) != 0)
        return -1;

    s->model = solid_model_create(c, p, s->msg, ms);
    if (!s->model)
        return -1;
    /* The case check refuses this combination with file and line; this guards a case
     * that skipped it. */
    if (s->rk4 && !solid_model_stateless(s->model)) {
        snprintf(s->msg, ms, "[solid] integrator = rk4: the %s model commits state in every "
                 "force evaluation, which RK4's trial stages would corrupt; use verlet",
                 fsi_case_get(c, ROLE, "solver"));
        return -1;
    }
    double stable = solid_model_stable_dt(s->model, p);
    if (!(stable > 0.0) || !isfinite(stable)) {
        snprintf(s->msg, ms, "the model's stable step is %g s: nothing can be integrated",
                 stable);
        return -1;
    }

    /* Energy check: the natural scale M (dx / stable step)^2 ~ M c^2 gives the floor
     * below which energy is round-off (a body at rest has E = 0). */
    double mass = solid_total_mass(p);
    double c_wave = p->spacing / stable;
    s->energy_floor = 1e-12 * mass * c_wave * c_wave;
    s->energy0 = solid_kinetic_energy(p) + solid_model_strain_energy(s->model, p);

    fsi_escape_box(p->x0, p->n, ESCAPE_DIAGONALS, p->spacing, s->box_min, s->box_max);

    s->out = fsi_h5_create(fsi_output_dir(part), fsi_participant_name(part),
                           fsi_case_get(c, ROLE, "solver"));
    if (!s->out) {
        snprintf(s->msg, ms, "cannot create the output file in %s", fsi_output_dir(part));
        return -1;
    }
    if (solid_output_describe(s->out) != 0 || solid_model_describe_fields(s->out) != 0 ||
        write_static(s) != 0) {
        snprintf(s->msg, ms, "cannot write the static particle data");
        return -1;
    }

    int clamped = 0, loaded = 0, unbreakable = 0;
    for (int i = 0; i < p->n; i++) {
        clamped += (p->flags[i] & SOLID_CLAMPED) != 0;
        loaded += (p->flags[i] & SOLID_LOADED) != 0;
        unbreakable += (p->flags[i] & SOLID_UNBREAKABLE) != 0;
    }
    if (unbreakable)
        fsi_info("%d particles in no_failure regions: their bonds do not break", unbreakable);
    fsi_info("%d particles (%d blocks, %d clamped, %d loaded), spacing %g m, mass %g, "
             "stable step %g s (sub-step %g s, %s), c0 = sqrt(K/rho) = %g m/s",
             p->n, s->geometry.n_blocks, clamped, loaded, p->spacing, mass, stable,
             s->safety * stable, s->rk4 ? "RK4" : "velocity Verlet", c0);
    /* Allowed (solid_keys.c) so that a stability limit can be probed, but nothing
     * guarantees a stable integration there: say so before the run, so that a later
     * "unstable" stop is not a surprise. */
    if (s->safety > 1.0)
        fsi_warn("time_step_safety = %g is beyond the estimated stable step (sub-steps "
                 "up to %g s, stable step %g s): the run may go unstable", s->safety,
                 s->safety * stable, stable);
    return 0;
}

/* f_held = the fluid's load of this window + the m c u half of the interface
 * impedance (solid_interface_damping; the -m c v half is in the integrator). Both are
 * constant over the window, so this is done once per window, not per sub-step. */
static void hold_interface_force(solid_run *s)
{
    const solid_particles *p = &s->p;
    for (int i = 0; i < p->n; i++) {
        const double mc = s->interface_damping[i] * p->density[i] * p->volume[i];
        for (int d = 0; d < FSI_DIM; d++) {
            const int k = i * FSI_DIM + d;
            s->f_held[k] = s->f_fluid[k] + mc * s->iface.u_fluid[k];
        }
    }
}

/* f_ext = prescribed loads at time t + the force held over the window. */
static void external_forces(solid_run *s, double t, double *f_ext)
{
    memcpy(f_ext, s->f_held, (size_t)s->p.n * FSI_DIM * sizeof *f_ext);
    solid_loads_add(&s->loads, t, f_ext);
}

/* Publishes the surface state at t_k and takes the fluid's loads of this window. */
static int exchange(solid_run *s, fsi_participant *part)
{
    memset(s->iface.surface, 0, (size_t)s->iface.capacity);
    if (fsi_coupled(part)) {
        solid_model_surface(s->model, &s->p, s->iface.surface);
        solid_interface_gather(&s->iface, &s->p, solid_model_density(s->model, &s->p),
                               s->dt_last);
    } else {
        s->iface.state.n = 0;
    }
    s->dt_last = fsi_window(part);
    if (fsi_write_interface(part, &s->iface.state) != 0) {
        snprintf(s->msg, sizeof s->msg, "cannot publish the solid state (%d particles)",
                 s->iface.state.n);
        return -1;
    }
    fsi_interface loads;
    fsi_read_interface(part, &loads);
    /* The impedance's reference u is the velocity the fluid moved each particle with,
     * which the library hands back in 'velocity' (in an explicit run the velocity
     * sent, v_mean, bit for bit). */
    if (solid_interface_take(&s->iface, &loads, &s->p, s->f_fluid, s->p_fluid, s->msg,
                             sizeof s->msg) != 0)
        return -1;
    solid_interface_damping(&s->iface, &s->p, s->f_fluid,
                            s->interface_impedance ? loads.impedance : 0.0,
                            s->interface_damping);
    hold_interface_force(s);
    return 0;
}

/* The internal force at the particles' positions (the model's, mirrored points'
 * forces handed to their partners), timed and counted. */
static int internal_force(solid_run *s, double t, double h)
{
    fsi_timer_start(&s->timers, s->t_force);
    int rc = solid_model_internal_force(s->model, &s->p, s->x_prev, h, t, s->f_int, s->msg,
                                        sizeof s->msg);
    fsi_timer_stop(&s->timers, s->t_force);
    s->force_calls++;
    if (rc == 0)
        solid_mirror_forces(&s->p, s->f_int);
    return rc;
}

/* RK4's stage forces (solid_rk4_forces): internal at the stage's positions, external
 * at its time. Only for stateless models (setup checks), so x_prev and the step
 * mean nothing to the model. */
static int rk4_forces(void *ctx, solid_particles *p, double t)
{
    solid_run *s = ctx;
    (void)p;
    if (internal_force(s, t, 0.0) != 0)
        return -1;
    external_forces(s, t, s->f_ext);
    return 0;
}

/* The largest interface or mass-proportional damping rate [1/s]: RK4 treats it
 * explicitly and needs c h below SOLID_RK4_MAX_DAMPING_STEP. */
static double largest_damping(const solid_run *s)
{
    double c = 0.0;
    for (int i = 0; i < s->p.n; i++)
        c = fmax(c, s->interface_damping[i]);
    return s->integrator.damping + c;
}

/* One sub-step [t - h, t] of velocity Verlet (000 Eq. 55). */
static int verlet_substep(solid_run *s, solid_forces *forces, double t, double h,
                          double *dw, solid_fault *fault)
{
    solid_particles *p = &s->p;
    fsi_timer_start(&s->timers, s->t_integrate);
    solid_verlet_drift(p, h, s->x_prev);
    fsi_timer_stop(&s->timers, s->t_integrate);
    if (internal_force(s, t, h) != 0)
        return -2;
    fsi_timer_start(&s->timers, s->t_integrate);
    external_forces(s, t, s->f_ext);
    int rc = solid_verlet_kick(p, forces, h, &s->integrator, s->x_prev, dw, fault);
    fsi_timer_stop(&s->timers, s->t_integrate);
    return rc;
}

/* The integrator over one window [t0, t0 + dt] in equal sub-steps. */
static int advance(solid_run *s, double t0, double dt, int window)
{
    solid_particles *p = &s->p;
    solid_forces forces = {s->f_int, s->f_ext, s->f_ext_prev};
    /* The acceleration at t_k with this window's fluid load (the one computed at the
     * end of the last window used the previous load). */
    external_forces(s, t0, s->f_ext);
    solid_acceleration(p, &forces, &s->integrator);
    if (dt <= 0.0)
        return 0;

    double stable = solid_model_stable_dt(s->model, p);
    double h_max = s->safety * stable;
    if (s->rk4) {
        const double c = largest_damping(s);
        if (c > 0.0)
            h_max = fmin(h_max, SOLID_RK4_MAX_DAMPING_STEP / c);
    }
    if (!(h_max > 0.0) || !isfinite(h_max) || dt / h_max > (double)MAX_SUBSTEPS) {
        snprintf(s->msg, sizeof s->msg, "the model's stable step is %g s at t = %.9g s "
                 "(window %d): the window of %g s cannot be sub-cycled", stable, t0, window,
                 dt);
        return -1;
    }
    /* 1e-9: a window equal to a whole number of sub-steps up to round-off does not
     * get one more. */
    long n = (long)ceil(dt / h_max - 1e-9);
    if (n < 1)
        n = 1;
    double h = dt / (double)n;
    s->substeps += n;
    s->substeps_computed += n;
    for (int i = 0; i < p->n; i++)
        for (int d = 0; d < FSI_DIM; d++) {
            const int k = i * FSI_DIM + d;
            s->fluid_impulse[d] += dt * s->f_fluid[k];
            s->fluid_work_at_sent += dt * s->f_fluid[k] * s->iface.u_fluid[k];
        }
    for (long j = 0; j < n; j++) {
        double t = t0 + dt * (double)(j + 1) / (double)n;
        /* f_ext_prev: the external forces at the sub-step's start (its work). */
        double *swap = s->f_ext_prev;
        s->f_ext_prev = s->f_ext;
        s->f_ext = swap;
        forces.external = s->f_ext;
        forces.external_prev = s->f_ext_prev;
        double dw = 0.0;
        solid_fault fault;
        int rc;
        if (s->rk4) {
            /* The stages' force evaluations are timed as internal_force; the rest of
             * the step is integration. */
            const double force0 = s->timers.seconds[s->t_force], wall0 = fsi_wall_seconds();
            rc = solid_rk4_step(p, t - h, h, &s->integrator, &s->rk4_state, &forces, rk4_forces,
                                s, s->x_prev, &dw, &fault);
            s->timers.seconds[s->t_integrate] +=
                fsi_wall_seconds() - wall0 - (s->timers.seconds[s->t_force] - force0);
        } else {
            rc = verlet_substep(s, &forces, t, h, &dw, &fault);
        }
        if (rc == -2) {
            /* The model names the point, its position and t; add the window and the
             * sub-step, as the integrator's and the energy check's messages do, so
             * every "unstable" stop can be placed in the same schedule. */
            size_t len = strlen(s->msg);
            if (len + 1 < sizeof s->msg)
                snprintf(s->msg + len, sizeof s->msg - len, " (window %d, sub-step %ld of "
                         "%ld)", window, j + 1, n);
            return -1;
        }
        for (int i = 0; i < p->n; i++) {
            const double mc = s->interface_damping[i] * p->density[i] * p->volume[i];
            for (int d = 0; d < FSI_DIM; d++) {
                const int k = i * FSI_DIM + d;
                const double dx = p->x[k] - s->x_prev[k];
                s->fluid_work += s->f_fluid[k] * dx;
                s->impedance_work += mc * (s->iface.u_fluid[k] - dx / h) * dx;
            }
        }
        s->work += dw;
        s->work_in += fmax(dw, 0.0);
        if (rc != 0) {
            char at[128];
            snprintf(s->msg, sizeof s->msg, "%s at particle %d %s at t = %.9g s (window %d, "
                     "sub-step %ld of %ld): the integration is unstable",
                     fault.what, p->id[fault.particle],
                     where_text(s, fault.particle, at, sizeof at), t, window, j + 1, n);
            return -1;
        }
    }
    return 0;
}

/* After a window: every point inside the generous box, energy within its budget. */
static int check_health(solid_run *s, double t, int window)
{
    const solid_particles *p = &s->p;
    const int i = fsi_outside_box(p->x, p->n, s->box_min, s->box_max);
    if (i >= 0) {
        char at[128];
        snprintf(s->msg, sizeof s->msg, "particle %d %s left the domain (more than %g body "
                 "diagonals from the solid's initial box) at t = %.9g s (window %d)",
                 p->id[i], where_text(s, i, at, sizeof at), ESCAPE_DIAGONALS, t, window);
        return -1;
    }
    /* Physically E(t) = E0 + W(t) - D(t) with dissipation D >= 0 (damping, plastic
     * flow, broken bonds), so E(t) <= E0 + W_in(t), the gross work put in. An
     * unstable integration creates energy from nothing. */
    double kinetic = solid_kinetic_energy(p);
    double strain = solid_model_strain_energy(s->model, p);
    double energy = kinetic + strain, budget = s->energy0 + s->work_in;
    s->kinetic = kinetic;
    s->strain = strain;
    if (!isfinite(energy) || energy > s->energy_limit * budget + s->energy_floor) {
        /* Name the fastest particle: where the instability is growing. */
        double speed;
        const int fastest = fsi_fastest(p->v, p->n, &speed);
        char at[128];
        snprintf(s->msg, sizeof s->msg, "energy grew to %.6g J (kinetic %.6g, strain %.6g), "
                 "%.3g times the initial energy plus the work put in (%.6g J), above "
                 "energy_growth_limit = %g; fastest: particle %d %s at %.3g m/s; at "
                 "t = %.9g s (window %d): the integration is unstable", energy, kinetic,
                 strain, budget > 0 ? energy / budget : INFINITY, budget, s->energy_limit,
                 p->id[fastest], where_text(s, fastest, at, sizeof at), speed, t,
                 window);
        return -1;
    }
    return 0;
}

static int write_frame(solid_run *s, int frame, double t, long window)
{
    const solid_particles *p = &s->p;
    for (int k = 0; k < p->n * FSI_DIM; k++)
        s->scratch[k] = p->x[k] - p->x0[k];
    if (fsi_h5_begin_frame(s->out, frame, t, window, p->n, p->x) != 0 ||
        fsi_h5_write_field_real(s->out, "displacement", s->scratch, FSI_DIM) != 0 ||
        fsi_h5_write_field_real(s->out, "velocity", p->v, FSI_DIM) != 0 ||
        fsi_h5_write_field_real(s->out, "acceleration", p->a, FSI_DIM) != 0 ||
        fsi_h5_write_field_real(s->out, "interface_force", s->f_fluid, FSI_DIM) != 0 ||
        fsi_h5_write_field_real(s->out, "interface_pressure", s->p_fluid, 1) != 0 ||
        solid_model_write_fields(s->model, s->out) != 0)
        return -1;
    /* What ParaView's SPH interpolators take: mass, density and h (the displacement
     * is written, so its scratch holds the masses now). */
    for (int i = 0; i < p->n; i++)
        s->scratch[i] = p->density[i] * p->volume[i];
    if (fsi_h5_write_field_real(s->out, "mass", s->scratch, 1) != 0 ||
        fsi_h5_write_field_real(s->out, "density", solid_model_density(s->model, p), 1) != 0 ||
        fsi_h5_write_frame_constant(s->out, "smoothing_length",
                                    solid_model_smoothing_length(s->model)) != 0)
        return -1;
    return fsi_h5_end_frame(s->out);
}

/* The diagnostics row of an accepted window (solid_diagnostics.h), timed as output. */
static int write_diagnostics(solid_run *s, double t, int window, double dt)
{
    const solid_window_summary w = {window, dt, s->substeps - s->window_first_substep,
                                    s->kinetic, s->strain, s->work, s->fluid_work,
                                    s->fluid_work_at_sent, s->impedance_work, s->f_fluid,
                                    s->max_speed};
    fsi_timer_start(&s->timers, s->t_output);
    const int rc = solid_diagnostics_write(&s->diagnostics, t, &s->p, s->integrator.gravity,
                                           &w, s->msg, sizeof s->msg);
    fsi_timer_stop(&s->timers, s->t_output);
    return rc;
}

int main(void)
{
    fsi_participant *part = fsi_open(NULL, ROLE, NULL, DBL_MAX);
    if (!part)
        return FSI_EXIT_RUN_FAILURE;
    solid_run s;
    memset(&s, 0, sizeof s);
    s.c = fsi_participant_case(part);
    if (setup(&s, part) != 0) {
        fsi_abort(part, "%s", s.msg);
        free_run(&s);
        return FSI_EXIT_RUN_FAILURE;
    }
    s.t_force = fsi_timer_index(&s.timers, "internal_force");
    s.t_integrate = fsi_timer_index(&s.timers, "integration");
    s.t_exchange = fsi_timer_index(&s.timers, "exchange");
    s.t_output = fsi_timer_index(&s.timers, "output");
    /* A restarted run goes on from the checkpoint's state (docs/checkpoints.md). */
    if (fsi_restart_state(part) && restore_state(&s, fsi_restart_state(part)) != 0) {
        fsi_abort(part, "restart: %s", s.msg);
        free_run(&s);
        return FSI_EXIT_RUN_FAILURE;
    }
    /* Cut back to the checkpoint's window at a restart, as probes.csv. */
    if (solid_diagnostics_open(&s.diagnostics, &s.geometry, fsi_output_dir(part),
                               fsi_participant_name(part),
                               fsi_restart_state(part) ? (off_t)s.diagnostics_bytes : -1,
                               s.msg, sizeof s.msg) != 0) {
        fsi_abort(part, "%s", s.msg);
        free_run(&s);
        return FSI_EXIT_RUN_FAILURE;
    }

    while (fsi_ongoing(part)) {
        double dt = fsi_window(part), t0 = fsi_time(part);
        int window = fsi_window_index(part);

        /* Implicit coupling: back to the window's start when the coupler repeats it;
         * the state to come back to, at the window's first iteration. */
        if ((fsi_requires_reading_checkpoint(part) && restore_state(&s, &s.saved) != 0) ||
            (fsi_requires_writing_checkpoint(part) && save_state(&s) != 0)) {
            fsi_abort(part, "window %d, iteration %d: %s", window, fsi_iteration(part), s.msg);
            break;
        }
        /* A coupled checkpoint is this state on disk (docs/checkpoints.md). */
        if (fsi_requires_writing_checkpoint(part) && fsi_write_checkpoint(part, &s.saved) != 0) {
            fsi_abort(part, "window %d: cannot write the solid's checkpoint", window);
            break;
        }
        s.window_first_substep = s.substeps;
        fsi_timer_start(&s.timers, s.t_exchange);
        int rc = exchange(&s, part);
        fsi_timer_stop(&s.timers, s.t_exchange);
        if (rc != 0) {
            fsi_abort(part, "window %d: %s", window, s.msg);
            break;
        }
        if (advance(&s, t0, dt, window) != 0 || check_health(&s, t0 + dt, window) != 0) {
            fsi_abort(part, "%s", s.msg);
            break;
        }
        solid_probes_set(&s.probes, &s.p, part);
        /* Where the particles sent at t_k are at t_k + dt: the library compares it with
         * the motion the fluid was given (nothing in an explicit run). */
        fsi_interface end;
        solid_interface_window_end(&s.iface, &s.p, &end);
        if (fsi_write_window_end(part, &end) != 0) {
            fsi_abort(part, "window %d: cannot send the positions of %d particles at the "
                      "window's end", window, end.n);
            break;
        }
        const int frame = fsi_output_frame(part);
        s.max_speed = 0.0;      /* for the progress line and the diagnostics row */
        if (s.p.n > 0)
            fsi_fastest(s.p.v, s.p.n, &s.max_speed);
        const long substeps = s.substeps - s.window_first_substep;
        fsi_set_progress(part, substeps > 0 ? dt / (double)substeps : 0.0, s.max_speed);
        fsi_advance(part, DBL_MAX);   /* sub-cycling: the solid never limits the window */
        /* Output only of the state the run goes on from. */
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
            fsi_abort(part, "window %d: %s", window, s.msg);
            break;
        }
    }
    if (s.model) {
        fsi_info("energy at the end: kinetic %.6g J, strain %.6g J; initial %.6g J, work "
                 "of loads, gravity and fluid %.6g J (gross input %.6g J)",
                 solid_kinetic_energy(&s.p), solid_model_strain_energy(s.model, &s.p),
                 s.energy0, s.work, s.work_in);
        if (fsi_coupled(part)) {
            char j[FSI_VECTOR_TEXT_SIZE];
            fsi_info("loads received from the fluid: impulse (%s) N s, work at the "
                     "velocity sent %.9g J, work over the solid's motion %.9g J",
                     fsi_vector_text(j, sizeof j, s.fluid_impulse), s.fluid_work_at_sent,
                     s.fluid_work);
            if (s.iface.density_min <= s.iface.density_max)    /* something was sent */
                fsi_info("interface: density sent %.17g to %.17g kg/m^3", s.iface.density_min,
                         s.iface.density_max);
        }
        /* One "bond update" is one directed bond through one internal-force call: the
         * unit bench/solid_validation.sh reports (docs/performance.md). Particle-steps
         * count integrator steps over the internal force's time; with RK4 a step takes
         * four evaluations. Both count what was computed, repeated windows of an
         * implicit run included, as the timers do. */
        const double force_s = s.timers.seconds[s.t_force];
        const double updates =
            (double)solid_model_interaction_count(s.model) * (double)s.force_calls;
        char repeated[96] = "";
        if (s.substeps_computed != s.substeps)
            snprintf(repeated, sizeof repeated, "; %ld of them in accepted windows",
                     s.substeps);
        fsi_info("performance: %ld sub-steps (%s, %ld force evaluations%s) of %d particles "
                 "and %lld interactions on %d thread(s); internal force %.3f s (%.4g "
                 "interaction updates/s, %.4g particle-steps/s), integration %.3f s",
                 s.substeps_computed, s.rk4 ? "RK4" : "velocity Verlet", s.force_calls,
                 repeated, s.p.n, (long long)solid_model_interaction_count(s.model),
                 omp_get_max_threads(), force_s, force_s > 0.0 ? updates / force_s : 0.0,
                 force_s > 0.0 ? (double)s.p.n * (double)s.substeps_computed / force_s : 0.0,
                 s.timers.seconds[s.t_integrate]);
    }
    free_run(&s);
    return fsi_close(part, &s.timers);
}
