#define _GNU_SOURCE
#include "supervisor.h"

#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "log.h"
#include "timers.h"

/* After the coupler ends, participants get this long to leave on their own. */
#define PARTICIPANT_EXIT_GRACE_S 10.0
/* Processes asked to stop get this long before SIGKILL. */
#define STOP_GRACE_S 2.0
/* After a process stopped because another aborted the run, the culprit gets this
 * long to end on its own so that it, not the first to leave, is named. */
#define CULPRIT_GRACE_S 2.0

int fsi_supervisor_start(fsi_supervisor *s, const char *name, const char *program,
                         char *const argv[], char *const extra_env[], const char *log_path,
                         int is_coupler, int is_helper)
{
    if (s->n == FSI_MAX_CHILDREN)
        return -1;
    if (s->n == 0)
        s->started = fsi_wall_seconds();
    fflush(NULL);
    pid_t parent = getpid();
    pid_t pid = fork();
    if (pid < 0) {
        fsi_error("cannot start %s: %s", name, strerror(errno));
        return -1;
    }
    if (pid == 0) {
        /* No process of a run outlives its supervisor (kill -9 of fsi run): the
         * kernel kills this one when the supervisor dies, and if it died before the
         * request was made, the parent is no longer the one that forked. */
        if (prctl(PR_SET_PDEATHSIG, SIGKILL) != 0 || getppid() != parent)
            _exit(FSI_EXIT_RUN_FAILURE);
        for (int i = 0; extra_env && extra_env[i]; i++)
            putenv(extra_env[i]);
        if (log_path) {
            /* A restarted run (FSI_RESTART_DIR) goes on with the logs of its start. */
            const char *restart = getenv("FSI_RESTART_DIR");
            int fd = open(log_path, O_WRONLY | O_CREAT | (restart && *restart ? O_APPEND : O_TRUNC),
                          0644);
            if (fd >= 0) {
                dup2(fd, STDOUT_FILENO);
                dup2(fd, STDERR_FILENO);
                close(fd);
            }
        }
        int devnull = open("/dev/null", O_RDONLY);
        if (devnull >= 0)
            dup2(devnull, STDIN_FILENO);
        execv(program, argv);
        fprintf(stderr, "cannot execute %s: %s\n", program, strerror(errno));
        _exit(127);
    }
    fsi_child *c = &s->child[s->n++];
    snprintf(c->name, sizeof c->name, "%s", name);
    snprintf(c->program, sizeof c->program, "%s", program);
    c->pid = pid;
    c->running = 1;
    c->is_coupler = is_coupler;
    c->is_helper = is_helper;
    return 0;
}

static void describe_end(const fsi_child *c, char *buf, size_t len)
{
    if (WIFSIGNALED(c->status)) {
        int sig = WTERMSIG(c->status);
        snprintf(buf, len, "was killed by signal %d (%s)", sig, strsignal(sig));
    } else if (WIFEXITED(c->status)) {
        int code = WEXITSTATUS(c->status);
        snprintf(buf, len, code == 127 ? "could not be executed (status 127)"
                                       : "exited with status %d",
                 code);
    } else {
        snprintf(buf, len, "ended in an unknown way");
    }
}

static int ended_well(const fsi_child *c)
{
    return WIFEXITED(c->status) && WEXITSTATUS(c->status) == 0;
}

static int stopped_by_peer(const fsi_child *c)
{
    return WIFEXITED(c->status) && WEXITSTATUS(c->status) == FSI_EXIT_STOPPED_BY_PEER;
}

/* What /proc/PID/stat says of a process: "T: stopped", "R: running", ... */
static void process_state(pid_t pid, char *buf, size_t len)
{
    char path[64], line[1024] = "";
    snprintf(path, sizeof path, "/proc/%d/stat", (int)pid);
    FILE *f = fopen(path, "r");
    if (f) {
        if (!fgets(line, sizeof line, f))
            line[0] = '\0';
        fclose(f);
    }
    /* "pid (comm) S ...": the state follows the last ')', comm may hold any byte */
    const char *paren = strrchr(line, ')');
    char state = paren && paren[1] == ' ' ? paren[2] : '?';
    const char *text = state == 'T'   ? "stopped"
                       : state == 't' ? "stopped by a debugger"
                       : state == 'R' ? "running"
                       : state == 'S' ? "sleeping"
                       : state == 'D' ? "in uninterruptible wait"
                                      : "state unknown";
    snprintf(buf, len, "%c: %s", state, text);
}

static const fsi_child *find_coupler(const fsi_supervisor *s)
{
    for (int i = 0; i < s->n; i++)
        if (s->child[i].is_coupler)
            return &s->child[i];
    return NULL;
}

/* A participant left because it heard nothing from the coupler: the coupler is
 * named, with the state the kernel gives it (a SIGSTOPped one is alive but silent). */
static void describe_silent_coupler(fsi_supervisor *s, const fsi_child *c, double now)
{
    const fsi_child *coupler = find_coupler(s);
    char state[64];
    if (coupler && coupler->running) {
        process_state(coupler->pid, state, sizeof state);
        snprintf(s->failure, sizeof s->failure,
                 "the coupler (pid %d) stopped answering (state %s): participant '%s' "
                 "(pid %d) heard nothing from it for its watchdog timeout and left after "
                 "%.1f s", (int)coupler->pid, state, c->name, (int)c->pid, now - s->started);
    } else {
        snprintf(s->failure, sizeof s->failure,
                 "participant '%s' (pid %d) heard nothing from the coupler, which had "
                 "already ended, for its watchdog timeout and left after %.1f s",
                 c->name, (int)c->pid, now - s->started);
    }
}

static void describe_failure(fsi_supervisor *s, const fsi_child *c, double now)
{
    char how[256];
    describe_end(c, how, sizeof how);
    if (stopped_by_peer(c))
        snprintf(how, sizeof how, "stopped because the run was aborted");
    if (!c->is_coupler && WIFEXITED(c->status) &&
        WEXITSTATUS(c->status) == FSI_EXIT_COUPLER_SILENT)
        describe_silent_coupler(s, c, now);
    else if (c->is_coupler)
        snprintf(s->failure, sizeof s->failure, "the coupler (pid %d) %s after %.1f s",
                 (int)c->pid, how, now - s->started);
    else
        snprintf(s->failure, sizeof s->failure, "participant '%s' (pid %d) %s after %.1f s",
                 c->name, (int)c->pid, how, now - s->started);
}

static void signal_running(fsi_supervisor *s, int sig, int helpers)
{
    for (int i = 0; i < s->n; i++)
        if (s->child[i].running && s->child[i].is_helper == helpers) {
            kill(s->child[i].pid, sig);
            if (sig == SIGTERM)
                kill(s->child[i].pid, SIGCONT);   /* a stopped process must wake to die */
        }
}

/* Reaps every child that has ended; returns how many are still running (helpers
 * excluded). */
static int reap(fsi_supervisor *s, fsi_child **ended)
{
    int status;
    pid_t pid;
    *ended = NULL;
    while ((pid = waitpid(-1, &status, WNOHANG)) > 0) {
        for (int i = 0; i < s->n; i++)
            if (s->child[i].pid == pid && s->child[i].running) {
                s->child[i].running = 0;
                s->child[i].status = status;
                if (!s->child[i].is_helper && !*ended)
                    *ended = &s->child[i];
            }
        if (*ended)
            break;
    }
    int running = 0;
    for (int i = 0; i < s->n; i++)
        running += s->child[i].running && !s->child[i].is_helper;
    return running;
}

static void nap(void)
{
    struct timespec ts = {0, 10 * 1000 * 1000};
    nanosleep(&ts, NULL);
}

/* Asks every remaining process to stop, then kills what is left. */
static void stop_all(fsi_supervisor *s)
{
    fsi_child *ended;
    signal_running(s, SIGTERM, 0);
    double deadline = fsi_wall_seconds() + STOP_GRACE_S;
    while (reap(s, &ended) > 0 && fsi_wall_seconds() < deadline)
        nap();
    signal_running(s, SIGKILL, 0);
    while (reap(s, &ended) > 0)
        nap();
}

static void describe_stop_signal(fsi_supervisor *s, int sig, double now)
{
    double after = now - s->started;
    if (sig == SIGINT)
        snprintf(s->failure, sizeof s->failure, "interrupted by the user (SIGINT) after %.1f s",
                 after);
    else if (sig == SIGHUP)
        snprintf(s->failure, sizeof s->failure,
                 "stopped by SIGHUP (hang-up: its terminal closed) after %.1f s", after);
    else
        snprintf(s->failure, sizeof s->failure, "stopped by signal %d (%s) after %.1f s", sig,
                 strsignal(sig), after);
}

int fsi_supervisor_wait(fsi_supervisor *s, volatile int *interrupted)
{
    double coupler_ended = -1.0;
    const fsi_child *first_stopped = NULL;    /* left because someone else aborted */
    double first_stopped_at = 0.0;
    for (;;) {
        fsi_child *c;
        int running = reap(s, &c);
        double now = fsi_wall_seconds();
        /* Before what ended is judged: Ctrl-C or a closed terminal signals the
         * whole process group, and the participants it killed are not the cause. */
        if (interrupted && *interrupted) {
            describe_stop_signal(s, *interrupted, now);
            stop_all(s);
            return 1;
        }
        if (c) {
            if (stopped_by_peer(c)) {
                if (!first_stopped) {
                    first_stopped = c;
                    first_stopped_at = now;
                }
                continue;
            }
            if (!ended_well(c)) {
                describe_failure(s, c, now);
                stop_all(s);
                return 1;
            }
            if (c->is_coupler)
                coupler_ended = now;
            continue;
        }
        if (first_stopped && (running == 0 || now - first_stopped_at > CULPRIT_GRACE_S)) {
            describe_failure(s, first_stopped, first_stopped_at);
            stop_all(s);
            return 1;
        }
        if (running == 0)
            return 0;
        if (coupler_ended >= 0 && now - coupler_ended > PARTICIPANT_EXIT_GRACE_S) {
            for (int i = 0; i < s->n; i++)
                if (s->child[i].running && !s->child[i].is_helper) {
                    snprintf(s->failure, sizeof s->failure,
                             "participant '%s' (pid %d) did not exit %.0f s after the run ended",
                             s->child[i].name, (int)s->child[i].pid, PARTICIPANT_EXIT_GRACE_S);
                    break;
                }
            stop_all(s);
            return 1;
        }
        nap();
    }
}

static volatile int *stop_flag;

static void on_stop_signal(int sig)
{
    *stop_flag = sig;
}

void fsi_supervisor_catch_signals(volatile int *flag)
{
    stop_flag = flag;
    struct sigaction sa = {0};
    sa.sa_handler = on_stop_signal;
    sigaction(SIGINT, &sa, NULL);
    sigaction(SIGTERM, &sa, NULL);
    sigaction(SIGHUP, &sa, NULL);
}

void fsi_supervisor_stop_helpers(fsi_supervisor *s)
{
    signal_running(s, SIGINT, 1);
    double deadline = fsi_wall_seconds() + STOP_GRACE_S;
    for (int i = 0; i < s->n; i++) {
        fsi_child *c = &s->child[i];
        while (c->running && c->is_helper) {
            if (waitpid(c->pid, &c->status, WNOHANG) == c->pid) {
                c->running = 0;
            } else if (fsi_wall_seconds() > deadline) {
                kill(c->pid, SIGKILL);
                waitpid(c->pid, &c->status, 0);
                c->running = 0;
            } else {
                nap();
            }
        }
    }
}
