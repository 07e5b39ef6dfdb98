/* Replay transport of the bus (docs/protocol.md, "Replay"): one participant runs
 * against a traffic log recorded by `fsi run --log-traffic`, with no network.
 *
 * - Receiving: the recorded messages for this participant (its welcome, the steps,
 *   the other side's interface data, aborts, the coupler's "finished" heartbeat)
 *   come in recorded order, but only up to this participant's next own recorded
 *   message that it has not published again yet: what was recorded after its
 *   message X it gets only after publishing X. That keeps lockstep without a clock.
 * - Publishing: every register, interface, done and abort message is compared with
 *   the recorded one of the same kind, window and iteration (repeats and resent
 *   copies are skipped on both sides), byte for byte except the fields that
 *   measure the machine rather than the computation (header seq, register pid and
 *   host, the final done's timers and counters). A message whose original was lost
 *   in the recorded run is recorded late, as its resent copy: it is compared when
 *   the log reaches that copy.
 *
 * Used by core/bus.c when FSI_REPLAY_LOG is set; the bus holds its lock around
 * every call, so the heartbeat thread may publish while the main thread polls. */
#ifndef FSI_BUS_REPLAY_H
#define FSI_BUS_REPLAY_H

#include <stdint.h>

#include "protocol.h"

typedef struct fsi_replay fsi_replay;

/* Opens the recording of participant 'self' in run 'run_id'. Returns NULL with a
 * message when the log cannot be read or holds no message of 'self' in that run. */
fsi_replay *fsi_replay_open(const char *log_path, const char *self, int64_t run_id);

/* The next recorded message due for this participant: returns 1 with its kind and
 * encoded bytes (valid until the next call), or 0 when nothing is due before this
 * participant publishes its next recorded message. A participant that is 'waiting'
 * (blocked until a message comes) with nothing due also gets an input of that next
 * message's window logged after it: the recorder logs datagrams of different senders
 * in the order they reached it, not in the order they were sent. */
int fsi_replay_next_input(fsi_replay *r, int waiting, fsi_msg_type *type, const void **bytes,
                          int *len);

/* Compares a message this participant publishes (an fsi_<kind>_t with its header
 * filled in) with the recording; kinds that only keep the bus alive are skipped. */
void fsi_replay_compare(fsi_replay *r, fsi_msg_type type, const void *msg);

/* Says why a participant that waits for a message will never get one. */
void fsi_replay_explain_wait(const fsi_replay *r, int window);

/* Recorded own messages never published count as differences too. Writes the
 * summary to stderr and, when FSI_REPLAY_REPORT names a file, to that file (once),
 * and returns the number of differences. */
long fsi_replay_finish(fsi_replay *r);

/* Frees the replay (call fsi_replay_finish first to get a report). */
void fsi_replay_free(fsi_replay *r);

#endif
