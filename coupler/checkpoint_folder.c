#include "checkpoint_folder.h"

#include <dirent.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

void fsi_checkpoint_dir(const char *out_dir, int window, char *out, size_t size)
{
    snprintf(out, size, "%s/checkpoints/window_%08d", out_dir, window);
}

static int read_complete(const char *dir, fsi_checkpoint_info *info)
{
    char path[4300];
    if (snprintf(path, sizeof path, "%s/COMPLETE", dir) >= (int)sizeof path)
        return -1;
    FILE *f = fopen(path, "r");
    if (!f)
        return -1;
    int got = fscanf(f, "version = %127s\nwindow = %d\ntime = %lf\nframes = %d", info->version,
                     &info->window, &info->time, &info->frames);
    fclose(f);
    if (snprintf(info->dir, sizeof info->dir, "%s", dir) >= (int)sizeof info->dir)
        return -1;
    return got == 4 ? 0 : -1;
}

/* Window numbers of the folders under OUT/checkpoints holding a COMPLETE, ascending.
 * Returns how many (at most max). */
static int complete_windows(const char *out_dir, int *windows, int max)
{
    char base[4200];
    snprintf(base, sizeof base, "%s/checkpoints", out_dir);
    DIR *d = opendir(base);
    if (!d)
        return 0;
    int n = 0;
    struct dirent *e;
    while ((e = readdir(d)) && n < max) {
        int k;
        char tail;
        if (sscanf(e->d_name, "window_%d%c", &k, &tail) != 1)
            continue;
        char dir[4300];
        fsi_checkpoint_info info;
        fsi_checkpoint_dir(out_dir, k, dir, sizeof dir);
        if (read_complete(dir, &info) == 0)
            windows[n++] = k;
    }
    closedir(d);
    for (int i = 1; i < n; i++)     /* a few entries: insertion sort */
        for (int j = i; j > 0 && windows[j - 1] > windows[j]; j--) {
            const int t = windows[j];
            windows[j] = windows[j - 1];
            windows[j - 1] = t;
        }
    return n;
}

static void remove_folder(const char *dir)
{
    DIR *d = opendir(dir);
    if (!d)
        return;
    struct dirent *e;
    char path[4400];
    while ((e = readdir(d)))
        if (strcmp(e->d_name, ".") != 0 && strcmp(e->d_name, "..") != 0) {
            if (snprintf(path, sizeof path, "%s/%s", dir, e->d_name) < (int)sizeof path)
                unlink(path);
        }
    closedir(d);
    rmdir(dir);
}

int fsi_checkpoint_complete(const char *out_dir, int window, double time, int frames,
                            int keep, char *msg, size_t msg_size)
{
    char dir[4300], path[4400], tmp[4420];
    fsi_checkpoint_dir(out_dir, window, dir, sizeof dir);
    snprintf(path, sizeof path, "%s/COMPLETE", dir);
    snprintf(tmp, sizeof tmp, "%s.tmp", path);
    FILE *f = fopen(tmp, "w");
    int err = f ? 0 : errno;
    if (f) {
        fprintf(f, "version = %s\nwindow = %d\ntime = %.17g\nframes = %d\n", FSI_VERSION, window,
                time, frames);
        if (fclose(f) != 0)
            err = errno;
    }
    if (!err && rename(tmp, path) != 0)
        err = errno;
    if (err) {
        snprintf(msg, msg_size, "cannot write %s: %s", path, strerror(err));
        return -1;
    }
    enum { MAX = 4096 };
    static int windows[MAX];
    const int n = complete_windows(out_dir, windows, MAX);
    for (int i = 0; i + keep < n; i++) {
        fsi_checkpoint_dir(out_dir, windows[i], dir, sizeof dir);
        remove_folder(dir);
    }
    return 0;
}

int fsi_checkpoint_latest(const char *out_dir, fsi_checkpoint_info *info, char *msg,
                          size_t msg_size)
{
    enum { MAX = 4096 };
    static int windows[MAX];
    const int n = complete_windows(out_dir, windows, MAX);
    if (n == 0) {
        snprintf(msg, msg_size, "%s/checkpoints holds no complete checkpoint (was the run "
                 "started with --checkpoint-interval, and did it reach the first one?)",
                 out_dir);
        return -1;
    }
    char dir[4300];
    fsi_checkpoint_dir(out_dir, windows[n - 1], dir, sizeof dir);
    if (read_complete(dir, info) != 0) {
        snprintf(msg, msg_size, "cannot read %s/COMPLETE", dir);
        return -1;
    }
    return 0;
}
