#include "messages.h"

#include <string.h>

typedef struct {
    int (*encoded_size)(const void *msg);
    int (*encode)(void *buf, int maxlen, const void *msg);
    int (*decode)(const void *buf, int len, void *msg);
    void (*cleanup)(void *msg);
    size_t struct_size;
} msg_codec;

/* Typed lcm-gen functions behind untyped wrappers (calling them through a cast
 * function pointer would be undefined behaviour). */
#define FSI_CODEC(T)                                                                  \
    static int T##_size_any(const void *m) { return fsi_##T##_encoded_size(m); }     \
    static int T##_encode_any(void *b, int n, const void *m)                          \
    {                                                                                 \
        return fsi_##T##_encode(b, 0, n, m);                                          \
    }                                                                                 \
    static int T##_decode_any(const void *b, int n, void *m)                          \
    {                                                                                 \
        return fsi_##T##_decode(b, 0, n, m);                                          \
    }                                                                                 \
    static void T##_cleanup_any(void *m) { fsi_##T##_decode_cleanup(m); }

FSI_CODEC(register_t)
FSI_CODEC(welcome_t)
FSI_CODEC(step_t)
FSI_CODEC(solid_state_t)
FSI_CODEC(fluid_load_t)
FSI_CODEC(done_t)
FSI_CODEC(resend_t)
FSI_CODEC(heartbeat_t)
FSI_CODEC(abort_t)

#define CODEC_ENTRY(T) \
    {T##_size_any, T##_encode_any, T##_decode_any, T##_cleanup_any, sizeof(fsi_##T)}

static const msg_codec codecs[FSI_MSG_COUNT] = {
    [FSI_MSG_REGISTER] = CODEC_ENTRY(register_t),
    [FSI_MSG_WELCOME] = CODEC_ENTRY(welcome_t),
    [FSI_MSG_STEP] = CODEC_ENTRY(step_t),
    [FSI_MSG_SOLID_STATE] = CODEC_ENTRY(solid_state_t),
    [FSI_MSG_FLUID_LOAD] = CODEC_ENTRY(fluid_load_t),
    [FSI_MSG_DONE] = CODEC_ENTRY(done_t),
    [FSI_MSG_RESEND] = CODEC_ENTRY(resend_t),
    [FSI_MSG_HEARTBEAT] = CODEC_ENTRY(heartbeat_t),
    [FSI_MSG_ABORT] = CODEC_ENTRY(abort_t),
};

static int known(fsi_msg_type type)
{
    return type >= 0 && type < FSI_MSG_COUNT;
}

int fsi_message_encoded_size(fsi_msg_type type, const void *msg)
{
    return known(type) ? codecs[type].encoded_size(msg) : -1;
}

size_t fsi_message_struct_size(fsi_msg_type type)
{
    return known(type) ? codecs[type].struct_size : 0;
}

int fsi_message_encode(fsi_msg_type type, const void *msg, void *buf, int len)
{
    return known(type) ? codecs[type].encode(buf, len, msg) : -1;
}

int fsi_message_decode(fsi_msg_type type, const void *buf, int len, fsi_message *out)
{
    memset(out, 0, sizeof *out);
    if (!known(type))
        return -1;
    int used = codecs[type].decode(buf, len, out);
    if (used == len)
        return 0;
    if (used >= 0)
        codecs[type].cleanup(out);
    return -1;
}

void fsi_message_cleanup(fsi_msg_type type, fsi_message *msg)
{
    if (known(type))
        codecs[type].cleanup(msg);
}
