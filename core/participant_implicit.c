#include "participant_implicit.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "dim.h"
#include "grow.h"

/* A window this much longer or shorter than the last one starts a new history. */
#define DT_CHANGE 1e-3

int implicit_solid_init(implicit_solid *s, const fsi_case *c, char *msg, size_t msg_size)
{
    memset(s, 0, sizeof *s);
    fsi_accel_settings set = {FSI_ACCEL_IQN_ILS, 0.5, 8, 1e-10, 100};
    if (fsi_case_choice_is(c, "run", "coupling_acceleration", "constant"))
        set.kind = FSI_ACCEL_CONSTANT;
    else if (fsi_case_choice_is(c, "run", "coupling_acceleration", "aitken"))
        set.kind = FSI_ACCEL_AITKEN;
    set.omega0 = fsi_case_get_real(c, "run", "coupling_relaxation", set.omega0);
    set.reuse_windows = (int)fsi_case_get_int(c, "run", "coupling_reuse", set.reuse_windows);
    set.filter_eps = fsi_case_get_real(c, "run", "coupling_filter", set.filter_eps);
    set.max_columns = (int)fsi_case_get_int(c, "run", "coupling_max_columns", set.max_columns);
    s->tolerance = fsi_case_get_real(c, "run", "coupling_tolerance", 1e-4);
    s->absolute_tolerance = fsi_case_get_real(c, "run", "coupling_absolute_tolerance", 1e-12);
    const char *repeat = getenv("FSI_TEST_REPEAT_MOTION");
    s->repeat_motion = repeat && strcmp(repeat, "1") == 0;
    s->accel = fsi_accel_create(&set, msg, msg_size);
    return s->accel ? 0 : -1;
}

void implicit_solid_free(implicit_solid *s)
{
    fsi_accel_free(s->accel);
    free(s->id);
    free(s->x_start);
    free(s->u_prev);
    free(s->u_in);
    free(s->u_out);
    free(s->u_next);
    free(s->v_sent);
    free(s->a_sent);
    free(s->force);
    free(s->force_last);
    memset(s, 0, sizeof *s);
}

static int reserve(implicit_solid *s, int n)
{
    if (n <= s->capacity)
        return 0;
    const size_t cap = fsi_grown_capacity((size_t)n), vec = cap * FSI_DIM * sizeof(double);
    int failed = 0;
    s->id = fsi_grow(s->id, cap * sizeof *s->id, &failed);
    double **v[] = {&s->x_start, &s->u_prev, &s->u_in, &s->u_out, &s->u_next,
                    &s->v_sent, &s->a_sent, &s->force, &s->force_last};
    for (size_t k = 0; k < sizeof v / sizeof v[0]; k++)
        *v[k] = fsi_grow(*v[k], vec, &failed);
    if (failed)
        return -1;
    s->capacity = (int)cap;
    return 0;
}

/* The same particles in the same order as the window's first iteration. */
static int same_particles(const implicit_solid *s, const fsi_interface *d, const char *what,
                          char *msg, size_t msg_size)
{
    if (d->n == s->n && (s->n == 0 || memcmp(d->id, s->id, (size_t)s->n * sizeof *s->id) == 0))
        return 0;
    snprintf(msg, msg_size, "implicit coupling: the solid's %s in iteration %d holds other "
             "particles (%d) than it sent at the window's start (%d): is its state restored "
             "when fsi_requires_reading_checkpoint() says so? (docs/participant_api.md)",
             what, s->iteration, d->n, s->n);
    return -1;
}

int implicit_solid_motion(implicit_solid *s, int iteration, double dt, double dt_prev,
                          const fsi_interface *d, char *msg, size_t msg_size)
{
    const int m = d->n * FSI_DIM;
    s->iteration = iteration;
    if (iteration == 0) {
        if (reserve(s, d->n) != 0) {
            snprintf(msg, msg_size, "out of memory for %d interface particles", d->n);
            return -1;
        }
        s->n = d->n;
        s->dt = dt;
        s->have_force_last = 0;
        memcpy(s->id, d->id, (size_t)d->n * sizeof *s->id);
        memcpy(s->x_start, d->position, (size_t)m * sizeof(double));
        memcpy(s->u_prev, d->velocity, (size_t)m * sizeof(double));
        /* The explicit scheme's prediction of the window's mean velocity. */
        for (int k = 0; k < m; k++)
            s->u_in[k] = d->velocity[k] + 0.5 * dt * d->acceleration[k];
        /* The secant pairs of earlier windows are differences of the map u -> u_out of
         * those windows; its derivative scales with the window's length (the load's
         * effect on the mean velocity grows as dt), so pairs from a window of another
         * length mislead the quasi-Newton step: C4 with windows alternating between
         * 1e-4 and 2e-4 s (cut at probe times) stalled at a residual of 4e-2 with them
         * and converged in 3-4 iterations without (docs/stability.md). The motion sent
         * also depends on the last window's length (the acceleration a below), so the
         * pairs of window 1, which follows the zero-length window 0, mislead window 2:
         * C4 at density ratio 0.1 without the impedance answer stalled at a residual of
         * 2 in window 2 with them. */
        const int length_changed =
            s->history_dt[0] > 0.0 &&
            (fabs(dt - s->history_dt[0]) > DT_CHANGE * s->history_dt[0] ||
             fabs(dt_prev - s->history_dt[1]) > DT_CHANGE * fmax(dt_prev, s->history_dt[1]));
        if (length_changed)
            fsi_accel_drop_history(s->accel);
        s->history_dt[0] = dt;
        s->history_dt[1] = dt_prev;
        int restarted = fsi_accel_begin_window(s->accel, d->n, FSI_DIM, d->id);
        if (restarted >= 0)     /* 1: another interface set, 2: another length */
            restarted = restarted | (length_changed ? 2 : 0);
        if (restarted < 0) {
            snprintf(msg, msg_size, "out of memory for the coupling acceleration");
            return -1;
        }
        s->restarted = restarted;
    } else {
        if (same_particles(s, d, "state", msg, msg_size) != 0)
            return -1;
        memcpy(s->u_in, s->u_next, (size_t)m * sizeof(double));
    }
    if (!(dt > 0.0)) {     /* a window of length zero: the state as it is */
        memcpy(s->v_sent, d->velocity, (size_t)m * sizeof(double));
        memcpy(s->a_sent, d->acceleration, (size_t)m * sizeof(double));
        return 0;
    }
    for (int k = 0; k < m; k++) {
        const double a = 2.0 * (s->u_in[k] - s->u_prev[k]) / (dt + dt_prev);
        s->a_sent[k] = a;
        s->v_sent[k] = s->u_in[k] - 0.5 * dt * a;
    }
    return 0;
}

void implicit_solid_set_force(implicit_solid *s, int k, const double *force)
{
    memcpy(&s->force[k * FSI_DIM], force, FSI_DIM * sizeof(double));
}

/* |a - b| / |a|, 0 when both are zero, infinite when only a is. */
static double relative_difference(const double *a, const double *b, int m)
{
    double diff = 0.0, norm = 0.0;
    for (int k = 0; k < m; k++) {
        diff += (a[k] - b[k]) * (a[k] - b[k]);
        norm += a[k] * a[k];
    }
    if (diff == 0.0)
        return 0.0;
    return norm > 0.0 ? sqrt(diff / norm) : INFINITY;
}

int implicit_solid_window_end(implicit_solid *s, const fsi_interface *end, char *msg,
                              size_t msg_size)
{
    if (same_particles(s, end, "end positions", msg, msg_size) != 0)
        return -1;
    const int m = s->n * FSI_DIM;
    implicit_verdict *v = &s->verdict;
    *v = (implicit_verdict){1, 0.0, 0.0, 0, s->restarted};
    if (!(s->dt > 0.0) || m == 0)
        return 0;
    double r2 = 0.0;
    for (int k = 0; k < m; k++) {
        s->u_out[k] = (end->position[k] - s->x_start[k]) / s->dt;
        r2 += (s->u_out[k] - s->u_in[k]) * (s->u_out[k] - s->u_in[k]);
    }
    /* Displacements are u dt: the same relative residual. */
    v->displacement_residual = relative_difference(s->u_out, s->u_in, m);
    const double rms_displacement = s->dt * sqrt(r2 / (double)s->n);
    const int motion_converged = v->displacement_residual <= s->tolerance ||
                                 rms_displacement <= s->absolute_tolerance;
    v->force_residual = s->have_force_last ? relative_difference(s->force, s->force_last, m)
                                           : 0.0;
    v->converged = motion_converged && v->force_residual <= s->tolerance;
    if (s->repeat_motion)
        memcpy(s->u_next, s->u_in, (size_t)m * sizeof(double));
    else if (fsi_accel_next(s->accel, s->u_in, s->u_out, s->u_next) != 0) {
        snprintf(msg, msg_size, "out of memory for the coupling acceleration");
        return -1;
    }
    v->history_columns = fsi_accel_columns(s->accel);
    memcpy(s->force_last, s->force, (size_t)m * sizeof(double));
    s->have_force_last = 1;
    return 0;
}

void implicit_solid_accept(implicit_solid *s)
{
    fsi_accel_end_window(s->accel);
}
