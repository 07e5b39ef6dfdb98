#include "replay_compare.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "messages.h"

/* Takes over from the recording what may differ between two runs of the same
 * computation, so that the encoded bytes compare everything else. */
static void take_machine_fields(fsi_msg_type type, fsi_message *mine, const fsi_message *rec)
{
    mine->header.seq = rec->header.seq;
    if (type == FSI_MSG_REGISTER) {
        mine->reg.pid = rec->reg.pid;
        mine->reg.host = rec->reg.host;
    } else if (type == FSI_MSG_DONE && mine->done.status == FSI_STATUS_FINISHED &&
               rec->done.status == FSI_STATUS_FINISHED) {
        mine->done.n_stats = rec->done.n_stats;
        mine->done.stat_names = rec->done.stat_names;
        mine->done.stat_values = rec->done.stat_values;
    }
}

/* Bitwise, so that a NaN equals the same NaN and -0.0 differs from 0.0, as the bytes do. */
static int first_real_difference(const char *name, const double *a, const double *b, int n,
                                 char *why, size_t len)
{
    for (int i = 0; i < n; i++)
        if (memcmp(&a[i], &b[i], sizeof a[i]) != 0) {
            snprintf(why, len, "%s[%d] = %.17g, recorded %.17g", name, i, a[i], b[i]);
            return 1;
        }
    return 0;
}

static int first_id_difference(const int32_t *a, const int32_t *b, int n, char *why, size_t len)
{
    for (int i = 0; i < n; i++)
        if (a[i] != b[i]) {
            snprintf(why, len, "id[%d] = %d, recorded %d", i, (int)a[i], (int)b[i]);
            return 1;
        }
    return 0;
}

static int count_difference(const char *name, int a, int b, char *why, size_t len)
{
    if (a == b)
        return 0;
    snprintf(why, len, "%s = %d, recorded %d", name, a, b);
    return 1;
}

/* The first field that differs, for the kinds whose values a solver computes. */
static int describe_fields(fsi_msg_type type, const fsi_message *a, const fsi_message *b,
                           char *why, size_t len)
{
    if (type == FSI_MSG_SOLID_STATE) {
        const fsi_solid_state_t *x = &a->solid_state, *y = &b->solid_state;
        return count_difference("n", x->n, y->n, why, len) ||
               first_id_difference(x->id, y->id, x->n, why, len) ||
               first_real_difference("position", x->position, y->position, x->n_components,
                                     why, len) ||
               first_real_difference("velocity", x->velocity, y->velocity, x->n_components,
                                     why, len) ||
               first_real_difference("acceleration", x->acceleration, y->acceleration,
                                     x->n_components, why, len) ||
               first_real_difference("volume", x->volume, y->volume, x->n, why, len) ||
               first_real_difference("density", x->density, y->density, x->n, why, len);
    }
    if (type == FSI_MSG_FLUID_LOAD) {
        const fsi_fluid_load_t *x = &a->fluid_load, *y = &b->fluid_load;
        return count_difference("n", x->n, y->n, why, len) ||
               first_id_difference(x->id, y->id, x->n, why, len) ||
               first_real_difference("pressure", x->pressure, y->pressure, x->n, why, len) ||
               first_real_difference("force", x->force, y->force, x->n_components, why, len);
    }
    if (type == FSI_MSG_DONE) {
        const fsi_done_t *x = &a->done, *y = &b->done;
        return count_difference("status", x->status, y->status, why, len) ||
               first_real_difference("dt_next_max", &x->dt_next_max, &y->dt_next_max, 1, why,
                                     len) ||
               count_difference("n_probes", x->n_probes, y->n_probes, why, len) ||
               first_real_difference("probe_values", x->probe_values, y->probe_values,
                                     x->n_probes, why, len);
    }
    return 0;
}

int fsi_replay_same(fsi_msg_type type, const void *mine, const void *recorded, int recorded_len,
                    char *why, size_t why_len)
{
    fsi_message rec, copy;
    if (fsi_message_decode(type, recorded, recorded_len, &rec) != 0) {
        snprintf(why, why_len, "the recorded message does not decode");
        return 0;
    }
    memset(&copy, 0, sizeof copy);
    memcpy(&copy, mine, fsi_message_struct_size(type));
    take_machine_fields(type, &copy, &rec);
    int len = fsi_message_encoded_size(type, &copy);
    char *bytes = len > 0 ? malloc((size_t)len) : NULL;
    int same = 0;
    if (!bytes || fsi_message_encode(type, &copy, bytes, len) != len) {
        snprintf(why, why_len, "cannot encode the message");
    } else if (len == recorded_len && memcmp(bytes, recorded, (size_t)len) == 0) {
        same = 1;
    } else if (!describe_fields(type, &copy, &rec, why, why_len)) {
        int at = 0;
        while (at < len && at < recorded_len && bytes[at] == ((const char *)recorded)[at])
            at++;
        snprintf(why, why_len, "%d bytes, recorded %d; first difference at byte %d", len,
                 recorded_len, at);
    }
    free(bytes);
    fsi_message_cleanup(type, &rec);
    return same;
}
