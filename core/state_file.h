/* A saved state (core/state_store.h) on disk: one participant's part of a coupled
 * checkpoint (docs/checkpoints.md). The file names the code version and the build's
 * FSI_DIM and ends with a checksum, so a state from another build, or one cut short
 * by a kill, is refused with a message instead of being restored. It is written under
 * a temporary name and renamed into place: it exists only when complete. */
#ifndef FSI_STATE_FILE_H
#define FSI_STATE_FILE_H

#include <stddef.h>

#include "state_store.h"

/* Writes every entry of st to path. 0, or -1 with msg (file and system error). */
int fsi_state_write_file(const fsi_state *st, const char *path, char *msg, size_t msg_size);

/* Reads path into st (cleared first). 0, or -1 with msg: missing, truncated, corrupt,
 * or written by another code version or dimension (named). */
int fsi_state_read_file(fsi_state *st, const char *path, char *msg, size_t msg_size);

#endif
