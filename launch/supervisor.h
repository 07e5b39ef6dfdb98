/* Starts the processes of a run and watches them: when one fails, the others are
 * stopped and the failure is named. */
#ifndef FSI_SUPERVISOR_H
#define FSI_SUPERVISOR_H

#include <sys/types.h>

#define FSI_MAX_CHILDREN 8

typedef struct {
    char name[64];          /* "coupler", "fluid", "solid", "lcm-logger" */
    char program[4096];
    pid_t pid;
    int running;
    int status;             /* waitpid status once it ended */
    int is_coupler;
    int is_helper;          /* a side process (traffic logger) that never decides the outcome */
} fsi_child;

typedef struct {
    fsi_child child[FSI_MAX_CHILDREN];
    int n;
    double started;
    char failure[2048];     /* why the run failed, empty on success */
} fsi_supervisor;

/* Starts program with the extra environment "NAME=value" strings (NULL-terminated);
 * stdout/stderr go to log_path, or stay on the terminal when it is NULL. The kernel
 * kills it (SIGKILL) when the calling process dies. */
int fsi_supervisor_start(fsi_supervisor *s, const char *name, const char *program,
                         char *const argv[], char *const extra_env[], const char *log_path,
                         int is_coupler, int is_helper);

/* Waits until the run ends: the coupler and every participant exited, or one of them
 * failed (then the rest are stopped). Returns 0 on success, 1 on failure with the
 * reason in s->failure: the process that failed, or the coupler when a participant
 * left because it was silent (FSI_EXIT_COUPLER_SILENT). 'interrupted' is polled to
 * stop early on Ctrl-C, SIGTERM or SIGHUP. */
int fsi_supervisor_wait(fsi_supervisor *s, volatile int *interrupted);

/* Makes SIGINT, SIGTERM and SIGHUP set *flag to the signal's number: the
 * 'interrupted' of fsi_supervisor_wait, which then stops the run in order. */
void fsi_supervisor_catch_signals(volatile int *flag);

/* Stops the helper processes (SIGINT, then SIGKILL after a grace period). */
void fsi_supervisor_stop_helpers(fsi_supervisor *s);

#endif
