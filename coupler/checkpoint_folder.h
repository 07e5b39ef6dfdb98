/* The coupled checkpoints of a run (docs/checkpoints.md): OUT/checkpoints/window_K/
 * holds each participant's NAME.state and NAME.library.state and the coupler's
 * coupler.state, and, written last, COMPLETE: the code version, the window, its time
 * and the output frames written before it. A folder without COMPLETE (a run killed
 * while writing it) is not a checkpoint. */
#ifndef FSI_CHECKPOINT_FOLDER_H
#define FSI_CHECKPOINT_FOLDER_H

#include <stddef.h>

typedef struct {
    char dir[4300];     /* OUT/checkpoints/window_K */
    int window;         /* K: the run goes on with window K */
    double time;        /* its start [s] */
    int frames;         /* output frames 0 .. frames - 1 were written before it */
    char version[128];  /* FSI_VERSION of the code that wrote it */
} fsi_checkpoint_info;

/* OUT/checkpoints/window_K into out. */
void fsi_checkpoint_dir(const char *out_dir, int window, char *out, size_t size);

/* Marks the checkpoint of window K complete (writes COMPLETE, then removes the
 * complete checkpoints older than the newest 'keep'). 0, or -1 with msg. */
int fsi_checkpoint_complete(const char *out_dir, int window, double time, int frames,
                            int keep, char *msg, size_t msg_size);

/* The newest complete checkpoint of the run in out_dir. 0, or -1 with msg when there is
 * none or its COMPLETE cannot be read. The version is not checked here. */
int fsi_checkpoint_latest(const char *out_dir, fsi_checkpoint_info *info, char *msg,
                          size_t msg_size);

#endif
