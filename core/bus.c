#include "bus.h"

#include <lcm/lcm.h>
#include <math.h>
#include <pthread.h>
#include <stdatomic.h>
#include <unistd.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bus_replay.h"
#include "messages.h"
#include "log.h"
#include "timers.h"

/* Kept copies of recent data messages, answered on resend_t. A handful covers the
 * lockstep protocol, where only the current window's messages are ever asked for. */
#define KEPT_MAX 16
/* A copy is published again at most this often: requests that queued up while this
 * process was computing must not each send a large message. Shorter than the
 * shortest interval between a requester's requests (core/request_timer.h). */
#define RESEND_MIN_GAP_S 0.0002

/* Measured loss: the fraction of other processes' sequence numbers never received,
 * smoothed over about this many recent ones. */
#define LOSS_GAIN (1.0 / 64)
/* With a measured loss p from LOSS_FOR_COPIES on, messages up to COPY_MAX_BYTES are
 * sent in n copies, the fewest with p^n <= COPIES_TARGET_LOSS, at most COPIES_MAX.
 * A loss-free run measures 0 and sends one copy; a single lost message moves the
 * estimate by LOSS_GAIN, below the threshold. */
#define LOSS_FOR_COPIES 0.02
#define COPIES_TARGET_LOSS 0.05
#define COPIES_MAX 12
#define COPY_MAX_BYTES 65536
#define SENDERS_MAX 8
/* Messages LCM queues for this process while it computes; beyond them it drops new
 * ones. Its default of 30 is a few windows of heartbeats and copies under heavy
 * loss. Large messages are never copied and resent at most once per gap. */
#define QUEUE_CAPACITY 1000

typedef struct {
    char name[64];
    int64_t seq;      /* highest sequence number received */
} sender_seen;

typedef struct {
    int used;
    fsi_msg_type type;
    int window, iteration;
    void *bytes;
    int len;
    double last_sent;
} kept_message;

struct fsi_bus {
    lcm_t *lcm;                /* NULL when replaying */
    fsi_replay *replay;        /* FSI_REPLAY_LOG: a recording instead of the network */
    char self[64];
    int64_t run_id;
    fsi_bus_handler handler;
    void *user;

    pthread_mutex_t lock;      /* guards everything below */
    int64_t seq;
    kept_message kept[KEPT_MAX];
    int kept_next;
    fsi_bus_counters counters;
    double drop_fraction;
    uint64_t drop_state;
    sender_seen senders[SENDERS_MAX];
    int n_senders;
    double measured_loss;
    int delivering_new;        /* set while the handler runs, see fsi_bus_message_is_new */

    pthread_t heartbeat_thread;
    int heartbeat_running;
    double heartbeat_interval;
    atomic_int heartbeat_stop;
    atomic_int heartbeat_window;
    atomic_int heartbeat_state;
};

static int keeps_copy(fsi_msg_type type)
{
    return type == FSI_MSG_STEP || type == FSI_MSG_SOLID_STATE ||
           type == FSI_MSG_FLUID_LOAD || type == FSI_MSG_DONE;
}

/* splitmix64: a small, well-mixed generator, so drops are reproducible per seed. */
static uint64_t next_random(uint64_t *state)
{
    uint64_t z = (*state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

static uint64_t name_hash(const char *s)
{
    uint64_t h = 1469598103934665603ull;
    for (; *s; s++)
        h = (h ^ (unsigned char)*s) * 1099511628211ull;
    return h;
}

static void read_test_drop_switch(fsi_bus *b)
{
    const char *f = getenv("FSI_TEST_DROP_FRACTION");
    if (!f || !*f)
        return;
    char *end;
    double fraction = strtod(f, &end);
    if (*end || fraction < 0.0 || fraction >= 1.0) {
        fsi_warn("FSI_TEST_DROP_FRACTION='%s' is not in [0, 1); ignored", f);
        return;
    }
    const char *seed = getenv("FSI_TEST_DROP_SEED");
    unsigned long long seed_value = 1u;
    if (seed && *seed) {
        seed_value = strtoull(seed, &end, 10);
        if (*end || seed[0] == '-') {
            fsi_warn("FSI_TEST_DROP_SEED='%s' is not a non-negative integer; using 1", seed);
            seed_value = 1u;
        }
    }
    b->drop_fraction = fraction;
    b->drop_state = seed_value ^ name_hash(b->self);
}

static int test_drops_this_one(fsi_bus *b)
{
    if (b->drop_fraction <= 0.0)
        return 0;
    double u = (double)(next_random(&b->drop_state) >> 11) * 0x1.0p-53;
    return u < b->drop_fraction;
}

/* How many copies of a message of 'len' bytes to send at the measured loss. */
static int copies_for(const fsi_bus *b, int len)
{
    double p = b->measured_loss;
    if (p < LOSS_FOR_COPIES || len > COPY_MAX_BYTES)
        return 1;
    int n = (int)ceil(log(COPIES_TARGET_LOSS) / log(p));
    return n < 1 ? 1 : n > COPIES_MAX ? COPIES_MAX : n;
}

/* Sends bytes unless the test switch withholds them; caller holds the lock. */
static int send_locked(fsi_bus *b, fsi_msg_type type, const void *bytes, int len)
{
    if (test_drops_this_one(b)) {
        b->counters.dropped_by_test++;
        return 0;
    }
    if (lcm_publish(b->lcm, fsi_msg_channel(type), bytes, (unsigned)len) != 0) {
        b->counters.publish_failed++;
        return -1;
    }
    b->counters.published++;
    return 0;
}

static kept_message *find_kept(fsi_bus *b, fsi_msg_type type, int window, int iteration)
{
    for (int i = 0; i < KEPT_MAX; i++) {
        kept_message *k = &b->kept[i];
        if (k->used && k->type == type && k->window == window && k->iteration == iteration)
            return k;
    }
    return NULL;
}

static void keep_copy_locked(fsi_bus *b, fsi_msg_type type, int window, int iteration,
                             void *bytes, int len)
{
    kept_message *k = find_kept(b, type, window, iteration);
    if (!k) {
        k = &b->kept[b->kept_next];
        b->kept_next = (b->kept_next + 1) % KEPT_MAX;
    }
    free(k->bytes);
    *k = (kept_message){1, type, window, iteration, bytes, len, fsi_wall_seconds()};
}

/* Under measured loss: the further copies of a message just sent, each with its own
 * sequence number, so that receivers measure the loss of every copy (a resent copy
 * keeps its original's). Caller holds the lock; 'msg' has the header filled in. */
static void send_extra_copies_locked(fsi_bus *b, fsi_msg_type type, void *msg, int len)
{
    int n = copies_for(b, len);
    if (n < 2)
        return;
    void *copy = malloc((size_t)len);
    fsi_header_t *h = msg;
    for (int i = 1; copy && i < n; i++) {
        h->seq = ++b->seq;
        if (fsi_message_encode(type, msg, copy, len) == len && send_locked(b, type, copy, len) == 0)
            b->counters.extra_copies++;
    }
    free(copy);
}

int fsi_bus_publish(fsi_bus *b, fsi_msg_type type, void *msg)
{
    fsi_header_t *h = msg;

    pthread_mutex_lock(&b->lock);
    h->protocol_version = FSI_PROTOCOL_VERSION;
    h->run_id = b->run_id;
    h->seq = ++b->seq;
    h->sender = b->self;
    if (b->replay) {
        fsi_replay_compare(b->replay, type, msg);
        b->counters.published++;
        pthread_mutex_unlock(&b->lock);
        return 0;
    }
    int len = fsi_message_encoded_size(type, msg);
    void *bytes = len > 0 ? malloc((size_t)len) : NULL;
    int rc = -1;
    if (bytes && fsi_message_encode(type, msg, bytes, len) == len) {
        rc = send_locked(b, type, bytes, len);
        send_extra_copies_locked(b, type, msg, len);
        if (keeps_copy(type)) {
            keep_copy_locked(b, type, h->window, h->iteration, bytes, len);
            bytes = NULL;
        }
    } else {
        b->counters.publish_failed++;
    }
    pthread_mutex_unlock(&b->lock);
    free(bytes);
    if (rc != 0)
        fsi_error("bus: could not publish %s for window %d", fsi_msg_name(type), h->window);
    return rc;
}

int fsi_bus_request_resend(fsi_bus *b, const char *target, fsi_msg_type type, int window,
                           int iteration)
{
    fsi_resend_t r = {0};
    r.header.window = window;
    r.header.iteration = iteration;
    r.target = (char *)target;
    r.msg_type = (int32_t)type;
    r.want_window = window;
    r.want_iteration = iteration;
    pthread_mutex_lock(&b->lock);
    b->counters.resend_requests++;
    pthread_mutex_unlock(&b->lock);
    return fsi_bus_publish(b, FSI_MSG_RESEND, &r);
}

static void answer_resend(fsi_bus *b, const fsi_resend_t *r)
{
    if (strcmp(r->target, b->self) != 0 || r->msg_type < 0 || r->msg_type >= FSI_MSG_COUNT)
        return;
    pthread_mutex_lock(&b->lock);
    kept_message *k = find_kept(b, (fsi_msg_type)r->msg_type, r->want_window, r->want_iteration);
    double now = fsi_wall_seconds();
    if (k && now - k->last_sent >= RESEND_MIN_GAP_S) {
        k->last_sent = now;
        for (int i = copies_for(b, k->len); i > 0; i--)
            if (send_locked(b, k->type, k->bytes, k->len) == 0)
                b->counters.resent++;
    }
    pthread_mutex_unlock(&b->lock);
}

static void count(fsi_bus *b, long *counter)
{
    pthread_mutex_lock(&b->lock);
    (*counter)++;
    pthread_mutex_unlock(&b->lock);
}

/* Updates the measured loss from the sender's sequence numbers: the numbers skipped
 * since the highest one received were lost (on a sender's first message nothing is
 * known). Returns 1 when 'seq' is newer than any received from this sender, 0 for a
 * resent copy or a late one. */
static int note_sequence(fsi_bus *b, const char *sender, int64_t seq)
{
    pthread_mutex_lock(&b->lock);
    sender_seen *s = NULL;
    for (int i = 0; i < b->n_senders && !s; i++)
        if (strcmp(b->senders[i].name, sender) == 0)
            s = &b->senders[i];
    int is_new = 1;
    if (!s) {
        if (b->n_senders < SENDERS_MAX) {
            s = &b->senders[b->n_senders++];
            snprintf(s->name, sizeof s->name, "%s", sender);
            s->seq = seq;
        }
    } else if (seq <= s->seq) {
        is_new = 0;
    } else {
        /* Each skipped number counts as one lost message, each received one as one
         * arrived; a burst beyond 1000 adds no more information. */
        int64_t skipped = seq - s->seq - 1;
        for (int64_t i = 0; i < skipped && i < 1000; i++)
            b->measured_loss += LOSS_GAIN * (1.0 - b->measured_loss);
        b->measured_loss -= LOSS_GAIN * b->measured_loss;
        s->seq = seq;
    }
    pthread_mutex_unlock(&b->lock);
    return is_new;
}

/* Every message passes here, from the network or from a recording; only valid
 * messages of this run from others go on. 'type' is the channel's kind or -1. */
static void accept_message(fsi_bus *b, int type, const void *data, int len)
{
    if (type < 0) {
        count(b, &b->counters.ignored_unknown_channel);
        return;
    }
    fsi_message msg;
    /* lcm-gen's decode checks the type fingerprint and every length against the buffer. */
    if (fsi_message_decode((fsi_msg_type)type, data, len, &msg) != 0) {
        count(b, &b->counters.ignored_undecodable);
        return;
    }
    const fsi_header_t *h = &msg.header;
    if (h->protocol_version != FSI_PROTOCOL_VERSION) {
        count(b, &b->counters.ignored_bad_version);
    } else if (h->run_id != b->run_id) {
        count(b, &b->counters.ignored_foreign_run);
    } else if (strcmp(h->sender, b->self) != 0) {
        count(b, &b->counters.received);
        int is_new = note_sequence(b, h->sender, h->seq);
        if (type == FSI_MSG_RESEND) {
            answer_resend(b, &msg.resend);
        } else if (b->handler) {
            b->delivering_new = is_new;
            b->handler((fsi_msg_type)type, &msg, b->user);
            b->delivering_new = 0;
        }
    }
    fsi_message_cleanup((fsi_msg_type)type, &msg);
}

static void on_lcm_message(const lcm_recv_buf_t *rbuf, const char *channel, void *user)
{
    accept_message(user, fsi_msg_type_of_channel(channel), rbuf->data, (int)rbuf->data_size);
}

/* Hands the next recorded message due to the handler; 0 when none is due. */
static int replay_one(fsi_bus *b, int waiting)
{
    fsi_msg_type type;
    const void *bytes;
    int len;
    pthread_mutex_lock(&b->lock);
    int due = fsi_replay_next_input(b->replay, waiting, &type, &bytes, &len);
    pthread_mutex_unlock(&b->lock);
    /* The bytes stay valid until the next call, which only this thread makes. */
    if (due)
        accept_message(b, (int)type, bytes, len);
    return due;
}

/* The process may leave through exit() (an abort, a failed wait) without closing
 * the bus; the replay's verdict must still be written. One bus per process replays. */
static fsi_bus *replaying_bus;

static void finish_replay_at_exit(void)
{
    fsi_bus *b = replaying_bus;
    if (!b)
        return;
    /* No heartbeat thread runs in a replay, so a lock held here is held by this
     * thread, which left through exit() from inside the replay (out of memory). */
    int locked = pthread_mutex_trylock(&b->lock) == 0;
    fsi_replay_finish(b->replay);
    if (locked)
        pthread_mutex_unlock(&b->lock);
}

/* FSI_REPLAY_LOG: the recording replaces the network entirely, no LCM is opened. */
static int open_replay(fsi_bus *b, const char *log_path)
{
    b->replay = fsi_replay_open(log_path, b->self, b->run_id);
    if (!b->replay)
        return -1;
    fsi_info("replaying %s from %s (no network)", b->self, log_path);
    replaying_bus = b;
    atexit(finish_replay_at_exit);
    return 0;
}

fsi_bus *fsi_bus_open(const char *url, const char *self, int64_t run_id,
                      fsi_bus_handler handler, void *user)
{
    fsi_bus *b = calloc(1, sizeof *b);
    if (!b)
        return NULL;
    snprintf(b->self, sizeof b->self, "%s", self);
    b->run_id = run_id;
    b->handler = handler;
    b->user = user;
    pthread_mutex_init(&b->lock, NULL);
    atomic_init(&b->heartbeat_stop, 0);
    atomic_init(&b->heartbeat_window, -1);
    atomic_init(&b->heartbeat_state, 0);
    read_test_drop_switch(b);
    const char *replay_log = getenv("FSI_REPLAY_LOG");
    if (replay_log && *replay_log) {
        if (open_replay(b, replay_log) == 0)
            return b;
        pthread_mutex_destroy(&b->lock);
        free(b);
        return NULL;
    }
    if (!url || !*url)
        url = FSI_DEFAULT_LCM_URL;
    b->lcm = lcm_create(url);
    if (!b->lcm) {
        fsi_error("bus: cannot open LCM URL '%s' (no multicast route? see docs/protocol.md)",
                  url);
        pthread_mutex_destroy(&b->lock);
        free(b);
        return NULL;
    }
    lcm_subscription_t *all = lcm_subscribe(b->lcm, ".*", on_lcm_message, b);
    if (!all || lcm_subscription_set_queue_capacity(all, QUEUE_CAPACITY) != 0) {
        fsi_error("bus: cannot subscribe on '%s'", url);
        fsi_bus_close(b);
        return NULL;
    }
    return b;
}

int fsi_bus_poll(fsi_bus *b, double timeout_s)
{
    if (b->replay) {
        /* Whoever polls waits for something; when the recording has nothing due
         * before this process's own next message, it never will. */
        if (replay_one(b, 1))
            return 1;
        fsi_replay_explain_wait(b->replay, atomic_load(&b->heartbeat_window));
        return -1;
    }
    int ms = timeout_s <= 0 ? 0 : (int)(timeout_s * 1000.0 + 0.5);
    return lcm_handle_timeout(b->lcm, ms);
}

int fsi_bus_drain(fsi_bus *b)
{
    int n = 0, rc;
    if (b->replay) {
        while (replay_one(b, 0))
            n++;
        return n;
    }
    while ((rc = lcm_handle_timeout(b->lcm, 0)) > 0)
        n++;
    return rc < 0 ? -1 : n;
}

static void *heartbeat_loop(void *arg)
{
    fsi_bus *b = arg;
    long pause_ms = (long)(b->heartbeat_interval * 1e3);
    while (!atomic_load(&b->heartbeat_stop)) {
        fsi_heartbeat_t hb = {0};
        hb.header.window = atomic_load(&b->heartbeat_window);
        hb.state = atomic_load(&b->heartbeat_state);
        fsi_bus_publish(b, FSI_MSG_HEARTBEAT, &hb);
        /* Short naps, so that close does not wait a whole interval. */
        for (long slept = 0; slept < pause_ms && !atomic_load(&b->heartbeat_stop); slept += 10)
            usleep(10000);
    }
    return NULL;
}

int fsi_bus_start_heartbeat(fsi_bus *b, double interval_s)
{
    if (b->heartbeat_running || b->replay)
        return 0;   /* a replay has nobody to tell that it is alive */
    b->heartbeat_interval = interval_s;
    atomic_store(&b->heartbeat_stop, 0);
    if (pthread_create(&b->heartbeat_thread, NULL, heartbeat_loop, b) != 0) {
        fsi_error("bus: cannot start the heartbeat thread");
        return -1;
    }
    b->heartbeat_running = 1;
    return 0;
}

void fsi_bus_set_heartbeat(fsi_bus *b, int window, int state)
{
    atomic_store(&b->heartbeat_window, window);
    atomic_store(&b->heartbeat_state, state);
}

fsi_bus_counters fsi_bus_get_counters(fsi_bus *b)
{
    pthread_mutex_lock(&b->lock);
    fsi_bus_counters c = b->counters;
    pthread_mutex_unlock(&b->lock);
    return c;
}

int fsi_bus_message_is_new(const fsi_bus *b)
{
    return b->delivering_new;
}

double fsi_bus_measured_loss(fsi_bus *b)
{
    pthread_mutex_lock(&b->lock);
    double p = b->measured_loss;
    pthread_mutex_unlock(&b->lock);
    return p;
}

double fsi_bus_test_drop_fraction(const fsi_bus *b)
{
    return b->drop_fraction;
}

int fsi_bus_replaying(const fsi_bus *b)
{
    return b->replay != NULL;
}

const char *fsi_bus_self(const fsi_bus *b)
{
    return b->self;
}

void fsi_bus_close(fsi_bus *b)
{
    if (!b)
        return;
    if (b->heartbeat_running) {
        atomic_store(&b->heartbeat_stop, 1);
        pthread_join(b->heartbeat_thread, NULL);
    }
    if (b->lcm)
        lcm_destroy(b->lcm);
    if (b->replay) {
        fsi_replay_finish(b->replay);
        fsi_replay_free(b->replay);
        replaying_bus = NULL;
    }
    for (int i = 0; i < KEPT_MAX; i++)
        free(b->kept[i].bytes);
    pthread_mutex_destroy(&b->lock);
    free(b);
}
