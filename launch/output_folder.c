#include "output_folder.h"

#include <ctype.h>
#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <fnmatch.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "solver_registry.h"

/* Every file a run writes directly in its folder, by name; --force removes these
 * and nothing else. */
static const char *const run_files[] = {
    "case.resolved.ini", "run.log", "probes.csv",     /* fsi run, the coupler */
    "coupling.csv",                                   /* implicit coupling */
    "run.xmf", "run.xmf.tmp",                         /* fsi run: fluid and solid */
    "traffic.lcmlog", "traffic.log",                  /* fsi run --log-traffic */
    "replay.log",                                     /* fsi replay */
    "c1_elastic_plate.png", "c1_elastic_plate.md",    /* fsi main (launch/fsi) */
    "c1_snapshots.png",                               /* fsi main (launch/fsi) */
    "diagnostics.png",                                /* fsi plot, fsi main */
};
/* ... and of each participant P (every role a case may have): P.h5, P.xmf, P.log,
 * the temporaries of their atomic rewrites, P_diagnostics.csv, and the folder
 * P.frames/ of per-frame files. */
static const char *const participant_suffixes[] = {".h5", ".xmf", ".log", ".xmf.tmp",
                                                   ".h5.tmp", "_diagnostics.csv"};
static const char frames_suffix[] = ".frames";

/* 1 when 'name' is a role followed by 'suffix'. */
static int is_role_with(const char *name, const char *suffix)
{
    const fsi_case_schema *schema = fsi_project_schema();
    size_t n = strlen(name), s = strlen(suffix);
    for (int r = 0; r < schema->n_roles; r++) {
        size_t len = strlen(schema->roles[r]);
        if (n == len + s && strncmp(name, schema->roles[r], len) == 0 &&
            strcmp(name + len, suffix) == 0)
            return 1;
    }
    return 0;
}

static int is_run_file(const char *name)
{
    for (size_t i = 0; i < sizeof run_files / sizeof run_files[0]; i++)
        if (strcmp(name, run_files[i]) == 0)
            return 1;
    for (size_t i = 0; i < sizeof participant_suffixes / sizeof participant_suffixes[0]; i++)
        if (is_role_with(name, participant_suffixes[i]))
            return 1;
    return 0;
}

/* The files of a P.frames/ folder (core/h5_output.c): NNNNNN.h5 (one per frame),
 * static.h5, vertices_N.h5 (the connectivity of frames of N points), *.tmp. */
static int is_frame_file(const char *name)
{
    if (strcmp(name, "static.h5") == 0 || fnmatch("*.tmp", name, 0) == 0)
        return 1;
    if (strncmp(name, "vertices_", 9) == 0)
        name += 9;
    const char *p = name;
    while (isdigit((unsigned char)*p))
        p++;
    return p > name && strcmp(p, ".h5") == 0;
}

static int holds_results(const char *dir)
{
    DIR *d = opendir(dir);
    if (!d)
        return 0;
    int found = 0;
    struct dirent *e;
    while (!found && (e = readdir(d)))
        found = is_run_file(e->d_name) || is_role_with(e->d_name, frames_suffix);
    closedir(d);
    return found;
}

static int remove_file(const char *path, const char *command)
{
    if (unlink(path) == 0 || errno == ENOENT)
        return 0;
    fprintf(stderr, "%s: cannot remove the earlier run's %s: %s\n", command, path,
            strerror(errno));
    return -1;
}

/* Removes the frame files of DIR/NAME (a P.frames folder), then the folder when
 * nothing of the user's is left in it. */
static int remove_frames(const char *dir, const char *name, const char *command)
{
    char folder[PATH_MAX], path[PATH_MAX + 256];
    snprintf(folder, sizeof folder, "%s/%s", dir, name);
    DIR *d = opendir(folder);
    if (!d)
        return remove_file(folder, command);   /* a file of that name */
    int rc = 0;
    struct dirent *e;
    while ((e = readdir(d)))
        if (is_frame_file(e->d_name)) {
            snprintf(path, sizeof path, "%s/%s", folder, e->d_name);
            rc |= remove_file(path, command);
        }
    closedir(d);
    if (rmdir(folder) != 0 && errno != ENOTEMPTY && errno != EEXIST) {
        fprintf(stderr, "%s: cannot remove the earlier run's %s: %s\n", command, folder,
                strerror(errno));
        rc = -1;
    }
    return rc;
}

/* OUT/checkpoints/: its window_K/ folders and what they hold (docs/checkpoints.md). */
static int remove_checkpoints(const char *dir, const char *command)
{
    DIR *d = opendir(dir);
    if (!d)
        return 0;
    int rc = 0;
    char path[PATH_MAX + 512];
    struct dirent *e;
    while ((e = readdir(d))) {
        if (strncmp(e->d_name, "window_", 7) != 0)
            continue;
        snprintf(path, sizeof path, "%s/%s", dir, e->d_name);
        DIR *w = opendir(path);
        struct dirent *f;
        char file[PATH_MAX + 1024];
        while (w && (f = readdir(w)))
            if (f->d_name[0] != '.') {
                snprintf(file, sizeof file, "%s/%s", path, f->d_name);
                rc |= remove_file(file, command);
            }
        if (w)
            closedir(w);
        rmdir(path);
    }
    closedir(d);
    rmdir(dir);
    return rc;
}

static int remove_results(const char *dir, const char *command)
{
    DIR *d = opendir(dir);
    if (!d)
        return 0;
    int rc = 0;
    char path[PATH_MAX + 256];
    struct dirent *e;
    while ((e = readdir(d))) {
        snprintf(path, sizeof path, "%s/%s", dir, e->d_name);
        if (is_run_file(e->d_name))
            rc |= remove_file(path, command);
        else if (is_role_with(e->d_name, frames_suffix))
            rc |= remove_frames(dir, e->d_name, command);
        else if (strcmp(e->d_name, "checkpoints") == 0)
            rc |= remove_checkpoints(path, command);
    }
    closedir(d);
    return rc;
}

static int refuse_earlier_results(const char *dir, const char *command)
{
    if (!holds_results(dir))
        return 0;
    fprintf(stderr, "%s: %s holds results of an earlier run; use --force to replace them "
                    "or --out to choose another folder\n", command, dir);
    return -1;
}

/* The pid the holder of the lock wrote; 0 if it has not yet (it writes it right
 * after taking the lock, so this waits a little for it). */
static long holder_pid(int fd)
{
    for (int attempt = 0; attempt < 40; attempt++) {
        char text[32] = "";
        ssize_t n = pread(fd, text, sizeof text - 1, 0);
        long pid = n > 0 ? strtol(text, NULL, 10) : 0;
        if (pid > 0)
            return pid;
        nanosleep(&(struct timespec){0, 25 * 1000 * 1000}, NULL);
    }
    return 0;
}

#define LOCK_ABSENT (-2)

/* Opens and locks DIR's lock file (creating it when 'create'). Returns its
 * descriptor, LOCK_ABSENT when it does not exist and !create, or -1 with a message
 * (another run holds it, or it cannot be opened). */
static int take_lock(const char *dir, int create, const char *command)
{
    char path[PATH_MAX + 32];
    snprintf(path, sizeof path, "%s/%s", dir, FSI_OUTPUT_LOCK);
    int fd = open(path, O_RDWR | O_CLOEXEC | (create ? O_CREAT : 0), 0644);
    if (fd < 0) {
        if (!create && errno == ENOENT)
            return LOCK_ABSENT;
        fprintf(stderr, "%s: cannot open the lock file %s: %s\n", command, path,
                strerror(errno));
        return -1;
    }
    if (flock(fd, LOCK_EX | LOCK_NB) != 0) {
        int busy = errno == EWOULDBLOCK;
        if (busy) {
            long pid = holder_pid(fd);
            char who[32] = "unknown";
            if (pid > 0)
                snprintf(who, sizeof who, "%ld", pid);
            fprintf(stderr, "%s: %s is in use by another run (pid %s); wait for it to end or "
                            "choose another folder with --out\n", command, dir, who);
        } else {
            fprintf(stderr, "%s: cannot lock %s: %s\n", command, path, strerror(errno));
        }
        close(fd);
        return -1;
    }
    return fd;
}

static void write_pid(int fd)
{
    char text[32];
    int n = snprintf(text, sizeof text, "%ld\n", (long)getpid());
    if (ftruncate(fd, 0) != 0 || pwrite(fd, text, (size_t)n, 0) != n)
        return;   /* a second run then names the holder "pid unknown" */
}

/* Creates a folder and its parents. Returns 0 or -1 (errno set). */
static int make_dirs(const char *path)
{
    char buf[PATH_MAX];
    snprintf(buf, sizeof buf, "%s", path);
    for (char *p = buf + 1; *p; p++)
        if (*p == '/') {
            *p = '\0';
            if (mkdir(buf, 0755) != 0 && errno != EEXIST)
                return -1;
            *p = '/';
        }
    return mkdir(buf, 0755) != 0 && errno != EEXIST ? -1 : 0;
}

int fsi_claim_output_dir(const char *dir, int force, const char *command)
{
    struct stat st;
    int exists = stat(dir, &st) == 0;
    if (!exists && errno != ENOENT) {
        fprintf(stderr, "%s: cannot use %s as the output folder: %s\n", command, dir,
                strerror(errno));
        return -1;
    }
    if (exists && (!S_ISDIR(st.st_mode) || access(dir, R_OK | W_OK | X_OK) != 0)) {
        fprintf(stderr, "%s: cannot use %s as the output folder: %s\n", command, dir,
                strerror(S_ISDIR(st.st_mode) ? errno : ENOTDIR));
        return -1;
    }
    int fd = LOCK_ABSENT;
    if (exists) {
        /* A run going in DIR is named before its results are taken for an earlier
         * run's. */
        fd = take_lock(dir, 0, command);
        if (fd == -1)
            return -1;
        if (force == FSI_CLAIM_REFUSE && refuse_earlier_results(dir, command) != 0)
            goto refused;
    } else if (make_dirs(dir) != 0) {
        fprintf(stderr, "%s: cannot create the output folder %s: %s\n", command, dir,
                strerror(errno));
        return -1;
    }
    if (fd == LOCK_ABSENT) {
        fd = take_lock(dir, 1, command);
        if (fd < 0)
            return -1;
        /* Checked again under the lock: a run may have come and gone meanwhile. */
        if (force == FSI_CLAIM_REFUSE && refuse_earlier_results(dir, command) != 0)
            goto refused;
    }
    if (force == FSI_CLAIM_REPLACE && remove_results(dir, command) != 0)
        goto refused;
    write_pid(fd);
    return fd;

refused:
    if (fd >= 0)
        close(fd);
    return -1;
}
