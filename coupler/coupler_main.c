/* The coupler: registers the participants the case names, grants coupling windows
 * in lockstep (serial-staggered: the solid publishes its state at t_k, the fluid
 * advances and publishes loads, the solid advances), ends windows on output and probe
 * times, watches every process's liveness, and stops the run naming whoever failed.
 * Protocol: docs/protocol.md. */
#include <errno.h>
#include <float.h>
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "bus.h"
#include "case_file.h"
#include "checkpoint_folder.h"
#include "fsi_abort_t.h"
#include "fsi_done_t.h"
#include "fsi_heartbeat_t.h"
#include "fsi_register_t.h"
#include "fsi_step_t.h"
#include "fsi_welcome_t.h"
#include "log.h"
#include "participant_env.h"
#include "probes_csv.h"
#include "progress.h"
#include "request_timer.h"
#include "state_file.h"
#include "timers.h"
#include "window_schedule.h"

#define MAX_PARTICIPANTS 2
#define POLL_SLICE_S 0.05

static const char *const roles[MAX_PARTICIPANTS] = {"fluid", "solid"};

typedef struct {
    char name[64];
    char role[16];
    int registered;
    int pid;
    char host[256];
    double last_heard;
    double dt_proposed;
    int done_window, done_iteration;    /* the last (window, iteration) reported done */
    /* The solid's verdict on its last iteration (implicit coupling; -1: not judged). */
    int converged;
    double displacement_residual, force_residual;
    int history_columns, history_restarted;
    int checkpoint;         /* its last done_t said it wrote its checkpoint part */
    int n_probes;
    char **probe_names;
    double *probe_values;
    int finished;
    int n_stats;
    char **stat_names;
    double *stat_values;
    /* Its own step [s] and largest speed [m/s] of the last window, for the progress
     * line (the "step" and "max_speed" of a done_t's stats, fsi_set_progress); NAN
     * when it reports none (the examples). */
    double step, max_speed;
    /* When to ask again for this window's done_t (core/request_timer.h). */
    fsi_wait_estimate done_wait;
    fsi_request_timer done_timer;
} participant_info;

typedef struct {
    fsi_run_env env;
    fsi_case *case_file;
    fsi_bus *bus;
    participant_info part[MAX_PARTICIPANTS];
    int n_part;
    int window;
    int iteration;          /* sub-iteration of the window (implicit coupling) */
    double t;
    int failed;
    int failure_relayed;    /* the failure was a participant's own abort, not ours to detect */
    char culprit[64];
    char reason[1024];
    fsi_progress progress;
    double window_dt;       /* the length of the last window granted [s] */
    fsi_probes_csv probes;
    fsi_probes_csv coupling_csv;    /* implicit: one row per iteration */
    /* [run] scheme = implicit and what ends a window's iterations */
    int implicit, min_iterations, max_iterations, stop_on_max_iterations;
    long iterations_total, windows_iterated, windows_not_converged;
    int iterations_most;
    /* Coupled checkpoints (docs/checkpoints.md): every checkpoint_interval of simulated
     * time, at the first frame time from next_checkpoint on, the state at the start of
     * window checkpoint_window (-1: none being taken), the coupler's part in pending. */
    double checkpoint_interval, next_checkpoint;
    int checkpoint_window, frames_done;
    fsi_state pending;
    fsi_state restart;      /* the coupler's part of the checkpoint restarted from */
    int restarting;
    double wall_start;
    /* Wall time from each grant to the last done_t: the cost of one coupling window. */
    double *window_wall;
    long n_window_wall, window_wall_capacity;
} coupler;

static participant_info *find(coupler *c, const char *name)
{
    for (int i = 0; i < c->n_part; i++)
        if (strcmp(c->part[i].name, name) == 0)
            return &c->part[i];
    return NULL;
}

static void fail(coupler *c, const char *culprit, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));

static void fail(coupler *c, const char *culprit, const char *fmt, ...)
{
    if (c->failed)
        return;
    c->failed = 1;
    snprintf(c->culprit, sizeof c->culprit, "%s", culprit);
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(c->reason, sizeof c->reason, fmt, ap);
    va_end(ap);
}

static char **copy_strings(char *const *src, int n)
{
    char **dst = calloc((size_t)(n > 0 ? n : 1), sizeof *dst);
    for (int i = 0; i < n; i++)
        dst[i] = strdup(src[i]);
    return dst;
}

static void free_strings(char **s, int n)
{
    for (int i = 0; s && i < n; i++)
        free(s[i]);
    free(s);
}

static void send_welcome(coupler *c, const participant_info *p)
{
    char *names[MAX_PARTICIPANTS], *proles[MAX_PARTICIPANTS];
    for (int i = 0; i < c->n_part; i++) {
        names[i] = c->part[i].name;
        proles[i] = c->part[i].role;
    }
    fsi_welcome_t w = {0};
    w.header.window = -1;
    w.participant = (char *)p->name;
    w.t_start = 0.0;
    w.t_end = fsi_case_get_real(c->case_file, "run", "end_time", 0.0);
    w.n_participants = c->n_part;
    w.participant_names = names;
    w.participant_roles = proles;
    fsi_bus_publish(c->bus, FSI_MSG_WELCOME, &w);
}

static void take_register(coupler *c, participant_info *p, const fsi_register_t *r)
{
    if (strcmp(r->role, p->role) != 0) {
        fail(c, p->name, "participant '%s' registered as a %s, but the case makes it the %s",
             p->name, r->role, p->role);
        return;
    }
    if (!p->registered) {
        p->registered = 1;
        p->pid = r->pid;
        snprintf(p->host, sizeof p->host, "%s", r->host);
        if (!(r->dt_proposed > 0.0)) {
            fail(c, p->name, "participant '%s' registered with a first window of %g s "
                 "(must be > 0)", p->name, r->dt_proposed);
            return;
        }
        p->dt_proposed = r->dt_proposed;
        p->n_probes = r->n_probes;
        p->probe_names = copy_strings(r->probe_names, r->n_probes);
        p->probe_values = calloc((size_t)(r->n_probes > 0 ? r->n_probes : 1), sizeof(double));
        fsi_info("%s registered (pid %d on %s, %d probes)", p->name, p->pid, p->host,
                 p->n_probes);
    }
    /* Answered every time: the previous welcome may have been lost. */
    send_welcome(c, p);
}

/* The participant has reported the current iteration of the current window. */
static int done_now(const coupler *c, const participant_info *p)
{
    return p->done_window == c->window && p->done_iteration == c->iteration;
}

static void take_done(coupler *c, participant_info *p, const fsi_done_t *d)
{
    if (d->header.window != c->window || d->header.iteration != c->iteration ||
        done_now(c, p))
        return;
    if (d->n_probes != p->n_probes) {
        fail(c, p->name, "participant '%s' sent %d probe values, registered %d", p->name,
             d->n_probes, p->n_probes);
        return;
    }
    if (d->status != FSI_STATUS_FINISHED && !(d->dt_next_max > 0.0)) {
        fail(c, p->name, "participant '%s' proposed a next window of %g s in window %d "
             "(must be > 0): its stable step collapsed", p->name, d->dt_next_max, c->window);
        return;
    }
    p->done_window = d->header.window;
    p->done_iteration = d->header.iteration;
    p->converged = d->converged;
    p->displacement_residual = d->displacement_residual;
    p->force_residual = d->force_residual;
    p->history_columns = d->history_columns;
    p->history_restarted = d->history_restarted;
    p->checkpoint = d->checkpoint;
    fsi_request_timer_arrived(&p->done_timer, fsi_wall_seconds(), fsi_bus_message_is_new(c->bus),
                              fsi_bus_measured_loss(c->bus));
    p->dt_proposed = d->dt_next_max;
    for (int s = 0; s < d->n_stats && d->status != FSI_STATUS_FINISHED; s++) {
        if (strcmp(d->stat_names[s], "step") == 0)
            p->step = d->stat_values[s];
        else if (strcmp(d->stat_names[s], "max_speed") == 0)
            p->max_speed = d->stat_values[s];
    }
    if (d->n_probes > 0)   /* an empty array may arrive as NULL */
        memcpy(p->probe_values, d->probe_values, (size_t)d->n_probes * sizeof(double));
    if (d->status == FSI_STATUS_FINISHED) {
        p->finished = 1;
        p->n_stats = d->n_stats;
        p->stat_names = copy_strings(d->stat_names, d->n_stats);
        p->stat_values = malloc((size_t)(d->n_stats > 0 ? d->n_stats : 1) * sizeof(double));
        if (d->n_stats > 0)
            memcpy(p->stat_values, d->stat_values, (size_t)d->n_stats * sizeof(double));
    }
}

static void on_message(fsi_msg_type type, const void *msg, void *user)
{
    coupler *c = user;
    const fsi_header_t *h = msg;
    participant_info *p = find(c, h->sender);
    if (!p)
        return;    /* not a participant of this case: never trusted */
    p->last_heard = fsi_wall_seconds();
    if (type == FSI_MSG_REGISTER)
        take_register(c, p, msg);
    else if (type == FSI_MSG_DONE)
        take_done(c, p, msg);
    else if (type == FSI_MSG_ABORT) {
        const fsi_abort_t *a = msg;
        if (!c->failed)
            c->failure_relayed = 1;
        fail(c, a->culprit, "participant '%s' failed: %s", a->culprit, a->reason);
    }
}

static void check_liveness(coupler *c)
{
    double now = fsi_wall_seconds();
    for (int i = 0; i < c->n_part && !c->failed; i++) {
        participant_info *p = &c->part[i];
        double silent = now - p->last_heard;
        if (p->registered && silent > c->env.watchdog_timeout)
            fail(c, p->name,
                 "participant '%s' (pid %d on %s) not heard for %.1f s at window %d "
                 "(t = %.9g s): dead or hung",
                 p->name, p->pid, p->host, silent, c->window, c->t);
    }
}

static int all_registered(const coupler *c)
{
    for (int i = 0; i < c->n_part; i++)
        if (!c->part[i].registered)
            return 0;
    return 1;
}

static int register_participants(coupler *c)
{
    double timeout = fsi_case_get_real(c->case_file, "run", "register_timeout", 30.0);
    double deadline = fsi_wall_seconds() + timeout;
    while (!all_registered(c) && !c->failed) {
        if (fsi_wall_seconds() > deadline) {
            for (int i = 0; i < c->n_part; i++)
                if (!c->part[i].registered)
                    fail(c, c->part[i].name,
                         "participant '%s' did not register within %.0f s (not started, "
                         "crashed at start, or on another LCM URL?)",
                         c->part[i].name, timeout);
            break;
        }
        fsi_bus_poll(c->bus, POLL_SLICE_S);
        fsi_bus_drain(c->bus);
        check_liveness(c);
    }
    return c->failed ? -1 : 0;
}

/* Waits for every participant's done_t of the current window, asking again for
 * missing ones once they are overdue; returns -1 when the run failed meanwhile. */

/* The progress line (progress.h) with the window granted last and each participant's
 * own step and largest speed as its done_t reported them (fsi_set_progress; nothing
 * for a participant that reports none). */
static void update_progress(coupler *c, int force)
{
    char *d = c->progress.detail;
    const size_t size = sizeof c->progress.detail;
    size_t at = (size_t)snprintf(d, size, "window %.3g s", c->window_dt);
    for (int i = 0; i < c->n_part && at < size; i++)
        if (isfinite(c->part[i].step))
            at += (size_t)snprintf(d + at, size - at, ", %s step %.3g s", c->part[i].name,
                                   c->part[i].step);
    for (int i = 0, first = 1; i < c->n_part && at < size; i++)
        if (isfinite(c->part[i].max_speed)) {
            at += (size_t)snprintf(d + at, size - at, "%s%s %.3g m/s",
                                   first ? " | max speed " : ", ", c->part[i].name,
                                   c->part[i].max_speed);
            first = 0;
        }
    fsi_progress_update(&c->progress, c->t, c->window, force);
}
static int wait_for_done(coupler *c)
{
    double now = fsi_wall_seconds();
    double loss = fsi_bus_measured_loss(c->bus);
    for (int i = 0; i < c->n_part; i++)
        fsi_request_timer_start(&c->part[i].done_timer, &c->part[i].done_wait, now, loss);
    double window_timeout = fsi_case_get_real(c->case_file, "run", "window_timeout", 600.0);
    double started = now;
    for (;;) {
        int missing = 0;
        double next_event = fsi_wall_seconds() + POLL_SLICE_S;
        now = fsi_wall_seconds();
        if (window_timeout > 0 && now - started > window_timeout) {
            for (int i = 0; i < c->n_part; i++)
                if (!done_now(c, &c->part[i])) {
                    fail(c, c->part[i].name,
                         "participant '%s' alive but window %d (t = %.9g s) not done after "
                         "%.0f s ([run] window_timeout): stuck or deadlocked",
                         c->part[i].name, c->window, c->t, window_timeout);
                    break;
                }
            return -1;
        }
        loss = fsi_bus_measured_loss(c->bus);
        for (int i = 0; i < c->n_part; i++) {
            participant_info *p = &c->part[i];
            if (done_now(c, p))
                continue;
            missing++;
            if (fsi_request_timer_due(&p->done_timer, now, loss))
                fsi_bus_request_resend(c->bus, p->name, FSI_MSG_DONE, c->window, c->iteration);
            next_event = fmin(next_event, p->done_timer.next_request);
        }
        if (!missing)
            return 0;
        /* Messages that queued while this process was not scheduled (a loaded
         * machine) count before silence is judged; what they changed is looked at
         * again first. */
        if (fsi_bus_drain(c->bus) > 0)
            continue;
        check_liveness(c);
        if (c->failed)
            return -1;
        fsi_bus_poll(c->bus, next_event - now);
        update_progress(c, 0);
    }
}

static void publish_step(coupler *c, double dt, int flags, int frame)
{
    fsi_step_t s = {0};
    s.header.window = c->window;
    s.header.iteration = c->iteration;
    s.t = c->t;
    s.dt = dt;
    s.flags = flags;
    s.frame = frame;
    fsi_bus_set_heartbeat(c->bus, c->window, FSI_STATE_RUNNING);
    fsi_bus_publish(c->bus, FSI_MSG_STEP, &s);
}

static double smallest_proposal(const coupler *c)
{
    double proposals[MAX_PARTICIPANTS];
    for (int i = 0; i < c->n_part; i++)
        proposals[i] = c->part[i].dt_proposed;
    return fsi_window_smallest_proposal(proposals, c->n_part);
}

static int open_probes(coupler *c, off_t resume_at)
{
    int n = 0;
    for (int i = 0; i < c->n_part; i++)
        n += c->part[i].n_probes;
    char **names = calloc((size_t)(n > 0 ? n : 1), sizeof *names);
    int k = 0;
    for (int i = 0; i < c->n_part; i++)
        for (int j = 0; j < c->part[i].n_probes; j++)
            names[k++] = c->part[i].probe_names[j];
    int rc = resume_at >= 0
                 ? fsi_probes_csv_resume(&c->probes, c->env.out_dir, "probes.csv", n, resume_at)
                 : fsi_probes_csv_open(&c->probes, c->env.out_dir, "probes.csv", n, names);
    free(names);
    if (rc != 0)
        fail(c, FSI_COUPLER_NAME, "%s", c->probes.error);
    return rc;
}

/* A row that cannot be written stops the run: probes.csv then ends at the last
 * complete row. */
static int write_probe_row(coupler *c, double t)
{
    double values[1024];
    int k = 0;
    for (int i = 0; i < c->n_part; i++)
        for (int j = 0; j < c->part[i].n_probes && k < 1024; j++)
            values[k++] = c->part[i].probe_values[j];
    if (fsi_probes_csv_row(&c->probes, t, values) == 0)
        return 0;
    fail(c, FSI_COUPLER_NAME, "%s", c->probes.error);
    return -1;
}

/* Keeps at most this many window timings (8 MB); later windows are not sampled. */
#define MAX_WINDOW_SAMPLES 1000000

static void record_window_wall(coupler *c, double seconds)
{
    if (c->n_window_wall == c->window_wall_capacity) {
        if (c->window_wall_capacity >= MAX_WINDOW_SAMPLES)
            return;
        long cap = c->window_wall_capacity ? 2 * c->window_wall_capacity : 4096;
        double *grown = realloc(c->window_wall, (size_t)cap * sizeof(double));
        if (!grown)
            return;
        c->window_wall = grown;
        c->window_wall_capacity = cap;
    }
    c->window_wall[c->n_window_wall++] = seconds;
}

static const participant_info *solid_of(const coupler *c)
{
    for (int i = 0; i < c->n_part; i++)
        if (strcmp(c->part[i].role, "solid") == 0)
            return &c->part[i];
    return NULL;
}

static int open_coupling_csv(coupler *c, off_t resume_at)
{
    char *names[] = {"window", "iteration", "dt", "displacement_residual", "force_residual",
                     "converged", "history_columns", "history_restarted", "accepted"};
    const int n = (int)(sizeof names / sizeof names[0]);
    if (resume_at >= 0 ? fsi_probes_csv_resume(&c->coupling_csv, c->env.out_dir, "coupling.csv",
                                               n, resume_at) == 0
                       : fsi_probes_csv_open(&c->coupling_csv, c->env.out_dir, "coupling.csv", n,
                                             names) == 0)
        return 0;
    fail(c, FSI_COUPLER_NAME, "%s", c->coupling_csv.error);
    return -1;
}

/* Implicit coupling: whether the iteration just done ends the window (1), the window
 * is repeated (0) or the run stops (-1), from the solid's verdict (docs/coupling.md).
 * A window of length zero, or a run without a solid or a fluid, has nothing to
 * iterate. Every iteration becomes a row of coupling.csv. */
static int judge_iteration(coupler *c, double dt)
{
    if (!c->implicit)
        return 1;
    const participant_info *solid = solid_of(c);
    const int iterations = c->iteration + 1;
    int verdict;
    if (!solid || solid->converged < 0 || !(dt > 0.0))
        verdict = 1;
    else if (solid->converged && iterations >= c->min_iterations)
        verdict = 1;
    else if (iterations < c->max_iterations)
        verdict = 0;
    else if (c->stop_on_max_iterations) {
        fail(c, FSI_COUPLER_NAME, "window %d (t = %.9g s, dt = %.6g s) did not converge in "
             "%d iterations: displacement residual %.3g, force residual %.3g against "
             "coupling_tolerance (raise coupling_max_iterations, shorten max_window, or "
             "set coupling_on_max_iterations = continue)", c->window, c->t, dt, iterations,
             solid->displacement_residual, solid->force_residual);
        verdict = -1;
    } else {
        if (c->windows_not_converged++ < 10)
            fsi_warn("window %d (t = %.9g s) accepted unconverged after %d iterations: "
                     "displacement residual %.3g, force residual %.3g%s", c->window, c->t,
                     iterations, solid->displacement_residual, solid->force_residual,
                     c->windows_not_converged == 10 ? " (no more of these warnings)" : "");
        verdict = 1;
    }
    if (solid && solid->converged >= 0 && dt > 0.0) {
        const double row[] = {c->window, c->iteration, dt, solid->displacement_residual,
                              solid->force_residual, solid->converged,
                              solid->history_columns, solid->history_restarted,
                              verdict == 1};
        if (fsi_probes_csv_row(&c->coupling_csv, c->t, row) != 0) {
            fail(c, FSI_COUPLER_NAME, "%s", c->coupling_csv.error);
            return -1;
        }
        if (verdict == 1) {
            c->windows_iterated++;
            c->iterations_total += iterations;
            if (iterations > c->iterations_most)
                c->iterations_most = iterations;
        }
    }
    return verdict;
}

/* What the coupler needs to grant window 'window' again after a restart: the schedule
 * after planning it, the plan, the counters, the output files' lengths. */
typedef struct {
    int window;
    double t;
    fsi_window_plan plan;
    fsi_window_schedule sched;
    off_t probes_committed, coupling_committed;
    long iterations_total, windows_iterated, windows_not_converged;
    int iterations_most, frames_done;
    double next_checkpoint;
} coupler_saved;

static void participant_entry(char *out, size_t size, const participant_info *p,
                              const char *what)
{
    snprintf(out, size, "coupler.%s.%s", p->name, what);
}

static int save_coupler(coupler *c, const fsi_window_plan *plan, const fsi_window_schedule *sched)
{
    const coupler_saved k = {c->window, c->t, *plan, *sched, c->probes.committed,
                             c->coupling_csv.fd >= 0 ? c->coupling_csv.committed : -1,
                             c->iterations_total, c->windows_iterated,
                             c->windows_not_converged, c->iterations_most, c->frames_done,
                             c->next_checkpoint};
    fsi_state_clear(&c->pending);
    int rc = fsi_state_put(&c->pending, "coupler.saved", &k, sizeof k);
    for (int i = 0; i < c->n_part; i++) {
        char name[64];
        participant_entry(name, sizeof name, &c->part[i], "dt_proposed");
        rc |= fsi_state_put(&c->pending, name, &c->part[i].dt_proposed, sizeof(double));
        participant_entry(name, sizeof name, &c->part[i], "probe_values");
        rc |= fsi_state_put(&c->pending, name, c->part[i].probe_values,
                            (size_t)c->part[i].n_probes * sizeof(double));
    }
    if (rc == 0)
        return 0;
    fail(c, FSI_COUPLER_NAME, "out of memory for the checkpoint of window %d", c->window);
    return -1;
}

static int restore_coupler(coupler *c, fsi_window_plan *plan, fsi_window_schedule *sched)
{
    coupler_saved k;
    int rc = fsi_state_get(&c->restart, "coupler.saved", &k, sizeof k);
    for (int i = 0; rc == 0 && i < c->n_part; i++) {
        char name[64];
        participant_entry(name, sizeof name, &c->part[i], "dt_proposed");
        rc |= fsi_state_get(&c->restart, name, &c->part[i].dt_proposed, sizeof(double));
        participant_entry(name, sizeof name, &c->part[i], "probe_values");
        rc |= fsi_state_get(&c->restart, name, c->part[i].probe_values,
                            (size_t)c->part[i].n_probes * sizeof(double));
    }
    if (rc != 0) {
        fail(c, FSI_COUPLER_NAME, "restart: the checkpoint's coupler.state does not match "
             "this case (its participants or probes differ)");
        return -1;
    }
    c->window = k.window;
    c->t = k.t;
    *plan = k.plan;
    *sched = k.sched;
    c->iterations_total = k.iterations_total;
    c->windows_iterated = k.windows_iterated;
    c->windows_not_converged = k.windows_not_converged;
    c->iterations_most = k.iterations_most;
    c->frames_done = k.frames_done;
    c->next_checkpoint = k.next_checkpoint;
    if (open_probes(c, k.probes_committed) != 0 ||
        (c->implicit && open_coupling_csv(c, k.coupling_committed) != 0))
        return -1;
    fsi_info("restarted at window %d, t = %.9g s", c->window, c->t);
    return 0;
}

/* The checkpoint of the current window's start, once everyone reported its part: the
 * coupler's own, then COMPLETE. */
static int finish_checkpoint(coupler *c)
{
    for (int i = 0; i < c->n_part; i++)
        if (!c->part[i].checkpoint) {
            fail(c, c->part[i].name, "participant '%s' did not write its part of the "
                 "checkpoint at window %d (t = %.9g s): a program that does not call "
                 "fsi_write_checkpoint cannot run with --checkpoint-interval",
                 c->part[i].name, c->window, c->t);
            return -1;
        }
    char dir[4300], path[4400], msg[4600];
    fsi_checkpoint_dir(c->env.out_dir, c->window, dir, sizeof dir);
    snprintf(path, sizeof path, "%s/coupler.state", dir);
    if (fsi_state_write_file(&c->pending, path, msg, sizeof msg) != 0 ||
        fsi_checkpoint_complete(c->env.out_dir, c->window, c->t, c->frames_done, 2, msg,
                                sizeof msg) != 0) {
        fail(c, FSI_COUPLER_NAME, "checkpoint at window %d: %s", c->window, msg);
        return -1;
    }
    fsi_info("checkpoint at window %d, t = %.9g s: %s", c->window, c->t, dir);
    c->checkpoint_window = -1;
    return 0;
}

static int run_windows(coupler *c)
{
    double t_end = fsi_case_get_real(c->case_file, "run", "end_time", 0.0);
    fsi_window_schedule sched;
    fsi_window_schedule_init(&sched, t_end,
                             fsi_case_get_real(c->case_file, "run", "output_interval", 0.01),
                             fsi_case_get_real(c->case_file, "run", "probe_interval", 1e-3),
                             fsi_case_get_real(c->case_file, "run", "max_window", 1e-3));
    /* Window 0 has zero length: everyone exchanges, writes frame 0 and samples probes
     * at t = 0, so the first output and the first probe row describe the initial state. */
    c->window = 0;
    c->iteration = 0;
    c->t = 0.0;
    fsi_window_plan plan = {0.0, 0.0, 0, 1, 0};
    c->checkpoint_window = -1;
    c->next_checkpoint = c->checkpoint_interval;
    if (c->restarting ? restore_coupler(c, &plan, &sched) != 0
                      : open_probes(c, -1) != 0 || (c->implicit && open_coupling_csv(c, -1) != 0))
        return -1;
    double granted = 0.0;
    for (;;) {
        if (c->iteration == 0)
            granted = fsi_wall_seconds();
        const int checkpoint = c->iteration == 0 && c->window == c->checkpoint_window;
        c->window_dt = plan.dt;
        publish_step(c, plan.dt, (plan.probe ? FSI_STEP_PROBE : 0) |
                                     (checkpoint ? FSI_STEP_CHECKPOINT : 0), plan.frame);
        if (wait_for_done(c) != 0)
            return -1;
        if (checkpoint && finish_checkpoint(c) != 0)
            return -1;
        const int verdict = judge_iteration(c, plan.dt);
        if (verdict < 0)
            return -1;
        if (verdict == 0) {
            c->iteration++;     /* the same window again, everyone from its start */
            continue;
        }
        c->iteration = 0;
        if (c->window > 0)
            record_window_wall(c, fsi_wall_seconds() - granted);
        c->t = plan.t_next;
        if (plan.probe && write_probe_row(c, c->t) != 0)
            return -1;
        update_progress(c, 0);
        if (plan.last)
            break;
        /* A checkpoint at the first frame time from each multiple of the interval on:
         * the output then restarts at a frame. */
        const int checkpoint_next = c->checkpoint_interval > 0 && plan.frame >= 0 &&
                                    c->t >= c->next_checkpoint * (1.0 - 1e-12);
        if (plan.frame >= 0)
            c->frames_done = plan.frame + 1;
        plan = fsi_window_schedule_next(&sched, c->t, smallest_proposal(c));
        c->window++;
        if (checkpoint_next) {
            c->next_checkpoint = c->checkpoint_interval * (floor(c->t / c->checkpoint_interval + 1e-9) + 1.0);
            c->checkpoint_window = c->window;
            if (save_coupler(c, &plan, &sched) != 0)
                return -1;
        }
    }
    /* The finishing window: no time advance, everyone sends its final report. */
    c->window++;
    publish_step(c, 0.0, FSI_STEP_FINISH, -1);
    return wait_for_done(c);
}

static void announce_finished(coupler *c)
{
    /* Several copies: a participant waits for one before it exits. */
    fsi_bus_set_heartbeat(c->bus, c->window, FSI_STATE_FINISHED);
    for (int i = 0; i < 10; i++) {
        fsi_heartbeat_t hb = {0};
        hb.header.window = c->window;
        hb.state = FSI_STATE_FINISHED;
        fsi_bus_publish(c->bus, FSI_MSG_HEARTBEAT, &hb);
        usleep(20000);
    }
}

static void announce_abort(coupler *c)
{
    fsi_abort_t a = {0};
    a.header.window = c->window;
    a.culprit = c->culprit;
    a.reason = c->reason;
    for (int i = 0; i < 3; i++)
        fsi_bus_publish(c->bus, FSI_MSG_ABORT, &a);
}

static int by_value(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static void write_window_timing(FILE *log, coupler *c)
{
    if (c->n_window_wall == 0)
        return;
    qsort(c->window_wall, (size_t)c->n_window_wall, sizeof(double), by_value);
    double *w = c->window_wall;
    long n = c->n_window_wall;
    fprintf(log, "window_round_trip_median = %.1f us\nwindow_round_trip_p90 = %.1f us\n"
                 "window_round_trip_max = %.1f us\n",
            1e6 * w[n / 2], 1e6 * w[(long)(0.9 * (double)(n - 1))], 1e6 * w[n - 1]);
}

static void write_bus_counters(FILE *log, const char *who, fsi_bus_counters b)
{
    fprintf(log,
            "bus %s: published %ld, received %ld, resent %ld, resend requests %ld, "
            "extra copies %ld, withheld by test switch %ld, ignored: foreign run %ld, "
            "bad version %ld, undecodable %ld, unknown channel %ld\n",
            who, b.published, b.received, b.resent, b.resend_requests, b.extra_copies,
            b.dropped_by_test,
            b.ignored_foreign_run, b.ignored_bad_version, b.ignored_undecodable,
            b.ignored_unknown_channel);
}

/* Appends the coupler's part of run.log: windows, timers and counters of every
 * participant, and the exit reason. Returns -1 (with a message naming the file)
 * when any of it could not be written. */
static int write_summary(coupler *c)
{
    char path[PATH_MAX + 16];
    snprintf(path, sizeof path, "%s/run.log", c->env.out_dir);
    FILE *log = fsi_fopen_checked(path, "a");
    if (!log) {
        fsi_error("cannot append to %s: %s", path, strerror(errno));
        return -1;
    }
    double wall = fsi_wall_seconds() - c->wall_start;
    fprintf(log, "\n[coupler]\nwindows = %d\nsimulated_time = %.9g s\nwall_time = %.3f s\n"
                 "windows_per_second = %.1f\n",
            c->window, c->t, wall, wall > 0 ? c->window / wall : 0.0);
    if (c->implicit)
        fprintf(log, "coupling_iterations = %ld\ncoupling_iterations_per_window = %.3f\n"
                     "coupling_iterations_most = %d\ncoupling_windows_not_converged = %ld\n",
                c->iterations_total,
                c->windows_iterated > 0 ? (double)c->iterations_total / (double)c->windows_iterated
                                        : 0.0,
                c->iterations_most, c->windows_not_converged);
    write_window_timing(log, c);
    write_bus_counters(log, "coupler", fsi_bus_get_counters(c->bus));
    for (int i = 0; i < c->n_part; i++) {
        participant_info *p = &c->part[i];
        fprintf(log, "\n[participant %s]\nrole = %s\npid = %d\nhost = %s\n", p->name, p->role,
                p->pid, p->host);
        for (int s = 0; s < p->n_stats; s++)
            fprintf(log, "%s = %.6g%s\n", p->stat_names[s], p->stat_values[s],
                    strncmp(p->stat_names[s], "bus_", 4) == 0 ? "" : " s");
    }
    if (c->failed)
        fprintf(log, "\ncoupler_exit = failure: %s\n", c->reason);
    else
        fprintf(log, "\ncoupler_exit = ok\n");
    int err = fsi_fclose_checked(log);
    if (err)
        fsi_error("cannot append to %s: %s", path, strerror(err));
    return err ? -1 : 0;
}

static int setup(coupler *c)
{
    c->probes.fd = -1;
    fsi_log_set_name(FSI_COUPLER_NAME);
    if (fsi_run_env_read(&c->env, FSI_COUPLER_NAME, NULL) != 0)
        return -1;
    c->case_file = fsi_case_read(c->env.case_path, stderr);
    if (!c->case_file)
        return -1;
    fsi_run_env_read_timing(&c->env, c->case_file);
    c->implicit = fsi_case_choice_is(c->case_file, "run", "scheme", "implicit");
    c->min_iterations = (int)fsi_case_get_int(c->case_file, "run", "coupling_min_iterations", 1);
    c->max_iterations = (int)fsi_case_get_int(c->case_file, "run", "coupling_max_iterations", 50);
    c->stop_on_max_iterations =
        !fsi_case_choice_is(c->case_file, "run", "coupling_on_max_iterations", "continue");
    c->coupling_csv.fd = -1;
    c->checkpoint_interval = fsi_case_get_real(c->case_file, "run", "checkpoint_interval", 0.0);
    const char *restart = getenv("FSI_RESTART_DIR");
    if (restart && *restart) {
        char path[4400], msg[4600];
        snprintf(path, sizeof path, "%s/coupler.state", restart);
        if (fsi_state_read_file(&c->restart, path, msg, sizeof msg) != 0) {
            fsi_error("restart: %s", msg);
            return -1;
        }
        c->restarting = 1;
    }
    for (int r = 0; r < MAX_PARTICIPANTS; r++) {
        if (!fsi_case_has_section(c->case_file, roles[r]))
            continue;
        participant_info *p = &c->part[c->n_part++];
        snprintf(p->name, sizeof p->name, "%s", roles[r]);
        snprintf(p->role, sizeof p->role, "%s", roles[r]);
        p->done_window = -1;
        p->converged = -1;
        p->dt_proposed = DBL_MAX;
        p->step = p->max_speed = NAN;
    }
    if (c->n_part == 0) {
        fsi_error("the case has neither [fluid] nor [solid]: nothing to couple");
        return -1;
    }
    c->bus = fsi_bus_open(c->env.lcm_url, FSI_COUPLER_NAME, c->env.run_id, on_message, c);
    if (!c->bus)
        return -1;
    fsi_bus_set_heartbeat(c->bus, -1, FSI_STATE_STARTING);
    return fsi_bus_start_heartbeat(c->bus, c->env.heartbeat_interval);
}

static void teardown(coupler *c)
{
    fsi_probes_csv_close(&c->probes);
    fsi_probes_csv_close(&c->coupling_csv);
    fsi_state_free(&c->pending);
    fsi_state_free(&c->restart);
    fsi_bus_close(c->bus);
    free(c->window_wall);
    for (int i = 0; i < c->n_part; i++) {
        participant_info *p = &c->part[i];
        free_strings(p->probe_names, p->n_probes);
        free(p->probe_values);
        free_strings(p->stat_names, p->n_stats);
        free(p->stat_values);
    }
    fsi_case_free(c->case_file);
}

int main(void)
{
    static coupler c;
    if (setup(&c) != 0) {
        teardown(&c);
        return FSI_EXIT_RUN_FAILURE;
    }
    c.wall_start = fsi_wall_seconds();
    double now = c.wall_start;
    for (int i = 0; i < c.n_part; i++)
        c.part[i].last_heard = now;
    fsi_progress_init(&c.progress, stdout,
                      fsi_case_get_real(c.case_file, "run", "progress_interval", 2.0),
                      fsi_case_get_real(c.case_file, "run", "end_time", 0.0));
    if (fsi_bus_test_drop_fraction(c.bus) > 0)
        fsi_warn("test switch: withholding %.0f %% of published messages",
                 100 * fsi_bus_test_drop_fraction(c.bus));

    int rc = register_participants(&c);
    if (rc == 0)
        rc = run_windows(&c);
    update_progress(&c, 1);
    if (c.progress.tty)
        fputc('\n', stdout);
    if (rc == 0 && !c.failed) {
        announce_finished(&c);
        fsi_info("run finished: %d windows, t = %.9g s", c.window, c.t);
    } else {
        announce_abort(&c);
        fsi_error("run stopped: %s", c.reason);
    }
    if (fsi_probes_csv_close(&c.probes) != 0)
        fail(&c, FSI_COUPLER_NAME, "%s", c.probes.error);
    if (fsi_probes_csv_close(&c.coupling_csv) != 0)
        fail(&c, FSI_COUPLER_NAME, "%s", c.coupling_csv.error);
    if (fflush(stdout) != 0 || ferror(stdout) || fsi_log_write_error())
        fail(&c, FSI_COUPLER_NAME, "cannot write its log (stdout/stderr, %s/coupler.log "
             "under fsi run): %s", c.env.out_dir,
             strerror(fsi_log_write_error() ? fsi_log_write_error() : EIO));
    int summary = write_summary(&c);
    int status = !c.failed ? FSI_EXIT_OK
                 : c.failure_relayed ? FSI_EXIT_STOPPED_BY_PEER : FSI_EXIT_RUN_FAILURE;
    if (summary != 0)
        status = FSI_EXIT_RUN_FAILURE;
    teardown(&c);
    return status;
}
