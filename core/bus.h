/* The bus: LCM publish/subscribe plus what UDP multicast lacks (docs/protocol.md).
 *
 * - Every published message gets the protocol version, run id, sender name and a
 *   per-sender sequence number in its header.
 * - The last data messages (step, solid_state, fluid_load, done) are kept; a resend_t
 *   naming this sender is answered by publishing the kept copy again.
 * - Received messages are checked before anyone sees them: another run's, another
 *   protocol version's, undecodable ones (wrong type or size) and unknown channels are
 *   ignored and counted, never passed on; our own echoes are dropped.
 * - Loss is measured from the gaps in every sender's sequence numbers; while it is
 *   high, small messages are sent in several copies.
 * - Test switch: FSI_TEST_DROP_FRACTION=f in the environment drops a fraction f of the
 *   messages this process publishes, at random from FSI_TEST_DROP_SEED (default 1).
 *   Only for tests that prove recovery; the run log records it.
 *
 * - Replay: FSI_REPLAY_LOG=path in the environment replaces the network by a traffic
 *   log (core/bus_replay.h): nothing is sent, the recorded messages for this process
 *   are received, and what it publishes is compared with what it published then.
 *
 * Thread safety: fsi_bus_publish may be called from any thread; fsi_bus_poll only
 * from one thread (the one that owns the handler). */
#ifndef FSI_BUS_H
#define FSI_BUS_H

#include <stdint.h>

#include "protocol.h"

typedef struct fsi_bus fsi_bus;

typedef struct {
    long published;
    long publish_failed;
    long dropped_by_test;        /* withheld by FSI_TEST_DROP_FRACTION */
    long received;               /* valid messages of this run from others */
    long resent;                 /* kept copies published again on request */
    long resend_requests;        /* resend_t this process sent */
    long extra_copies;           /* further copies sent because loss was measured */
    long ignored_foreign_run;
    long ignored_bad_version;
    long ignored_undecodable;
    long ignored_unknown_channel;
} fsi_bus_counters;

/* Called for every accepted message; 'msg' is the decoded fsi_<type>_t and lives
 * only during the call. */
typedef void (*fsi_bus_handler)(fsi_msg_type type, const void *msg, void *user);

/* Opens the LCM URL (NULL: FSI_DEFAULT_LCM_URL). Returns NULL with a message on
 * failure. 'self' is copied. */
fsi_bus *fsi_bus_open(const char *url, const char *self, int64_t run_id,
                      fsi_bus_handler handler, void *user);

/* Publishes 'msg' (an fsi_<type>_t whose header.window and header.iteration the
 * caller has set); the bus fills in the rest of the header. Returns 0 or -1. */
int fsi_bus_publish(fsi_bus *b, fsi_msg_type type, void *msg);

/* Asks 'target' to publish its kept (type, window, iteration) message again. */
int fsi_bus_request_resend(fsi_bus *b, const char *target, fsi_msg_type type, int window,
                           int iteration);

/* Handles incoming messages for at most timeout_s seconds; returns after the first
 * one handled, or 0 on timeout, -1 on a transport error. */
int fsi_bus_poll(fsi_bus *b, double timeout_s);

/* Handles every message already waiting, without waiting for more; returns how many,
 * or -1 on a transport error. Liveness is judged only after this: when a process
 * was busy (a long window, or a loaded machine that did not schedule it) the
 * heartbeats it missed are queued, not lost. */
int fsi_bus_drain(fsi_bus *b);

/* Starts a background thread publishing heartbeat_t every interval_s seconds with the
 * window and state last set; it stops in fsi_bus_close. */
int fsi_bus_start_heartbeat(fsi_bus *b, double interval_s);
void fsi_bus_set_heartbeat(fsi_bus *b, int window, int state);

fsi_bus_counters fsi_bus_get_counters(fsi_bus *b);
/* Inside the handler: 1 when the message's sequence number is newer than any received
 * from its sender (an original, as far as this process can tell), 0 for a resent copy
 * or a late one. */
int fsi_bus_message_is_new(const fsi_bus *b);
/* Smoothed fraction of other processes' messages this process never received. */
double fsi_bus_measured_loss(fsi_bus *b);
/* Fraction of messages withheld by the test switch (0 when off). */
double fsi_bus_test_drop_fraction(const fsi_bus *b);
const char *fsi_bus_self(const fsi_bus *b);
/* 1 when the bus replays a traffic log (FSI_REPLAY_LOG) instead of using the network. */
int fsi_bus_replaying(const fsi_bus *b);

void fsi_bus_close(fsi_bus *b);

#endif
