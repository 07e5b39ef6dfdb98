#include "participant.h"

#include <errno.h>
#include <limits.h>
#include <math.h>
#include <signal.h>
#include <sys/stat.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "bus.h"
#include "dim.h"
#include "fsi_abort_t.h"
#include "fsi_done_t.h"
#include "fsi_fluid_load_t.h"
#include "fsi_heartbeat_t.h"
#include "fsi_register_t.h"
#include "fsi_solid_state_t.h"
#include "fsi_step_t.h"
#include "fsi_welcome_t.h"
#include "grow.h"
#include "log.h"
#include "participant_env.h"
#include "participant_implicit.h"
#include "request_timer.h"
#include "state_file.h"

#define MAX_PROBES 64
#define MAX_PEERS 8

/* The other side's interface data, tagged with the window it belongs to. */
typedef struct {
    int window;      /* -1: empty */
    int iteration;
    int n, capacity;
    int32_t *id;
    double *position, *velocity, *acceleration, *volume, *density, *pressure, *force;
    double impedance;
} interface_slot;

struct fsi_participant {
    char name[64];
    char role[16];
    char out_dir[PATH_MAX];
    fsi_case *case_file;
    fsi_bus *bus;
    fsi_run_env env;

    double dt_first;
    int n_probes;
    char *probe_names[MAX_PROBES];
    double probe_values[MAX_PROBES];

    int registered, welcomed;
    char peer_name[MAX_PEERS][64];
    char peer_role[MAX_PEERS][16];
    int n_peers;

    /* current window */
    int window, iteration;
    int implicit;           /* [run] scheme = implicit */
    int window_complete;    /* after fsi_advance: the window is accepted */
    /* fsi_set_progress: reported with every done_t once set (progress_set). */
    int progress_set;
    double progress_step, progress_speed;
    double t, dt;
    int flags, frame;
    int finished;

    double dt_prev;         /* the length of the last accepted window */

    /* the next grant, possibly received before it is asked for */
    int next_window;     /* -1: none */
    int next_iteration;
    double next_t, next_dt;
    int next_flags, next_frame;

    interface_slot other;
    /* The other side's data for a later grant (an implicit run's next iteration, or the
     * next window), arriving while this side still works on the current one: kept
     * apart so that what fsi_read_interface() handed out stays valid until the next
     * fsi_ongoing(), which moves it in. */
    interface_slot pending;

    /* Solid: what it published this window, for the velocity handed back with the
     * loads (the impedance's reference) and to match loads by id: ids in sent order,
     * the reference velocity, and (id, index) sorted by id. */
    int sent_n, sent_capacity;
    int32_t *sent_id;
    double *sent_velocity;
    int32_t (*sent_order)[2];
    implicit_solid *implicit_solid;     /* solid of an implicit run */

    /* Coupled checkpoints (docs/checkpoints.md): the state read at a restart, and
     * whether this window's checkpoint was written (reported in done_t). */
    fsi_state restart, restart_library;
    int restarting;
    int checkpoint_written;

    double coupler_last_heard;
    int coupler_finished;
    int aborted;
    char abort_culprit[64];
    char abort_reason[512];

    /* FSI_WRITE_INITIAL (fsi run --check --write-initial): alone, without a bus, one
     * window 0 of zero length that writes frame 0, then the end. */
    int initial_only;

    fsi_timers lib_timers;    /* time spent waiting on the other processes */
    int t_wait;

    /* How long each kind of wait took (when to ask again), and whether the message
     * that ended the last one was an original (core/request_timer.h). */
    fsi_wait_estimate welcome_wait, step_wait, interface_wait;
    int taken_new;
};

static int read_restart(fsi_participant *p);
static int apply_restart(fsi_participant *p);
static void test_kill_switch(const fsi_participant *p);

static const char *other_role(const fsi_participant *p)
{
    return strcmp(p->role, "fluid") == 0 ? "solid" : "fluid";
}

static const char *peer_with_role(const fsi_participant *p, const char *role)
{
    for (int i = 0; i < p->n_peers; i++)
        if (strcmp(p->peer_role[i], role) == 0)
            return p->peer_name[i];
    return NULL;
}

static void grow_slot(interface_slot *s, int n)
{
    if (n <= s->capacity)
        return;
    size_t v = (size_t)n * FSI_DIM * sizeof(double), sc = (size_t)n * sizeof(double);
    s->id = realloc(s->id, (size_t)n * sizeof(int32_t));
    s->position = realloc(s->position, v);
    s->velocity = realloc(s->velocity, v);
    s->acceleration = realloc(s->acceleration, v);
    s->force = realloc(s->force, v);
    s->volume = realloc(s->volume, sc);
    s->density = realloc(s->density, sc);
    s->pressure = realloc(s->pressure, sc);
    if (!s->id || !s->position || !s->velocity || !s->acceleration || !s->force ||
        !s->volume || !s->density || !s->pressure) {
        fsi_error("out of memory for %d interface particles", n);
        exit(FSI_EXIT_RUN_FAILURE);
    }
    s->capacity = n;
}

static void free_slot(interface_slot *s)
{
    free(s->id);
    free(s->position);
    free(s->velocity);
    free(s->acceleration);
    free(s->force);
    free(s->volume);
    free(s->density);
    free(s->pressure);
}

static int valid_interface_size(int n, int dim, int n_components)
{
    return n >= 0 && dim == FSI_DIM && n_components == n * FSI_DIM;
}

/* (w1, i1) comes after (w0, i0): a later window, or a later iteration of the same. */
static int key_after(int w1, int i1, int w0, int i0)
{
    return w1 > w0 || (w1 == w0 && i1 > i0);
}

/* Where data of (window, iteration) goes: the current slot, or the pending one when it
 * belongs to a later grant than the current; NULL when it is older than what that slot
 * holds. */
static interface_slot *slot_for(fsi_participant *p, int window, int iteration)
{
    interface_slot *s =
        key_after(window, iteration, p->window, p->iteration) ? &p->pending : &p->other;
    return key_after(window, iteration, s->window, s->iteration) ? s : NULL;
}

static void take_solid_state(fsi_participant *p, const fsi_solid_state_t *m)
{
    interface_slot *s = strcmp(p->role, "fluid") == 0
                            ? slot_for(p, m->header.window, m->header.iteration)
                            : NULL;
    if (!s)
        return;
    if (!valid_interface_size(m->n, m->dim, m->n_components)) {
        fsi_warn("ignored solid_state of window %d: dim %d, n %d, %d components", m->header.window,
                 m->dim, m->n, m->n_components);
        return;
    }
    grow_slot(s, m->n);
    s->window = m->header.window;
    s->iteration = m->header.iteration;
    s->n = m->n;
    p->taken_new = fsi_bus_message_is_new(p->bus);
    memcpy(s->id, m->id, (size_t)m->n * sizeof(int32_t));
    memcpy(s->position, m->position, (size_t)m->n_components * sizeof(double));
    memcpy(s->velocity, m->velocity, (size_t)m->n_components * sizeof(double));
    memcpy(s->acceleration, m->acceleration, (size_t)m->n_components * sizeof(double));
    memcpy(s->volume, m->volume, (size_t)m->n * sizeof(double));
    memcpy(s->density, m->density, (size_t)m->n * sizeof(double));
}

static void take_fluid_load(fsi_participant *p, const fsi_fluid_load_t *m)
{
    interface_slot *s = strcmp(p->role, "solid") == 0
                            ? slot_for(p, m->header.window, m->header.iteration)
                            : NULL;
    if (!s)
        return;
    if (!valid_interface_size(m->n, m->dim, m->n_components)) {
        fsi_warn("ignored fluid_load of window %d: dim %d, n %d, %d components", m->header.window,
                 m->dim, m->n, m->n_components);
        return;
    }
    grow_slot(s, m->n);
    s->window = m->header.window;
    s->iteration = m->header.iteration;
    s->n = m->n;
    p->taken_new = fsi_bus_message_is_new(p->bus);
    memcpy(s->id, m->id, (size_t)m->n * sizeof(int32_t));
    memcpy(s->pressure, m->pressure, (size_t)m->n * sizeof(double));
    memcpy(s->force, m->force, (size_t)m->n_components * sizeof(double));
    s->impedance = m->impedance;
}

static void take_welcome(fsi_participant *p, const fsi_welcome_t *m)
{
    if (p->welcomed || strcmp(m->participant, p->name) != 0)
        return;
    p->n_peers = 0;
    for (int i = 0; i < m->n_participants && i < MAX_PEERS; i++) {
        snprintf(p->peer_name[i], sizeof p->peer_name[i], "%s", m->participant_names[i]);
        snprintf(p->peer_role[i], sizeof p->peer_role[i], "%s", m->participant_roles[i]);
        p->n_peers++;
    }
    p->welcomed = 1;
    p->taken_new = fsi_bus_message_is_new(p->bus);
}

static void take_step(fsi_participant *p, const fsi_step_t *m)
{
    int k = m->header.window, i = m->header.iteration;
    if (!key_after(k, i, p->window, p->iteration) ||
        (p->next_window >= 0 && !key_after(k, i, p->next_window, p->next_iteration)))
        return;
    p->next_window = k;
    p->next_iteration = i;
    p->next_t = m->t;
    p->next_dt = m->dt;
    p->next_flags = m->flags;
    p->next_frame = m->frame;
    p->taken_new = fsi_bus_message_is_new(p->bus);
}

static void on_message(fsi_msg_type type, const void *msg, void *user)
{
    fsi_participant *p = user;
    const fsi_header_t *h = msg;
    if (strcmp(h->sender, FSI_COUPLER_NAME) == 0)
        p->coupler_last_heard = fsi_wall_seconds();
    switch (type) {
    case FSI_MSG_WELCOME:
        take_welcome(p, msg);
        break;
    case FSI_MSG_STEP:
        take_step(p, msg);
        break;
    case FSI_MSG_SOLID_STATE:
        take_solid_state(p, msg);
        break;
    case FSI_MSG_FLUID_LOAD:
        take_fluid_load(p, msg);
        break;
    case FSI_MSG_HEARTBEAT:
        if (strcmp(h->sender, FSI_COUPLER_NAME) == 0 &&
            ((const fsi_heartbeat_t *)msg)->state == FSI_STATE_FINISHED)
            p->coupler_finished = 1;
        break;
    case FSI_MSG_ABORT: {
        const fsi_abort_t *a = msg;
        if (!p->aborted) {
            p->aborted = 1;
            snprintf(p->abort_culprit, sizeof p->abort_culprit, "%s", a->culprit);
            snprintf(p->abort_reason, sizeof p->abort_reason, "%s", a->reason);
        }
        break;
    }
    default:
        break;
    }
}

/* The run cannot go on for this process: say why and leave (output is between frames). */
static void die_with_run(const char *why, int status)
{
    fsi_error("%s", why);
    exit(status);
}

static void check_run_alive(fsi_participant *p)
{
    char why[1024];
    if (p->aborted) {
        snprintf(why, sizeof why, "run aborted by %s: %s", p->abort_culprit, p->abort_reason);
        die_with_run(why, FSI_EXIT_STOPPED_BY_PEER);
    }
    double silent = fsi_wall_seconds() - p->coupler_last_heard;
    if (silent > p->env.watchdog_timeout) {
        snprintf(why, sizeof why,
                 "coupler not heard for %.1f s (window %d, t = %.6g s): stopping", silent,
                 p->window, p->t);
        die_with_run(why, FSI_EXIT_COUPLER_SILENT);
    }
}

typedef int (*ready_fn)(const fsi_participant *p);
typedef void (*request_fn)(fsi_participant *p);

/* Handles messages until ready(p); asks again for what is missing once it is overdue
 * by the estimate of this kind of wait (NULL: never asks). */
static void wait_for(fsi_participant *p, ready_fn ready, request_fn request,
                     fsi_wait_estimate *estimate)
{
    if (ready(p))
        return;
    fsi_timer_start(&p->lib_timers, p->t_wait);
    fsi_request_timer timer;
    fsi_request_timer_start(&timer, estimate, fsi_wall_seconds(), fsi_bus_measured_loss(p->bus));
    if (!request)
        timer.next_request = INFINITY;
    while (!ready(p)) {
        /* Handle what arrived while this process computed before judging the
         * coupler's silence: after a window longer than the watchdog timeout its
         * heartbeats are queued, not missing. */
        if (fsi_bus_drain(p->bus) < 0)
            die_with_run("the bus failed while waiting", FSI_EXIT_RUN_FAILURE);
        if (ready(p))
            break;
        check_run_alive(p);
        double now = fsi_wall_seconds();
        if (fsi_request_timer_due(&timer, now, fsi_bus_measured_loss(p->bus)))
            request(p);
        /* Wakes at least every heartbeat interval to judge the coupler's silence. */
        double until = fmin(timer.next_request, now + p->env.heartbeat_interval);
        if (fsi_bus_poll(p->bus, until - now) < 0)
            die_with_run("the bus failed while waiting", FSI_EXIT_RUN_FAILURE);
    }
    fsi_request_timer_arrived(&timer, fsi_wall_seconds(), p->taken_new,
                              fsi_bus_measured_loss(p->bus));
    fsi_timer_stop(&p->lib_timers, p->t_wait);
}

fsi_participant *fsi_open(const char *name, const char *role, const char *case_path,
                          double dt_first)
{
    if (strcmp(role, "fluid") != 0 && strcmp(role, "solid") != 0) {
        fsi_error("fsi_open: role must be 'fluid' or 'solid', not '%s'", role);
        return NULL;
    }
    fsi_participant *p = calloc(1, sizeof *p);
    if (!p)
        return NULL;
    if (fsi_run_env_read(&p->env, name, case_path) != 0) {
        free(p);
        return NULL;
    }
    snprintf(p->name, sizeof p->name, "%s", p->env.participant);
    snprintf(p->role, sizeof p->role, "%s", role);
    snprintf(p->out_dir, sizeof p->out_dir, "%s", p->env.out_dir);
    fsi_log_set_name(p->name);
    p->case_file = fsi_case_read(p->env.case_path, stderr);
    if (!p->case_file) {
        free(p);
        return NULL;
    }
    fsi_run_env_read_timing(&p->env, p->case_file);
    p->dt_first = dt_first;
    p->window = -1;
    p->next_window = -1;
    p->other.window = -1;
    p->pending.window = -1;
    p->implicit = fsi_case_choice_is(p->case_file, "run", "scheme", "implicit");
    p->window_complete = 1;
    if (p->implicit && strcmp(role, "solid") == 0) {
        char msg[512];
        p->implicit_solid = calloc(1, sizeof *p->implicit_solid);
        if (!p->implicit_solid ||
            implicit_solid_init(p->implicit_solid, p->case_file, msg, sizeof msg) != 0) {
            fsi_error("implicit coupling: %s", p->implicit_solid ? msg : "out of memory");
            if (p->implicit_solid)
                implicit_solid_free(p->implicit_solid);
            free(p->implicit_solid);
            fsi_case_free(p->case_file);
            free(p);
            return NULL;
        }
    }
    p->t_wait = fsi_timer_index(&p->lib_timers, "coupling_wait");
    if (read_restart(p) != 0) {
        if (p->implicit_solid)
            implicit_solid_free(p->implicit_solid);
        free(p->implicit_solid);
        fsi_state_free(&p->restart);
        fsi_state_free(&p->restart_library);
        fsi_case_free(p->case_file);
        free(p);
        return NULL;
    }
    const char *initial = getenv("FSI_WRITE_INITIAL");
    p->initial_only = initial && strcmp(initial, "1") == 0;
    if (p->initial_only)
        return p;
    p->bus = fsi_bus_open(p->env.lcm_url, p->name, p->env.run_id, on_message, p);
    if (!p->bus) {
        fsi_case_free(p->case_file);
        free(p);
        return NULL;
    }
    /* A replay has no coupler to hear; a wait that the recording cannot end is
     * reported by the bus instead. */
    if (fsi_bus_replaying(p->bus))
        p->env.watchdog_timeout = INFINITY;
    p->coupler_last_heard = fsi_wall_seconds();
    fsi_bus_set_heartbeat(p->bus, -1, FSI_STATE_STARTING);
    fsi_bus_start_heartbeat(p->bus, p->env.heartbeat_interval);
    return p;
}

int fsi_add_probe(fsi_participant *p, const char *column)
{
    if (p->registered || p->n_probes == MAX_PROBES) {
        fsi_error("fsi_add_probe('%s'): %s", column,
                  p->registered ? "probes must be added before the first window"
                                : "too many probes");
        return -1;
    }
    p->probe_names[p->n_probes] = strdup(column);
    p->probe_values[p->n_probes] = 0.0;
    return p->n_probes++;
}

static void send_register(fsi_participant *p)
{
    char host[256] = "";
    gethostname(host, sizeof host - 1);
    fsi_register_t r = {0};
    r.header.window = -1;
    r.role = p->role;
    r.pid = (int32_t)getpid();
    r.host = host;
    r.dt_proposed = p->dt_first;
    r.n_probes = p->n_probes;
    r.probe_names = p->probe_names;
    fsi_bus_publish(p->bus, FSI_MSG_REGISTER, &r);
}

static int is_welcomed(const fsi_participant *p)
{
    return p->welcomed;
}

static int has_next_step(const fsi_participant *p)
{
    return p->next_window >= 0 &&
           key_after(p->next_window, p->next_iteration, p->window, p->iteration);
}

/* The next grant is the next window, or in an implicit run possibly the same window
 * again: ask for both. */
static void request_step(fsi_participant *p)
{
    fsi_bus_request_resend(p->bus, FSI_COUPLER_NAME, FSI_MSG_STEP, p->window + 1, 0);
    if (p->implicit && p->window >= 0)
        fsi_bus_request_resend(p->bus, FSI_COUPLER_NAME, FSI_MSG_STEP, p->window,
                               p->iteration + 1);
}

int fsi_ongoing(fsi_participant *p)
{
    if (p->finished)
        return 0;
    /* A run whose messages are lost is not a finished run (docs/output.md). */
    if (fsi_log_write_error()) {
        fsi_abort(p, "cannot write its log (stderr, %s/%s.log under fsi run): %s",
                  fsi_output_dir(p), p->name, strerror(fsi_log_write_error()));
        return 0;
    }
    if (p->initial_only) {
        /* Window 0 as the coupler grants it (coupler_main.c): zero length, probes and
         * frame 0; the run ends after it. */
        p->finished = p->window >= 0;
        p->window = 0;
        p->flags = FSI_STEP_PROBE;
        return !p->finished;
    }
    if (!p->registered) {
        if (p->restarting && apply_restart(p) != 0)
            return 0;
        p->registered = 1;
        send_register(p);
        wait_for(p, is_welcomed, send_register, &p->welcome_wait);
    }
    wait_for(p, has_next_step, request_step, &p->step_wait);
    if (p->next_window != p->window) {
        /* The last window was accepted: the run goes on from its end. */
        if (p->window >= 0) {
            p->dt_prev = p->dt;
            if (p->implicit_solid)
                implicit_solid_accept(p->implicit_solid);
        }
    }
    p->window = p->next_window;
    p->iteration = p->next_iteration;
    p->checkpoint_written = 0;
    if (p->pending.window == p->window && p->pending.iteration == p->iteration) {
        const interface_slot swap = p->other;
        p->other = p->pending;
        p->pending = swap;
    }
    p->t = p->next_t;
    p->dt = p->next_dt;
    p->flags = p->next_flags;
    p->frame = p->next_frame;
    fsi_bus_set_heartbeat(p->bus, p->window, FSI_STATE_RUNNING);
    test_kill_switch(p);
    if (p->flags & FSI_STEP_FINISH)
        p->finished = 1;
    return !p->finished;
}

double fsi_window(const fsi_participant *p)
{
    return p->dt;
}

double fsi_time(const fsi_participant *p)
{
    return p->t;
}

int fsi_window_index(const fsi_participant *p)
{
    return p->window;
}

int fsi_probe_window(const fsi_participant *p)
{
    return (p->flags & FSI_STEP_PROBE) != 0;
}

int fsi_output_frame(const fsi_participant *p)
{
    return p->frame;
}

int fsi_iteration(const fsi_participant *p)
{
    return p->iteration;
}

int fsi_requires_writing_checkpoint(const fsi_participant *p)
{
    return p->iteration == 0 && (p->implicit || (p->flags & FSI_STEP_CHECKPOINT));
}

/* OUT/checkpoints/window_K: the checkpoint of the state at window K's start. */
static void checkpoint_dir(const fsi_participant *p, int window, char *out, size_t size)
{
    snprintf(out, size, "%s/checkpoints/window_%08d", p->out_dir, window);
}

static int make_dir(const char *path)
{
    return mkdir(path, 0755) == 0 || errno == EEXIST ? 0 : -1;
}

/* What the library carries across windows itself, beside the solver's state. */
static int library_state(const fsi_participant *p, fsi_state *st)
{
    fsi_state_clear(st);
    int rc = fsi_state_put(st, "library.window", &p->window, sizeof p->window) |
             fsi_state_put(st, "library.dt_prev", &p->dt_prev, sizeof p->dt_prev) |
             fsi_state_put(st, "library.probe_values", p->probe_values,
                           (size_t)p->n_probes * sizeof(double));
    if (p->implicit_solid)
        rc |= fsi_accel_save(p->implicit_solid->accel, st, "library.accel.") |
              fsi_state_put(st, "library.history_dt", p->implicit_solid->history_dt,
                            sizeof p->implicit_solid->history_dt);
    return rc ? -1 : 0;
}

int fsi_write_checkpoint(fsi_participant *p, const fsi_state *st)
{
    if (!(p->flags & FSI_STEP_CHECKPOINT) || p->iteration != 0 || p->checkpoint_written)
        return 0;
    char dir[PATH_MAX + 64], path[PATH_MAX + 192], msg[PATH_MAX + 320];
    snprintf(dir, sizeof dir, "%s/checkpoints", p->out_dir);
    make_dir(dir);
    checkpoint_dir(p, p->window, dir, sizeof dir);
    if (make_dir(dir) != 0) {
        fsi_error("cannot create the checkpoint folder %s: %s", dir, strerror(errno));
        return -1;
    }
    if (st->failed) {
        fsi_error("the state to checkpoint at window %d is incomplete (out of memory)",
                  p->window);
        return -1;
    }
    fsi_state own = {0};
    snprintf(path, sizeof path, "%s/%s.state", dir, p->name);
    int rc = fsi_state_write_file(st, path, msg, sizeof msg);
    if (rc == 0) {
        snprintf(path, sizeof path, "%s/%s.library.state", dir, p->name);
        rc = library_state(p, &own) != 0 ? -1 : fsi_state_write_file(&own, path, msg, sizeof msg);
        if (own.failed)
            snprintf(msg, sizeof msg, "out of memory for the library's state");
    }
    fsi_state_free(&own);
    if (rc != 0) {
        fsi_error("checkpoint of window %d: %s", p->window, msg);
        return -1;
    }
    p->checkpoint_written = 1;
    return 0;
}

const fsi_state *fsi_restart_state(const fsi_participant *p)
{
    return p->restarting ? &p->restart : NULL;
}

/* FSI_RESTART_DIR (set by fsi run --restart): the solver's state and the library's
 * own, read at fsi_open (the solver restores its part before its first window). 0, or
 * -1 with a message. */
static int read_restart(fsi_participant *p)
{
    const char *dir = getenv("FSI_RESTART_DIR");
    if (!dir || !*dir)
        return 0;
    char path[PATH_MAX + 128], msg[PATH_MAX + 256];
    snprintf(path, sizeof path, "%s/%s.state", dir, p->name);
    int rc = fsi_state_read_file(&p->restart, path, msg, sizeof msg);
    if (rc == 0) {
        snprintf(path, sizeof path, "%s/%s.library.state", dir, p->name);
        rc = fsi_state_read_file(&p->restart_library, path, msg, sizeof msg);
    }
    if (rc != 0) {
        fsi_error("restart: %s", msg);
        return -1;
    }
    p->restarting = 1;
    return 0;
}

/* The library's own part of a restart, once the probes are declared. 0, or -1. */
static int apply_restart(fsi_participant *p)
{
    const fsi_state *own = &p->restart_library;
    int window;
    if (fsi_state_get(own, "library.window", &window, sizeof window) == 0 &&
        fsi_state_get(own, "library.dt_prev", &p->dt_prev, sizeof p->dt_prev) == 0 &&
        fsi_state_get(own, "library.probe_values", p->probe_values,
                      (size_t)p->n_probes * sizeof(double)) == 0 &&
        (!p->implicit_solid ||
         (fsi_accel_restore(p->implicit_solid->accel, own, "library.accel.") == 0 &&
          fsi_state_get(own, "library.history_dt", p->implicit_solid->history_dt,
                        sizeof p->implicit_solid->history_dt) == 0))) {
        /* As if window K - 1 had just ended: the first grant expected, and asked for
         * again when it is lost, is K's (a participant that starts at -1 would ask for
         * window 0). */
        p->window = window - 1;
        p->dt = p->dt_prev;
        return 0;
    }
    fsi_abort(p, "restart: the checkpoint's %s.library.state does not match this "
              "participant (its probes or the coupling scheme differ from the run that wrote "
              "it)", p->name);
    return -1;
}

int fsi_requires_reading_checkpoint(const fsi_participant *p)
{
    return p->implicit && p->iteration > 0;
}

int fsi_window_complete(const fsi_participant *p)
{
    return p->window_complete;
}

int fsi_write_window_end(fsi_participant *p, const fsi_interface *end)
{
    if (!p->implicit_solid || !fsi_coupled(p))
        return 0;
    char msg[512];
    if (implicit_solid_window_end(p->implicit_solid, end, msg, sizeof msg) == 0)
        return 0;
    fsi_error("fsi_write_window_end: %s", msg);
    return -1;
}

int fsi_coupled(const fsi_participant *p)
{
    return peer_with_role(p, other_role(p)) != NULL;
}

static int by_id(const void *a, const void *b)
{
    const int32_t x = ((const int32_t *)a)[0], y = ((const int32_t *)b)[0];
    return (x > y) - (x < y);
}

/* Keeps the ids the solid publishes and the reference velocity of each (the one sent,
 * or an implicit iteration's window-mean velocity), sorted for the loads' lookup. */
static int remember_sent(fsi_participant *p, const fsi_interface *d, const double *velocity)
{
    const int n = d->n;
    if (n > p->sent_capacity) {
        const size_t cap = (size_t)n + (size_t)n / 4 + 16;
        int failed = 0;
        p->sent_id = fsi_grow(p->sent_id, cap * sizeof *p->sent_id, &failed);
        p->sent_velocity = fsi_grow(p->sent_velocity, cap * FSI_DIM * sizeof(double), &failed);
        p->sent_order = fsi_grow(p->sent_order, cap * sizeof *p->sent_order, &failed);
        if (failed) {
            fsi_error("fsi_write_interface: out of memory for %d interface particles", n);
            return -1;
        }
        p->sent_capacity = (int)cap;
    }
    p->sent_n = n;
    if (n == 0)
        return 0;
    memcpy(p->sent_id, d->id, (size_t)n * sizeof *p->sent_id);
    memcpy(p->sent_velocity, velocity, (size_t)n * FSI_DIM * sizeof(double));
    for (int k = 0; k < n; k++) {
        p->sent_order[k][0] = d->id[k];
        p->sent_order[k][1] = k;
    }
    qsort(p->sent_order, (size_t)n, sizeof *p->sent_order, by_id);
    return 0;
}

/* The index in sent order of a particle id, or -1 when it was not sent. */
static int sent_index(const fsi_participant *p, int32_t id, int guess)
{
    if (guess < p->sent_n && p->sent_id[guess] == id)
        return guess;
    const int32_t key[2] = {id, 0};
    const int32_t(*hit)[2] = bsearch(key, p->sent_order, (size_t)p->sent_n,
                                      sizeof *p->sent_order, by_id);
    return hit ? (*hit)[1] : -1;
}

/* The first array a solid state of n > 0 particles lacks, or NULL. */
static const char *missing_solid_array(const fsi_interface *d)
{
    if (d->n <= 0)
        return NULL;
    return !d->id             ? "id"
           : !d->position     ? "position"
           : !d->velocity     ? "velocity"
           : !d->acceleration ? "acceleration"
           : !d->volume       ? "volume"
           : !d->density      ? "density"
                              : NULL;
}

int fsi_write_interface(fsi_participant *p, const fsi_interface *d)
{
    if (!fsi_coupled(p))
        return 0;
    if (strcmp(p->role, "solid") == 0) {
        /* Refused here rather than left to the encoder, which would read through the
         * NULL: a solid written before protocol version 3 sets no density, and a
         * stand-in value would reach the fluid as the solid's mass. */
        const char *missing = missing_solid_array(d);
        if (missing) {
            fsi_error("fsi_write_interface: the solid state of %d particles has no %s array "
                      "(docs/participant_api.md, Interface data)", d->n, missing);
            return -1;
        }
        fsi_solid_state_t m = {0};
        m.header.window = p->window;
        m.header.iteration = p->iteration;
        m.dim = FSI_DIM;
        m.n = d->n;
        m.n_components = d->n * FSI_DIM;
        m.id = d->id;
        m.position = d->position;
        m.velocity = d->velocity;
        m.acceleration = d->acceleration;
        if (p->implicit_solid) {
            char msg[512];
            implicit_solid *is = p->implicit_solid;
            if (implicit_solid_motion(is, p->iteration, p->dt, p->dt_prev, d, msg,
                                      sizeof msg) != 0) {
                fsi_error("fsi_write_interface: %s", msg);
                return -1;
            }
            m.velocity = is->v_sent;
            m.acceleration = is->a_sent;
        }
        if (remember_sent(p, d, p->implicit_solid ? p->implicit_solid->u_in : d->velocity) != 0)
            return -1;
        m.volume = d->volume;
        m.density = d->density;
        return fsi_bus_publish(p->bus, FSI_MSG_SOLID_STATE, &m);
    }
    fsi_fluid_load_t m = {0};
    m.header.window = p->window;
    m.header.iteration = p->iteration;
    m.dim = FSI_DIM;
    m.n = d->n;
    m.n_components = d->n * FSI_DIM;
    m.id = d->id;
    m.pressure = d->pressure;
    m.force = d->force;
    m.impedance = d->impedance;
    return fsi_bus_publish(p->bus, FSI_MSG_FLUID_LOAD, &m);
}

static int has_interface_data(const fsi_participant *p)
{
    return p->other.window == p->window && p->other.iteration == p->iteration;
}

static void request_interface(fsi_participant *p)
{
    int solid_waits = strcmp(p->role, "solid") == 0;
    fsi_bus_request_resend(p->bus, peer_with_role(p, other_role(p)),
                           solid_waits ? FSI_MSG_FLUID_LOAD : FSI_MSG_SOLID_STATE, p->window,
                           p->iteration);
}

int fsi_read_interface(fsi_participant *p, fsi_interface *d)
{
    memset(d, 0, sizeof *d);
    if (!fsi_coupled(p))
        return 0;
    wait_for(p, has_interface_data, request_interface, &p->interface_wait);
    interface_slot *s = &p->other;
    if (strcmp(p->role, "solid") == 0) {
        /* Each load's reference velocity, and its force for the implicit verdict;
         * particles without a load have none. */
        implicit_solid *is = p->implicit_solid;
        if (is)
            memset(is->force, 0, (size_t)is->n * FSI_DIM * sizeof(double));
        for (int j = 0; j < s->n; j++) {
            const int k = sent_index(p, s->id[j], j);
            double *u = &s->velocity[j * FSI_DIM];
            if (k < 0) {
                for (int c = 0; c < FSI_DIM; c++)
                    u[c] = 0.0;
                continue;
            }
            memcpy(u, &p->sent_velocity[k * FSI_DIM], FSI_DIM * sizeof(double));
            if (is && k < is->n)
                implicit_solid_set_force(is, k, &s->force[j * FSI_DIM]);
        }
    }
    d->n = s->n;
    d->id = s->id;
    d->position = s->position;
    d->velocity = s->velocity;
    d->acceleration = s->acceleration;
    d->volume = s->volume;
    d->density = s->density;
    d->pressure = s->pressure;
    d->force = s->force;
    d->impedance = s->impedance;
    return 0;
}

void fsi_set_probe(fsi_participant *p, int index, double value)
{
    if (index >= 0 && index < p->n_probes)
        p->probe_values[index] = value;
}

static int send_done(fsi_participant *p, int status, double dt_next_max, int n_stats,
                     char **names, double *values)
{
    fsi_done_t d = {0};
    d.header.window = p->window;
    d.header.iteration = p->iteration;
    d.status = status;
    d.converged = -1;
    d.checkpoint = p->checkpoint_written;
    if (p->implicit_solid && fsi_coupled(p) && status == FSI_STATUS_OK) {
        const implicit_verdict *v = &p->implicit_solid->verdict;
        d.converged = v->converged;
        d.displacement_residual = v->displacement_residual;
        d.force_residual = v->force_residual;
        d.history_columns = v->history_columns;
        d.history_restarted = v->history_restarted;
    }
    d.dt_next_max = dt_next_max;
    d.n_probes = p->n_probes;
    d.probe_values = p->probe_values;
    d.n_stats = n_stats;
    d.stat_names = names;
    d.stat_values = values;
    d.message = "";
    return fsi_bus_publish(p->bus, FSI_MSG_DONE, &d);
}

/* Test switch FSI_TEST_STALL="NAME:K": participant NAME never reports window K,
 * while its heartbeat thread keeps it looking alive — how the tests reproduce a
 * deadlock for [run] window_timeout. */
/* 1 when the test switch 'variable' = "NAME:K" names this participant and its window. */
static int test_switch_names_window(const fsi_participant *p, const char *variable)
{
    const char *spec = getenv(variable);
    const char *colon = spec ? strrchr(spec, ':') : NULL;
    return colon && (size_t)(colon - spec) == strlen(p->name) &&
           strncmp(spec, p->name, strlen(p->name)) == 0 && atoi(colon + 1) == p->window;
}

static void test_stall_switch(const fsi_participant *p)
{
    if (!test_switch_names_window(p, "FSI_TEST_STALL"))
        return;
    fsi_warn("test switch FSI_TEST_STALL: stalling in window %d", p->window);
    for (;;)
        pause();
}

/* Test switch FSI_TEST_SLOW="NAME:K:SECONDS": participant NAME spends SECONDS more in
 * window K, without handling messages (as a long computation does), then goes on:
 * how the tests check that a window longer than the watchdog timeout is not taken
 * for a dead coupler. */
static void test_slow_switch(const fsi_participant *p)
{
    const char *spec = getenv("FSI_TEST_SLOW");
    size_t len = strlen(p->name);
    if (!spec || strncmp(spec, p->name, len) != 0 || spec[len] != ':')
        return;
    char *end;
    long k = strtol(spec + len + 1, &end, 10);
    if (*end != ':' || k != p->window)
        return;
    double seconds = strtod(end + 1, NULL);
    fsi_warn("test switch FSI_TEST_SLOW: %.3g s more in window %d", seconds, p->window);
    double until = fsi_wall_seconds() + seconds;
    while (fsi_wall_seconds() < until)
        ;
}

/* Test switch FSI_TEST_KILL="NAME:K": participant NAME kills itself with SIGKILL at the
 * start of window K (after its first iteration's grant), as kill -9 would: how the
 * tests interrupt a run at a known point to restart it from a checkpoint. */
static void test_kill_switch(const fsi_participant *p)
{
    if (p->iteration != 0 || !test_switch_names_window(p, "FSI_TEST_KILL"))
        return;
    fsi_warn("test switch FSI_TEST_KILL: killed at the start of window %d", p->window);
    raise(SIGKILL);
}

void fsi_set_progress(fsi_participant *p, double step, double max_speed)
{
    p->progress_set = 1;
    p->progress_step = step;
    p->progress_speed = max_speed;
}

int fsi_advance(fsi_participant *p, double dt_next_max)
{
    if (p->initial_only) {
        p->window_complete = 1;
        return 0;
    }
    test_stall_switch(p);
    test_slow_switch(p);
    char *names[] = {"step", "max_speed"};
    double values[] = {p->progress_step, p->progress_speed};
    int rc = send_done(p, FSI_STATUS_OK, dt_next_max, p->progress_set ? 2 : 0,
                       p->progress_set ? names : NULL, p->progress_set ? values : NULL);
    p->window_complete = 1;
    if (p->implicit) {
        /* The coupler's verdict: the next grant is another window, or this one again. */
        wait_for(p, has_next_step, request_step, &p->step_wait);
        p->window_complete = p->next_window != p->window;
    }
    return rc;
}

void fsi_abort(fsi_participant *p, const char *fmt, ...)
{
    char reason[512];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(reason, sizeof reason, fmt, ap);
    va_end(ap);
    fsi_error("%s", reason);
    if (!p->bus)
        return;
    fsi_abort_t a = {0};
    a.header.window = p->window;
    a.header.iteration = p->iteration;
    a.culprit = p->name;
    a.reason = reason;
    /* Sent a few times: UDP may lose one, and the coupler's watchdog is the slow path. */
    for (int i = 0; i < 3; i++)
        fsi_bus_publish(p->bus, FSI_MSG_ABORT, &a);
}

static int coupler_has_finished(const fsi_participant *p)
{
    return p->coupler_finished;
}

/* Timers and bus counters as name/value pairs for the final done_t. */
static int collect_stats(fsi_participant *p, const fsi_timers *timers, char **names,
                         double *values, int max)
{
    int n = 0;
    for (int i = 0; timers && i < timers->n && n < max; i++, n++) {
        names[n] = (char *)timers->name[i];
        values[n] = timers->seconds[i];
    }
    for (int i = 0; i < p->lib_timers.n && n < max; i++, n++) {
        names[n] = (char *)p->lib_timers.name[i];
        values[n] = p->lib_timers.seconds[i];
    }
    fsi_bus_counters c = fsi_bus_get_counters(p->bus);
    const struct {
        const char *name;
        long value;
    } counters[] = {
        {"bus_published", c.published},
        {"bus_received", c.received},
        {"bus_resent", c.resent},
        {"bus_resend_requests", c.resend_requests},
        {"bus_extra_copies", c.extra_copies},
        {"bus_dropped_by_test", c.dropped_by_test},
        {"bus_ignored_foreign_run", c.ignored_foreign_run},
        {"bus_ignored_bad_version", c.ignored_bad_version},
        {"bus_ignored_undecodable", c.ignored_undecodable},
        {"bus_ignored_unknown_channel", c.ignored_unknown_channel},
    };
    for (size_t i = 0; i < sizeof counters / sizeof counters[0] && n < max; i++, n++) {
        names[n] = (char *)counters[i].name;
        values[n] = (double)counters[i].value;
    }
    return n;
}

int fsi_close(fsi_participant *p, const fsi_timers *timers)
{
    int status = FSI_EXIT_OK;
    if (p->initial_only) {
        status = p->finished ? FSI_EXIT_OK : FSI_EXIT_RUN_FAILURE;
    } else if (p->finished) {
        char *names[2 * FSI_TIMERS_MAX + 16];
        double values[2 * FSI_TIMERS_MAX + 16];
        int n = collect_stats(p, timers, names, values, 2 * FSI_TIMERS_MAX + 16);
        send_done(p, FSI_STATUS_FINISHED, 0.0, n, names, values);
        fsi_bus_set_heartbeat(p->bus, p->window, FSI_STATE_FINISHED);
        /* Stay until the coupler confirms it has every final report (it re-requests a
         * lost one from us while we wait here). */
        wait_for(p, coupler_has_finished, NULL, NULL);
    } else {
        status = FSI_EXIT_RUN_FAILURE;
    }
    if (p->bus)
        fsi_bus_close(p->bus);
    fsi_case_free(p->case_file);
    free_slot(&p->other);
    free_slot(&p->pending);
    free(p->sent_id);
    free(p->sent_velocity);
    free(p->sent_order);
    if (p->implicit_solid)
        implicit_solid_free(p->implicit_solid);
    free(p->implicit_solid);
    fsi_state_free(&p->restart);
    fsi_state_free(&p->restart_library);
    for (int i = 0; i < p->n_probes; i++)
        free(p->probe_names[i]);
    free(p);
    return status;
}

const fsi_case *fsi_participant_case(const fsi_participant *p)
{
    return p->case_file;
}

const char *fsi_participant_name(const fsi_participant *p)
{
    return p->name;
}

const char *fsi_output_dir(const fsi_participant *p)
{
    return p->out_dir;
}
