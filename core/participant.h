/* The participant library: how a solver joins a coupled run (docs/participant_api.md).
 *
 *     fsi_participant *p = fsi_open(NULL, "solid", NULL, dt_stable);
 *     int tip = fsi_add_probe(p, "tip_uy");
 *     while (fsi_ongoing(p)) {                 // blocks until the coupler grants a window
 *         double dt = fsi_window(p);
 *         fsi_write_interface(p, &my_state);   // solid: state at t_k
 *         fsi_read_interface(p, &loads);       // solid: the fluid's loads for this window
 *         ... advance by dt (sub-cycling as needed) ...
 *         fsi_set_probe(p, tip, uy);
 *         if (fsi_output_frame(p) >= 0) ... write output at fsi_time(p) + dt ...
 *         fsi_advance(p, dt_next_max);
 *     }
 *     return fsi_close(p, &timers);
 *
 * The run is coordinated through the environment `fsi run` sets for every process:
 * FSI_PARTICIPANT (name), FSI_CASE (resolved case file), FSI_OUT (output folder),
 * FSI_RUN_ID and FSI_LCM_URL. With FSI_WRITE_INITIAL=1 (fsi run --check
 * --write-initial) the participant runs alone: no bus, one window 0 of zero length
 * (probes, frame 0), then fsi_ongoing returns 0; fsi_coupled is 0.
 *
 * Failure: when the run is aborted (another process failed) or the coupler falls
 * silent for [run] watchdog_timeout, the library prints why and exits the process
 * with status 1; output files are closed between frames, so they stay readable.
 * A solver that fails itself calls fsi_abort() so that everyone stops at once.
 *
 * Ownership: the handle owns the case, the bus and the buffers that
 * fsi_read_interface() hands out (valid until the next read or fsi_close). */
#ifndef FSI_PARTICIPANT_H
#define FSI_PARTICIPANT_H

#include <stdint.h>

#include "case_file.h"
#include "state_store.h"
#include "timers.h"

typedef struct fsi_participant fsi_participant;

/* Interface particle data. The solid writes id, position, velocity, acceleration
 * (n * FSI_DIM, particle-major), volume and density (n each; all of them required,
 * fsi_write_interface refuses a state of n > 0 that lacks one); the fluid writes id,
 * pressure and force (n * FSI_DIM) for the particles it received, and its acoustic
 * impedance rho0 c0 (one number: what the solid needs to answer the fluid within a
 * window, docs/coupling.md). What the solid reads back also holds, in velocity, the
 * window-mean velocity the fluid moved each particle with (the velocity it sent, or
 * in an implicit run the iteration's motion), the reference of the impedance term. Initialise with designated initialisers: fields may be
 * added. */
typedef struct {
    int n;
    int32_t *id;
    double *position;
    double *velocity;
    double *acceleration;
    double *volume;             /* [m^FSI_DIM], the particle's reference volume */
    double *density;            /* [kg/m^3], the solid's current density at the particle
                                 * (the fluid needs the solid's mass, density * volume) */
    double *pressure;
    double *force;
    double impedance;           /* [Pa s/m], fluid only */
} fsi_interface;

/* Joins the run. NULL name/case_path are taken from FSI_PARTICIPANT/FSI_CASE.
 * role is "fluid" or "solid"; dt_first is the largest first window this solver can
 * take [s]; it stands as this participant's proposal until its first fsi_advance()
 * (window 0 has zero length, so the proposal made there sizes window 1). Returns NULL with a message when the environment or case is unusable.
 * Registration with the coupler happens in the first fsi_ongoing() call. */
fsi_participant *fsi_open(const char *name, const char *role, const char *case_path,
                          double dt_first);

/* Declares a probe column "<probe>_<quantity>" before the first fsi_ongoing(),
 * optionally followed by its unit in brackets, "tip_uy [m]": probes.csv's header then
 * names the column tip_uy and its units line gives m (docs/output.md). Returns its
 * index for fsi_set_probe, or -1. */
int fsi_add_probe(fsi_participant *p, const char *column);

/* Blocks until the coupler grants the next window; 1 when there is one to compute,
 * 0 when the run is over (then call fsi_close). */
int fsi_ongoing(fsi_participant *p);

double fsi_window(const fsi_participant *p);      /* dt of the current window [s] */
double fsi_time(const fsi_participant *p);        /* t_k, its start [s] */
int fsi_window_index(const fsi_participant *p);   /* k */
/* True when the coupler records probes at the end of this window: a solver whose
 * probes are costly may compute them only then (fsi_set_probe is always allowed). */
int fsi_probe_window(const fsi_participant *p);
/* Frame index to write at the end of this window (at t_k + dt), or -1. */
int fsi_output_frame(const fsi_participant *p);
/* True when the other side of the interface takes part in this run. */
int fsi_coupled(const fsi_participant *p);

/* Publishes this side's interface data for the current window. */
int fsi_write_interface(fsi_participant *p, const fsi_interface *data);
/* Blocks until the other side's data for the current window has arrived and points
 * 'data' at it (arrays owned by p). Uncoupled: n = 0. */
int fsi_read_interface(fsi_participant *p, fsi_interface *data);

/* Implicit coupling ([run] scheme = implicit, docs/coupling.md): the coupler repeats
 * a window until the interface converges. A participant saves its state at the start
 * of a window's first iteration and restores it whenever the window is repeated,
 * the way preCICE's requiresWritingCheckpoint / requiresReadingCheckpoint work:
 *
 *     while (fsi_ongoing(p)) {
 *         if (fsi_requires_reading_checkpoint(p)) restore(&saved);
 *         if (fsi_requires_writing_checkpoint(p)) save(&saved);
 *         ... exchange and advance as in an explicit run ...
 *         fsi_write_window_end(p, &end);       // solid: its positions at t_k + dt
 *         fsi_advance(p, dt_next_max);         // implicit: waits for the verdict
 *         if (fsi_window_complete(p)) ... output ...
 *     }
 *
 * In an explicit run the two checkpoint calls are always 0, fsi_write_window_end does
 * nothing and fsi_window_complete is always 1, so one loop serves both. */
int fsi_iteration(const fsi_participant *p);      /* sub-iteration of the window, 0.. */
/* True at the first iteration of each window of an implicit run, and at the start of
 * a window the coupler takes a coupled checkpoint at: save the state now, before the
 * exchange, and hand it to fsi_write_checkpoint. */
int fsi_requires_writing_checkpoint(const fsi_participant *p);
/* True when the coupler repeats the window: restore the state saved at its start
 * before anything else. */
int fsi_requires_reading_checkpoint(const fsi_participant *p);
/* Solid: the positions at the window's end (t_k + dt) of the particles it wrote at
 * the window's start, same ids in the same order (only n, id and position are read).
 * The library compares them with the motion the fluid was given and chooses the
 * motion of the next iteration (docs/coupling.md). 0, or -1 with a message. */
int fsi_write_window_end(fsi_participant *p, const fsi_interface *end);
/* Coupled checkpoints (fsi run --checkpoint-interval, docs/checkpoints.md): the state
 * just saved, complete enough that a run restored from it goes on bit for bit as this
 * one does. Written to the run's checkpoint folder when the coupler asked for one at
 * this window's start; nothing otherwise. 0, or -1 with a message (then abort). */
int fsi_write_checkpoint(fsi_participant *p, const fsi_state *st);
/* The state to start from when the run is restarted from a checkpoint (fsi run
 * --restart): restore it after setting up and before the first fsi_ongoing(); NULL in
 * a run from the beginning. Owned by p. */
const fsi_state *fsi_restart_state(const fsi_participant *p);
/* After fsi_advance: 1 when the window is accepted and the run goes on from its end
 * (write its output now), 0 when the coupler repeats it. */
int fsi_window_complete(const fsi_participant *p);

/* Value of a probe at the end of the current window. */
void fsi_set_probe(fsi_participant *p, int index, double value);

/* Optional: this participant's own step [s] (its last sub-step in the window) and its
 * largest particle speed [m/s] at the window's end, for the coupler's progress line;
 * sent with the next fsi_advance() (done_t's stats "step" and "max_speed",
 * docs/protocol.md) and every one after it, until changed. */
void fsi_set_progress(fsi_participant *p, double step, double max_speed);

/* Reports the window done and proposes the largest next window [s]. */
int fsi_advance(fsi_participant *p, double dt_next_max);

/* Stops everyone: publishes an abort naming this participant with the reason. */
void fsi_abort(fsi_participant *p, const char *fmt, ...) __attribute__((format(printf, 2, 3)));

/* Sends the final report (timers may be NULL), waits until the coupler has it,
 * frees everything. Returns the process exit status to use. */
int fsi_close(fsi_participant *p, const fsi_timers *timers);

const fsi_case *fsi_participant_case(const fsi_participant *p);
const char *fsi_participant_name(const fsi_participant *p);
const char *fsi_output_dir(const fsi_participant *p);

#endif
