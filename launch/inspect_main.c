/* `fsi inspect LOG`: reads a traffic log written by `fsi run --log-traffic` (LCM's
 * event-log format) and prints one line per window, iteration and channel: messages,
 * duplicate copies, resend requests, particle count, pressure range, largest force
 * and velocity. Heartbeats are summarised at the end. */
#include <lcm/eventlog.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli_args.h"
#include "dim.h"
#include "log.h"
#include "messages.h"
#include "protocol.h"

#define MAX_SEEN 8

/* What one (window, iteration, message kind) line aggregates. */
typedef struct {
    int used;
    int window, iteration;
    fsi_msg_type type;
    long messages;
    long duplicates;          /* copies of a message already seen (same sender and seq) */
    long resend_requests;     /* resend_t asking for this window and kind */
    int n;                    /* particles in the interface message */
    double p_min, p_max, f_max, v_max;
    double dt;
    int n_seen;
    char seen_sender[MAX_SEEN][64];
    long long seen_seq[MAX_SEEN];
} line_stats;

typedef struct {
    line_stats *slots;
    size_t capacity, count;
    long heartbeats, undecodable, other_channels, events;
} inspection;

static size_t slot_hash(int window, int iteration, int type, size_t capacity)
{
    unsigned long long h = (unsigned long long)(window + 2) * 1000003ull +
                           (unsigned long long)iteration * 97ull + (unsigned long long)type;
    return (size_t)(h * 11400714819323198485ull >> 20) % capacity;
}

static void grow(inspection *in);

static line_stats *line_for(inspection *in, int window, int iteration, fsi_msg_type type)
{
    if (2 * (in->count + 1) > in->capacity)
        grow(in);
    size_t i = slot_hash(window, iteration, type, in->capacity);
    for (;; i = (i + 1) % in->capacity) {
        line_stats *s = &in->slots[i];
        if (!s->used) {
            *s = (line_stats){.used = 1, .window = window, .iteration = iteration, .type = type,
                              .p_min = INFINITY, .p_max = -INFINITY, .dt = NAN};
            in->count++;
            return s;
        }
        if (s->window == window && s->iteration == iteration && s->type == type)
            return s;
    }
}

static void grow(inspection *in)
{
    inspection bigger = *in;
    bigger.capacity = in->capacity ? 2 * in->capacity : 1024;
    bigger.slots = calloc(bigger.capacity, sizeof *bigger.slots);
    bigger.count = 0;
    if (!bigger.slots) {
        fsi_error("out of memory");
        exit(FSI_EXIT_RUN_FAILURE);
    }
    for (size_t i = 0; i < in->capacity; i++)
        if (in->slots[i].used) {
            line_stats *s = line_for(&bigger, in->slots[i].window, in->slots[i].iteration,
                                     in->slots[i].type);
            *s = in->slots[i];
        }
    free(in->slots);
    *in = bigger;
}

static double vector_norm(const double *v)
{
    double s = 0.0;
    for (int d = 0; d < FSI_DIM; d++)
        s += v[d] * v[d];
    return sqrt(s);
}

static int is_duplicate(line_stats *s, const fsi_header_t *h)
{
    for (int i = 0; i < s->n_seen; i++)
        if (s->seen_seq[i] == h->seq && strcmp(s->seen_sender[i], h->sender) == 0)
            return 1;
    if (s->n_seen < MAX_SEEN) {
        snprintf(s->seen_sender[s->n_seen], sizeof s->seen_sender[0], "%s", h->sender);
        s->seen_seq[s->n_seen++] = h->seq;
    }
    return 0;
}

static void take_interface(line_stats *s, int n, int dim, const double *pressure,
                           const double *force, const double *velocity)
{
    if (dim != FSI_DIM)
        return;
    s->n = n;
    for (int i = 0; i < n; i++) {
        if (pressure) {
            s->p_min = fmin(s->p_min, pressure[i]);
            s->p_max = fmax(s->p_max, pressure[i]);
        }
        if (force)
            s->f_max = fmax(s->f_max, vector_norm(force + i * FSI_DIM));
        if (velocity)
            s->v_max = fmax(s->v_max, vector_norm(velocity + i * FSI_DIM));
    }
}

/* Adds one event of our channels; returns -1 when it does not decode. */
static int take_event(inspection *in, fsi_msg_type type, const void *data, int len)
{
    fsi_message m;
    if (fsi_message_decode(type, data, len, &m) != 0)
        return -1;
    const fsi_header_t *h = &m.header;
    if (type == FSI_MSG_HEARTBEAT) {
        in->heartbeats++;
    } else if (type == FSI_MSG_RESEND) {
        const fsi_resend_t *r = &m.resend;
        if (r->msg_type >= 0 && r->msg_type < FSI_MSG_COUNT)
            line_for(in, r->want_window, r->want_iteration, (fsi_msg_type)r->msg_type)
                ->resend_requests++;
    } else {
        line_stats *s = line_for(in, h->window, h->iteration, type);
        s->messages++;
        s->duplicates += is_duplicate(s, h);
        if (type == FSI_MSG_STEP)
            s->dt = m.step.dt;
        else if (type == FSI_MSG_SOLID_STATE)
            take_interface(s, m.solid_state.n, m.solid_state.dim, NULL, NULL,
                           m.solid_state.velocity);
        else if (type == FSI_MSG_FLUID_LOAD)
            take_interface(s, m.fluid_load.n, m.fluid_load.dim, m.fluid_load.pressure,
                           m.fluid_load.force, NULL);
    }
    fsi_message_cleanup(type, &m);
    return 0;
}

static int by_window_then_kind(const void *a, const void *b)
{
    const line_stats *x = a, *y = b;
    if (x->used != y->used)
        return y->used - x->used;
    if (x->window != y->window)
        return x->window < y->window ? -1 : 1;
    if (x->iteration != y->iteration)
        return x->iteration < y->iteration ? -1 : 1;
    return (int)x->type - (int)y->type;
}

static void print_number(double v)
{
    if (isfinite(v))
        printf(" %12.5g", v);
    else
        printf(" %12s", "-");
}

static void print_lines(inspection *in)
{
    qsort(in->slots, in->capacity, sizeof *in->slots, by_window_then_kind);
    printf("%7s %4s %-16s %5s %4s %4s %7s %12s %12s %12s %12s %12s\n", "window", "iter",
           "channel", "msgs", "dup", "req", "n", "dt", "p_min", "p_max", "max|F|", "max|v|");
    for (size_t i = 0; i < in->count; i++) {
        const line_stats *s = &in->slots[i];
        int interface = s->type == FSI_MSG_SOLID_STATE || s->type == FSI_MSG_FLUID_LOAD;
        printf("%7d %4d %-16s %5ld %4ld %4ld", s->window, s->iteration, fsi_msg_channel(s->type),
               s->messages, s->duplicates, s->resend_requests);
        if (interface)
            printf(" %7d", s->n);
        else
            printf(" %7s", "-");
        print_number(s->dt);
        print_number(s->type == FSI_MSG_FLUID_LOAD ? s->p_min : NAN);
        print_number(s->type == FSI_MSG_FLUID_LOAD ? s->p_max : NAN);
        print_number(s->type == FSI_MSG_FLUID_LOAD ? s->f_max : NAN);
        print_number(s->type == FSI_MSG_SOLID_STATE ? s->v_max : NAN);
        printf("\n");
    }
    printf("# %ld events: %ld heartbeats, %ld undecodable, %ld on other channels\n", in->events,
           in->heartbeats, in->undecodable, in->other_channels);
}

static void usage(FILE *out)
{
    fprintf(out, "usage: fsi inspect LOG\n"
                 "  LOG   a traffic.lcmlog from fsi run --log-traffic; prints one line per\n"
                 "        window, iteration and message kind, heartbeats summed at the end\n");
}

int main(int argc, char **argv)
{
    fsi_log_set_name("fsi inspect");
    const char *path = NULL;
    fsi_args a = fsi_args_begin(argc, argv, "fsi inspect", usage);
    while (fsi_args_next(&a)) {
        if (fsi_arg_positional(&a) && !path)
            path = a.arg;
        else
            fsi_arg_unknown(&a);
    }
    if (a.error)
        return FSI_EXIT_BAD_INPUT;
    if (!path) {
        usage(stderr);
        return FSI_EXIT_BAD_INPUT;
    }
    lcm_eventlog_t *log = lcm_eventlog_create(path, "r");
    if (!log) {
        fsi_error("cannot open traffic log '%s'", path);
        return FSI_EXIT_BAD_INPUT;
    }
    inspection in = {0};
    grow(&in);
    lcm_eventlog_event_t *e;
    while ((e = lcm_eventlog_read_next_event(log))) {
        in.events++;
        int type = fsi_msg_type_of_channel(e->channel);
        if (type < 0)
            in.other_channels++;
        else if (take_event(&in, (fsi_msg_type)type, e->data, (int)e->datalen) != 0)
            in.undecodable++;
        lcm_eventlog_free_event(e);
    }
    lcm_eventlog_destroy(log);
    print_lines(&in);
    free(in.slots);
    return FSI_EXIT_OK;
}
