/* Encoding and decoding of every message kind through one table over lcm-gen's
 * functions, for the bus and for tools that read traffic logs. */
#ifndef FSI_MESSAGES_H
#define FSI_MESSAGES_H

#include <stddef.h>

#include "fsi_abort_t.h"
#include "fsi_done_t.h"
#include "fsi_fluid_load_t.h"
#include "fsi_header_t.h"
#include "fsi_heartbeat_t.h"
#include "fsi_register_t.h"
#include "fsi_resend_t.h"
#include "fsi_solid_state_t.h"
#include "fsi_step_t.h"
#include "fsi_welcome_t.h"
#include "protocol.h"

/* Any decoded message; every kind starts with its header. */
typedef union {
    fsi_header_t header;
    fsi_register_t reg;
    fsi_welcome_t welcome;
    fsi_step_t step;
    fsi_solid_state_t solid_state;
    fsi_fluid_load_t fluid_load;
    fsi_done_t done;
    fsi_resend_t resend;
    fsi_heartbeat_t heartbeat;
    fsi_abort_t abort_msg;
} fsi_message;

/* Bytes needed to encode msg (an fsi_<kind>_t), or -1. */
int fsi_message_encoded_size(fsi_msg_type type, const void *msg);
/* sizeof the fsi_<kind>_t of a kind, or 0. */
size_t fsi_message_struct_size(fsi_msg_type type);
/* Encodes into buf[len]; returns the bytes written or -1. */
int fsi_message_encode(fsi_msg_type type, const void *msg, void *buf, int len);
/* Decodes exactly len bytes (type fingerprint and every length checked). Returns 0,
 * or -1 when the bytes are not one whole message of this kind (nothing to clean). */
int fsi_message_decode(fsi_msg_type type, const void *buf, int len, fsi_message *out);
/* Frees what a successful decode allocated. */
void fsi_message_cleanup(fsi_msg_type type, fsi_message *msg);

#endif
