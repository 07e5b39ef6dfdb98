/* Compares a message a replayed participant publishes with the recorded one
 * (core/bus_replay.h): byte for byte, after copying over from the recording the
 * fields that describe the machine and the moment rather than the computation. */
#ifndef FSI_REPLAY_COMPARE_H
#define FSI_REPLAY_COMPARE_H

#include <stddef.h>

#include "protocol.h"

/* 'mine' is an fsi_<kind>_t with its header filled in; 'recorded' the encoded bytes
 * of the recorded message of the same kind. Returns 1 when they are the same,
 * 0 with the first difference described in 'why' (e.g. "force[13] = 0.25,
 * recorded 0.5"). Not compared: header seq (it counts heartbeats and resend
 * requests, which depend on timing), register pid and host, and the timers and
 * counters of the final done. */
int fsi_replay_same(fsi_msg_type type, const void *mine, const void *recorded, int recorded_len,
                    char *why, size_t why_len);

#endif
