/* Helpers of the tests that replay a hand-made traffic log (test_bus_replay.c,
 * test_participant_interface.c): writing one message as the recorder does, and
 * reading a replay's report. Header-only: every test is one executable. */
#ifndef FSI_UNIT_TRAFFIC_LOG_H
#define FSI_UNIT_TRAFFIC_LOG_H

#include <lcm/eventlog.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "messages.h"

/* Sets the header of msg (any message: the header comes first) as the bus would for
 * sender in run run_id. */
static inline void unit_set_header(void *msg, const char *sender, int64_t run_id, int window,
                                   int64_t seq)
{
    fsi_header_t *h = msg;
    h->protocol_version = FSI_PROTOCOL_VERSION;
    h->run_id = run_id;
    h->window = window;
    h->seq = seq;
    h->sender = (char *)sender;
}

/* Appends msg, of kind type, to log with its header set as sender's in run run_id. */
static inline void unit_log_put(lcm_eventlog_t *log, fsi_msg_type type, void *msg,
                                const char *sender, int64_t run_id, int window, int64_t seq)
{
    unit_set_header(msg, sender, run_id, window, seq);
    int len = fsi_message_encoded_size(type, msg);
    char *bytes = malloc((size_t)len);
    fsi_message_encode(type, msg, bytes, len);
    lcm_eventlog_event_t e = {0};
    e.channel = (char *)fsi_msg_channel(type);
    e.channellen = (int32_t)strlen(e.channel);
    e.data = bytes;
    e.datalen = len;
    lcm_eventlog_write_event(log, &e);
    free(bytes);
}

/* A solid state of n particles over the given arrays (vectors n * FSI_DIM). */
static inline fsi_solid_state_t unit_solid_state(int n, int32_t *id, double *x, double *v,
                                                 double *a, double *volume, double *density)
{
    fsi_solid_state_t m = {0};
    m.dim = FSI_DIM;
    m.n = n;
    m.n_components = n * FSI_DIM;
    m.id = id;
    m.position = x;
    m.velocity = v;
    m.acceleration = a;
    m.volume = volume;
    m.density = density;
    return m;
}

/* The text of the file at path (a replay's report) into text[len]; "" if unreadable. */
static inline void unit_read_text(const char *path, char *text, size_t len)
{
    FILE *f = fopen(path, "r");
    size_t n = f ? fread(text, 1, len - 1, f) : 0;
    text[n] = '\0';
    if (f)
        fclose(f);
}

#endif
