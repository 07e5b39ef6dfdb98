#include "protocol.h"

#include <string.h>

static const char *const channels[FSI_MSG_COUNT] = {
    [FSI_MSG_REGISTER] = "FSI_REGISTER",
    [FSI_MSG_WELCOME] = "FSI_WELCOME",
    [FSI_MSG_STEP] = "FSI_STEP",
    [FSI_MSG_SOLID_STATE] = "FSI_SOLID_STATE",
    [FSI_MSG_FLUID_LOAD] = "FSI_FLUID_LOAD",
    [FSI_MSG_DONE] = "FSI_DONE",
    [FSI_MSG_RESEND] = "FSI_RESEND",
    [FSI_MSG_HEARTBEAT] = "FSI_HEARTBEAT",
    [FSI_MSG_ABORT] = "FSI_ABORT",
};

static const char *const names[FSI_MSG_COUNT] = {
    [FSI_MSG_REGISTER] = "register",
    [FSI_MSG_WELCOME] = "welcome",
    [FSI_MSG_STEP] = "step",
    [FSI_MSG_SOLID_STATE] = "solid_state",
    [FSI_MSG_FLUID_LOAD] = "fluid_load",
    [FSI_MSG_DONE] = "done",
    [FSI_MSG_RESEND] = "resend",
    [FSI_MSG_HEARTBEAT] = "heartbeat",
    [FSI_MSG_ABORT] = "abort",
};

const char *fsi_msg_channel(fsi_msg_type type)
{
    return (type >= 0 && type < FSI_MSG_COUNT) ? channels[type] : "FSI_UNKNOWN";
}

const char *fsi_msg_name(fsi_msg_type type)
{
    return (type >= 0 && type < FSI_MSG_COUNT) ? names[type] : "unknown";
}

int fsi_msg_type_of_channel(const char *channel)
{
    for (int t = 0; t < FSI_MSG_COUNT; t++)
        if (strcmp(channel, channels[t]) == 0)
            return t;
    return -1;
}
