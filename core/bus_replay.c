#include "bus_replay.h"

#include <limits.h>
#include <lcm/eventlog.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "log.h"
#include "messages.h"
#include "replay_compare.h"

/* One recorded message, kept encoded. */
typedef struct {
    fsi_msg_type type;
    void *bytes;
    int len;
    int window, iteration;
} recorded;

/* A relevant event read past the gate: an input, or an own message. */
typedef struct {
    recorded m;
    int own;
} lookahead_item;

/* Where a (window, iteration) key stands; the last one seen per kind tells a new
 * message from a repeat (a resent copy, a repeated register, the 3 aborts). */
typedef struct {
    int window, iteration;
} message_key;

struct fsi_replay {
    lcm_eventlog_t *log;
    char path[PATH_MAX];
    char self[64];
    int64_t run_id;
    int at_end;

    /* Recorded messages for this participant, due before its next own recorded
     * message that it has not published yet (the 'gate'). The log is read only as
     * far as the gate, so memory stays small however long the run. */
    recorded *queue;
    int queue_head, queue_count, queue_capacity;
    recorded gate;
    int have_gate;
    recorded current;            /* the input last handed out */
    /* Events read past the gate while looking for an input of the gate's window that
     * the recorder logged after the gate: the recorder's order between senders is the
     * order the datagrams reached it, not the order they were sent in. */
    lookahead_item *lookahead;
    int n_lookahead, lookahead_capacity;
    /* Own messages published before the log shows them: when a message was lost and
     * sent again on request, its first recorded copy comes after later ones. They
     * are compared when the read-ahead reaches that copy. */
    recorded *early;
    int n_early, early_capacity;

    message_key recorded_key[FSI_MSG_COUNT];   /* own messages read from the log */
    message_key published_key[FSI_MSG_COUNT];  /* own messages published in the replay */

    long compared, differences, missing, delivered;
    int first_window;
    char first[768];
    int finished;
};

/* Own messages that are compared: what the computation decides. Heartbeats and
 * resend requests depend on timing and are not. */
static int is_compared_kind(fsi_msg_type type)
{
    return type == FSI_MSG_REGISTER || type == FSI_MSG_SOLID_STATE ||
           type == FSI_MSG_FLUID_LOAD || type == FSI_MSG_DONE || type == FSI_MSG_ABORT;
}

/* Messages of others that this participant acts on. Other heartbeats only prove
 * liveness, which a replay has no use for; the coupler's "finished" one is what
 * lets fsi_close() return. */
static int is_input(fsi_msg_type type, const fsi_message *m, const char *self)
{
    switch (type) {
    case FSI_MSG_WELCOME:
        return strcmp(m->welcome.participant, self) == 0;
    case FSI_MSG_STEP:
    case FSI_MSG_SOLID_STATE:
    case FSI_MSG_FLUID_LOAD:
    case FSI_MSG_ABORT:
        return 1;
    case FSI_MSG_HEARTBEAT:
        return strcmp(m->header.sender, FSI_COUPLER_NAME) == 0 &&
               m->heartbeat.state == FSI_STATE_FINISHED;
    default:
        return 0;
    }
}

static int newer(message_key *last, int window, int iteration)
{
    if (window < last->window || (window == last->window && iteration <= last->iteration))
        return 0;
    *last = (message_key){window, iteration};
    return 1;
}

static recorded copy_recorded(fsi_msg_type type, const lcm_eventlog_event_t *e,
                              const fsi_header_t *h)
{
    recorded r = {type, malloc((size_t)e->datalen), (int)e->datalen, h->window, h->iteration};
    if (!r.bytes) {
        fsi_error("replay: out of memory reading %s", "the traffic log");
        exit(FSI_EXIT_RUN_FAILURE);
    }
    memcpy(r.bytes, e->data, (size_t)e->datalen);
    return r;
}

/* Makes room for one more element in a growing array of 'count' elements. */
static void make_room(void **array, int count, int *capacity, size_t size)
{
    if (count < *capacity)
        return;
    int grown = *capacity ? 2 * *capacity : 16;
    void *a = realloc(*array, (size_t)grown * size);
    if (!a) {
        fsi_error("replay: out of memory (%d messages held)", count);
        exit(FSI_EXIT_RUN_FAILURE);
    }
    *array = a;
    *capacity = grown;
}

static void enqueue(fsi_replay *r, recorded m)
{
    if (r->queue_head == r->queue_count)
        r->queue_head = r->queue_count = 0;
    make_room((void **)&r->queue, r->queue_count, &r->queue_capacity, sizeof *r->queue);
    r->queue[r->queue_count++] = m;
}

static void difference(fsi_replay *r, int window, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));

static void difference(fsi_replay *r, int window, const char *fmt, ...)
{
    char text[sizeof r->first];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(text, sizeof text, fmt, ap);
    va_end(ap);
    if (r->differences++ == 0) {
        r->first_window = window;
        snprintf(r->first, sizeof r->first, "%s", text);
        fsi_error("replay: first difference: %s", text);
    }
}

static void compare_with_recorded(fsi_replay *r, fsi_msg_type type, const void *msg,
                                  const recorded *own)
{
    char why[512];
    r->compared++;
    if (!fsi_replay_same(type, msg, own->bytes, own->len, why, sizeof why))
        difference(r, own->window, "%s of window %d: %s", fsi_msg_name(type), own->window, why);
}

/* Keeps an encoded copy of a message published before its recorded copy was read. */
static void keep_early(fsi_replay *r, fsi_msg_type type, const void *msg)
{
    const fsi_header_t *h = msg;
    int len = fsi_message_encoded_size(type, msg);
    recorded m = {type, len > 0 ? malloc((size_t)len) : NULL, len, h->window, h->iteration};
    make_room((void **)&r->early, r->n_early, &r->early_capacity, sizeof *r->early);
    if (!m.bytes || fsi_message_encode(type, msg, m.bytes, len) != len) {
        fsi_error("replay: out of memory keeping %s of window %d", fsi_msg_name(type),
                  h->window);
        exit(FSI_EXIT_RUN_FAILURE);
    }
    r->early[r->n_early++] = m;
}

/* Compares the recorded 'own' with the early copy of the same message, if there is
 * one; returns 1 when there was (and frees 'own'). */
static int compare_early(fsi_replay *r, recorded *own)
{
    for (int i = 0; i < r->n_early; i++) {
        recorded *m = &r->early[i];
        if (m->type != own->type || m->window != own->window || m->iteration != own->iteration)
            continue;
        fsi_message mine;
        if (fsi_message_decode(m->type, m->bytes, m->len, &mine) == 0) {
            compare_with_recorded(r, m->type, &mine, own);
            fsi_message_cleanup(m->type, &mine);
        }
        free(m->bytes);
        *m = r->early[--r->n_early];
        free(own->bytes);
        return 1;
    }
    return 0;
}

/* Sorts one logged event: an input, this participant's next own message, or
 * nothing (another run, another kind, a repeat, undecodable bytes); returns 1 and
 * fills 'item' for the first two. */
static int classify_event(fsi_replay *r, const lcm_eventlog_event_t *e, lookahead_item *item)
{
    int type = fsi_msg_type_of_channel(e->channel);
    fsi_message m;
    if (type < 0 || fsi_message_decode((fsi_msg_type)type, e->data, (int)e->datalen, &m) != 0)
        return 0;
    const fsi_header_t *h = &m.header;
    int relevant = 0;
    if (h->protocol_version == FSI_PROTOCOL_VERSION && h->run_id == r->run_id) {
        if (strcmp(h->sender, r->self) != 0) {
            relevant = is_input((fsi_msg_type)type, &m, r->self);
            item->own = 0;
        } else {
            relevant = is_compared_kind((fsi_msg_type)type) &&
                       newer(&r->recorded_key[type], h->window, h->iteration);
            item->own = 1;
        }
        if (relevant)
            item->m = copy_recorded((fsi_msg_type)type, e, h);
    }
    fsi_message_cleanup((fsi_msg_type)type, &m);
    return relevant;
}

static void take_item(fsi_replay *r, lookahead_item item)
{
    if (!item.own)
        enqueue(r, item.m);
    else if (!compare_early(r, &item.m)) {
        r->gate = item.m;
        r->have_gate = 1;
    }
}

/* The next relevant event of the log itself; 0 at its end. */
static int read_log_item(fsi_replay *r, lookahead_item *item)
{
    while (!r->at_end) {
        lcm_eventlog_event_t *e = lcm_eventlog_read_next_event(r->log);
        if (!e) {
            r->at_end = 1;
            break;
        }
        int relevant = classify_event(r, e, item);
        lcm_eventlog_free_event(e);
        if (relevant)
            return 1;
    }
    return 0;
}

/* The next relevant logged event, from the look-ahead first; 0 at the log's end. */
static int next_item(fsi_replay *r, lookahead_item *item)
{
    if (r->n_lookahead == 0)
        return read_log_item(r, item);
    *item = r->lookahead[0];
    memmove(r->lookahead, r->lookahead + 1, (size_t)--r->n_lookahead * sizeof *item);
    return 1;
}

/* Reads the log up to this participant's next own message, or to its end. */
static void read_ahead(fsi_replay *r)
{
    lookahead_item item;
    while (!r->have_gate && next_item(r, &item))
        take_item(r, item);
}

/* How far past the gate an input of the gate's window is looked for: the recorder
 * can log a datagram after others sent up to a few windows later, never thousands. */
enum { LOOKAHEAD_LIMIT = 4096 };

/* A participant waits with nothing due before the gate: an input of the gate's
 * window (or an earlier one) logged after the gate is due now, since the participant
 * could not have published the gate without it. Inputs of later windows and own
 * messages stay in order. */
static void take_late_input(fsi_replay *r)
{
    for (int i = 0;; i++) {
        if (i == r->n_lookahead) {
            lookahead_item item;
            if (r->n_lookahead >= LOOKAHEAD_LIMIT || !read_log_item(r, &item))
                return;
            make_room((void **)&r->lookahead, r->n_lookahead, &r->lookahead_capacity,
                      sizeof *r->lookahead);
            r->lookahead[r->n_lookahead++] = item;
        }
        lookahead_item *it = &r->lookahead[i];
        if (!it->own && it->m.window <= r->gate.window) {
            enqueue(r, it->m);
            memmove(it, it + 1, (size_t)(r->n_lookahead - i - 1) * sizeof *it);
            r->n_lookahead--;
            return;
        }
    }
}

static void init_keys(message_key *keys)
{
    /* Below every real key: registers carry window -1. */
    for (int i = 0; i < FSI_MSG_COUNT; i++)
        keys[i] = (message_key){INT_MIN, INT_MIN};
}

fsi_replay *fsi_replay_open(const char *log_path, const char *self, int64_t run_id)
{
    fsi_replay *r = calloc(1, sizeof *r);
    if (!r)
        return NULL;
    snprintf(r->path, sizeof r->path, "%s", log_path);
    snprintf(r->self, sizeof r->self, "%s", self);
    r->run_id = run_id;
    r->first_window = -1;
    init_keys(r->recorded_key);
    init_keys(r->published_key);
    r->log = lcm_eventlog_create(log_path, "r");
    if (!r->log) {
        fsi_error("replay: cannot read the traffic log '%s'", log_path);
        free(r);
        return NULL;
    }
    read_ahead(r);
    if (!r->have_gate) {
        fsi_error("replay: the traffic log '%s' holds no message of participant '%s' in run "
                  "%lld",
                  log_path, self, (long long)run_id);
        fsi_replay_free(r);
        return NULL;
    }
    return r;
}

int fsi_replay_next_input(fsi_replay *r, int waiting, fsi_msg_type *type, const void **bytes,
                          int *len)
{
    free(r->current.bytes);
    r->current.bytes = NULL;
    read_ahead(r);
    if (waiting && r->queue_head == r->queue_count && r->have_gate)
        take_late_input(r);
    if (r->queue_head == r->queue_count)
        return 0;
    r->current = r->queue[r->queue_head++];
    r->delivered++;
    *type = r->current.type;
    *bytes = r->current.bytes;
    *len = r->current.len;
    return 1;
}

void fsi_replay_compare(fsi_replay *r, fsi_msg_type type, const void *msg)
{
    const fsi_header_t *h = msg;
    if (!is_compared_kind(type) || !newer(&r->published_key[type], h->window, h->iteration))
        return;
    read_ahead(r);
    if (r->have_gate && r->gate.type == type && r->gate.window == h->window &&
        r->gate.iteration == h->iteration) {
        compare_with_recorded(r, type, msg, &r->gate);
        free(r->gate.bytes);
        r->gate.bytes = NULL;
        r->have_gate = 0;
    } else {
        keep_early(r, type, msg);
    }
}

void fsi_replay_explain_wait(const fsi_replay *r, int window)
{
    if (r->have_gate)
        fsi_error("replay: %s waits in window %d for a message that the recording gives it "
                  "only after its own %s of window %d, which it has not published: the "
                  "replay left the recorded run",
                  r->self, window, fsi_msg_name(r->gate.type), r->gate.window);
    else
        fsi_error("replay: %s waits in window %d, but the recording %s ends here", r->self,
                  window, r->path);
}

static void write_report(const fsi_replay *r)
{
    const char *path = getenv("FSI_REPLAY_REPORT");
    FILE *f = path && *path ? fopen(path, "w") : NULL;
    if (!f)
        return;
    fprintf(f,
            "participant = %s\nlog = %s\ncompared = %ld\ndifferences = %ld\nmissing = %ld\n"
            "inputs = %ld\nfirst_difference_window = %d\nfirst_difference = %s\n",
            r->self, r->path, r->compared, r->differences, r->missing, r->delivered,
            r->first_window, r->differences ? r->first : "none");
    fclose(f);
}

long fsi_replay_finish(fsi_replay *r)
{
    if (r->finished)
        return r->differences;
    r->finished = 1;
    /* Own recorded messages the replay never published. Inputs read on the way are
     * of no more use. */
    for (read_ahead(r); r->have_gate; read_ahead(r)) {
        r->missing++;
        difference(r, r->gate.window, "%s of window %d is recorded but was not published",
                   fsi_msg_name(r->gate.type), r->gate.window);
        free(r->gate.bytes);
        r->gate.bytes = NULL;
        r->have_gate = 0;
        for (; r->queue_head < r->queue_count; r->queue_head++)
            free(r->queue[r->queue_head].bytes);
    }
    for (int i = 0; i < r->n_early; i++) {
        r->compared++;
        difference(r, r->early[i].window, "%s of window %d was published but is not recorded",
                   fsi_msg_name(r->early[i].type), r->early[i].window);
    }
    if (r->differences)
        fsi_error("replay: %ld of %ld messages differ from the recording (%ld recorded ones "
                  "not published, %d published ones not recorded); first: %s",
                  r->differences, r->compared, r->missing, r->n_early, r->first);
    else
        fsi_info("replay: %ld messages compared, all identical to the recording", r->compared);
    write_report(r);
    return r->differences;
}

void fsi_replay_free(fsi_replay *r)
{
    if (!r)
        return;
    for (int i = r->queue_head; i < r->queue_count; i++)
        free(r->queue[i].bytes);
    free(r->queue);
    for (int i = 0; i < r->n_early; i++)
        free(r->early[i].bytes);
    free(r->early);
    for (int i = 0; i < r->n_lookahead; i++)
        free(r->lookahead[i].m.bytes);
    free(r->lookahead);
    free(r->gate.bytes);
    free(r->current.bytes);
    if (r->log)
        lcm_eventlog_destroy(r->log);
    free(r);
}
