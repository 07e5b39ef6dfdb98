/* Example solid participant: independent mass-spring oscillators, one per interface
 * particle, each loaded by whatever the fluid returns. Small enough to read in one
 * sitting; docs/participant_api.md walks through it. With the linear_dashpot fluid,
 * particle i obeys m u'' + c u' + (k_i + k_f) u = 0, which bench/ and the tests
 * compare against the closed-form solution.
 *
 * It also shows what implicit coupling asks of a solid (core/participant.h): save the
 * state at a window's first iteration, restore it when the coupler repeats the window,
 * report the positions at the window's end, and write output only once the window is
 * accepted. In an explicit run none of that does anything. */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "dim.h"
#include "h5_output.h"
#include "log.h"
#include "participant.h"
#include "state_store.h"

typedef struct {
    int n;
    double mass, time_step;
    double *stiffness;       /* per particle [N/m] */
    int32_t *id;
    double *position, *velocity, *acceleration;             /* n * FSI_DIM */
    double *volume, *density;   /* n: a lattice cell each, mass / volume [kg/m^3] */
    double *load;            /* force from the fluid, held over the window */
} springs;

/* y displacement of particle i is its FSI_DIM-vector's component 1. */
#define UY(s, i) ((s)->position[(i) * FSI_DIM + 1])
#define VY(s, i) ((s)->velocity[(i) * FSI_DIM + 1])
#define AY(s, i) ((s)->acceleration[(i) * FSI_DIM + 1])

static int springs_init(springs *s, const fsi_case *c)
{
    s->n = (int)fsi_case_get_int(c, "solid", "particles", 100);
    s->mass = fsi_case_get_real(c, "solid", "mass", 1.0);
    s->time_step = fsi_case_get_real(c, "solid", "time_step", 1e-4);
    double k = fsi_case_get_real(c, "solid", "stiffness", 100.0);
    double spread = fsi_case_get_real(c, "solid", "stiffness_spread", 0.5);
    double u0 = fsi_case_get_real(c, "solid", "initial_displacement", 0.01);
    double spacing = fsi_case_get_real(c, "solid", "spacing", 0.01);
    size_t n = (size_t)s->n, v = n * FSI_DIM;
    s->stiffness = calloc(n, sizeof(double));
    s->id = calloc(n, sizeof(int32_t));
    s->position = calloc(v, sizeof(double));
    s->velocity = calloc(v, sizeof(double));
    s->acceleration = calloc(v, sizeof(double));
    s->load = calloc(v, sizeof(double));
    s->volume = calloc(n, sizeof(double));
    s->density = calloc(n, sizeof(double));
    if (!s->stiffness || !s->id || !s->position || !s->velocity || !s->acceleration ||
        !s->load || !s->volume || !s->density)
        return -1;
    for (int i = 0; i < s->n; i++) {
        s->stiffness[i] = k * (1.0 + (s->n > 1 ? spread * i / (s->n - 1) : 0.0));
        s->id[i] = i;
        s->position[i * FSI_DIM] = i * spacing;
        UY(s, i) = u0;
        s->volume[i] = pow(spacing, FSI_DIM);
        s->density[i] = s->mass / s->volume[i];
        AY(s, i) = -s->stiffness[i] * u0 / s->mass;
    }
    return 0;
}

/* The state a repeated window starts from: positions, velocities and accelerations
 * (the load is set anew from the fluid's answer in every window). */
static int springs_save(const springs *s, fsi_state *st)
{
    const size_t v = (size_t)s->n * FSI_DIM * sizeof(double);
    fsi_state_clear(st);
    return fsi_state_put(st, "position", s->position, v) |
           fsi_state_put(st, "velocity", s->velocity, v) |
           fsi_state_put(st, "acceleration", s->acceleration, v);
}

static int springs_restore(springs *s, const fsi_state *st)
{
    const size_t v = (size_t)s->n * FSI_DIM * sizeof(double);
    return fsi_state_get(st, "position", s->position, v) |
           fsi_state_get(st, "velocity", s->velocity, v) |
           fsi_state_get(st, "acceleration", s->acceleration, v);
}

static void springs_free(springs *s)
{
    free(s->stiffness);
    free(s->id);
    free(s->position);
    free(s->velocity);
    free(s->acceleration);
    free(s->load);
    free(s->volume);
    free(s->density);
}

/* Loads arrive for the particles we sent, by id. */
static int take_loads(springs *s, const fsi_interface *in)
{
    memset(s->load, 0, (size_t)s->n * FSI_DIM * sizeof(double));
    for (int j = 0; j < in->n; j++) {
        int i = in->id[j];
        if (i < 0 || i >= s->n)
            return -1;
        for (int d = 0; d < FSI_DIM; d++)
            s->load[i * FSI_DIM + d] = in->force[j * FSI_DIM + d];
    }
    return 0;
}

/* Velocity Verlet with the fluid load held constant over the window; sub-steps no
 * larger than time_step (stable for time_step < 2 / omega_max). */
static void springs_advance(springs *s, double dt)
{
    int substeps = (int)ceil(dt / s->time_step - 1e-12);
    if (substeps < 1)
        return;
    double h = dt / substeps;
    for (int step = 0; step < substeps; step++)
        for (int i = 0; i < s->n; i++) {
            VY(s, i) += 0.5 * h * AY(s, i);
            UY(s, i) += h * VY(s, i);
            AY(s, i) = (-s->stiffness[i] * UY(s, i) + s->load[i * FSI_DIM + 1]) / s->mass;
            VY(s, i) += 0.5 * h * AY(s, i);
        }
}

static int write_frame(fsi_h5_writer *out, const springs *s, int frame, double t, long window)
{
    if (fsi_h5_begin_frame(out, frame, t, window, s->n, s->position) != 0 ||
        fsi_h5_write_field_real(out, "velocity", s->velocity, FSI_DIM) != 0 ||
        fsi_h5_write_field_real(out, "acceleration", s->acceleration, FSI_DIM) != 0 ||
        fsi_h5_write_field_real(out, "load", s->load, FSI_DIM) != 0 ||
        fsi_h5_write_field_int(out, "id", s->id, 1) != 0)
        return -1;
    return fsi_h5_end_frame(out);
}

int main(void)
{
    fsi_participant *p = fsi_open(NULL, "solid", NULL, DBL_MAX);
    if (!p)
        return FSI_EXIT_RUN_FAILURE;
    springs s = {0};
    if (springs_init(&s, fsi_participant_case(p)) != 0) {
        fsi_abort(p, "out of memory for %d particles", s.n);
        return FSI_EXIT_RUN_FAILURE;
    }
    fsi_h5_writer *out = fsi_h5_create(fsi_output_dir(p), fsi_participant_name(p),
                                       "spring_oscillators");
    if (!out) {
        fsi_abort(p, "cannot create the output file");
        return FSI_EXIT_RUN_FAILURE;
    }
    static const fsi_h5_field_info fields[] = {
        {"static/stiffness", "N/m", "Spring stiffness k_i of the particle's oscillator."},
        {"velocity", "m/s", "Particle velocity."},
        {"acceleration", "m/s^2", "Particle acceleration."},
        {"load", "N", "Force from the fluid, held over the window."},
        {"id", "1", "Particle index."},
    };
    if (fsi_h5_describe_fields(out, fields, 5) != 0 ||
        fsi_h5_write_static_real(out, "stiffness", s.stiffness, s.n, 1) != 0) {
        fsi_abort(p, "cannot write the static data: %s", fsi_h5_last_error());
        fsi_h5_close(out);
        springs_free(&s);
        return FSI_EXIT_RUN_FAILURE;
    }
    int probe_uy = fsi_add_probe(p, "p0_uy [m]");
    int probe_vy = fsi_add_probe(p, "p0_vy [m/s]");

    fsi_timers timers = {0};
    int t_solve = fsi_timer_index(&timers, "solid_advance");
    int t_output = fsi_timer_index(&timers, "output");
    fsi_interface state = {.n = s.n, .id = s.id, .position = s.position,
                           .velocity = s.velocity, .acceleration = s.acceleration,
                           .volume = s.volume, .density = s.density};
    fsi_interface loads;
    /* Every particle is sent in every window, so the window's end is the same ids with
     * their positions at t_k + dt. */
    const fsi_interface end = {.n = s.n, .id = s.id, .position = s.position};
    fsi_state saved = {0};
    /* A run restarted from a coupled checkpoint goes on from its state. */
    if (fsi_restart_state(p) && springs_restore(&s, fsi_restart_state(p)) != 0) {
        fsi_abort(p, "the checkpoint's state does not fit %d particles", s.n);
        return fsi_close(p, NULL);
    }

    while (fsi_ongoing(p)) {
        double dt = fsi_window(p);
        if ((fsi_requires_reading_checkpoint(p) && springs_restore(&s, &saved) != 0) ||
            (fsi_requires_writing_checkpoint(p) &&
             (springs_save(&s, &saved) != 0 || fsi_write_checkpoint(p, &saved) != 0))) {
            fsi_abort(p, "cannot save or restore the state of window %d", fsi_window_index(p));
            break;
        }
        if (fsi_write_interface(p, &state) != 0) {
            fsi_abort(p, "cannot publish the state of window %d", fsi_window_index(p));
            break;
        }
        fsi_read_interface(p, &loads);
        if (take_loads(&s, &loads) != 0) {
            fsi_abort(p, "load for an unknown particle id in window %d", fsi_window_index(p));
            break;
        }
        fsi_timer_start(&timers, t_solve);
        springs_advance(&s, dt);
        fsi_timer_stop(&timers, t_solve);
        if (!isfinite(UY(&s, 0))) {
            fsi_abort(p, "particle 0 displacement is not finite at t = %.9g s (window %d)",
                      fsi_time(p) + dt, fsi_window_index(p));
            break;
        }
        fsi_set_probe(p, probe_uy, UY(&s, 0));
        fsi_set_probe(p, probe_vy, VY(&s, 0));
        if (fsi_write_window_end(p, &end) != 0) {
            fsi_abort(p, "cannot send the positions at the end of window %d",
                      fsi_window_index(p));
            break;
        }
        const int frame = fsi_output_frame(p), window = fsi_window_index(p);
        const double t_end = fsi_time(p) + dt;
        fsi_advance(p, DBL_MAX);    /* sub-cycling: the solid never limits the window */
        if (frame >= 0 && fsi_window_complete(p)) {     /* the window is accepted */
            fsi_timer_start(&timers, t_output);
            int rc = write_frame(out, &s, frame, t_end, window);
            fsi_timer_stop(&timers, t_output);
            if (rc != 0) {
                fsi_abort(p, "cannot write output frame %d: %s", frame, fsi_h5_last_error());
                break;
            }
        }
    }
    fsi_state_free(&saved);
    fsi_h5_close(out);
    springs_free(&s);
    return fsi_close(p, &timers);
}
