/* `fsi replay RUN_DIR --participant NAME`: runs one participant of a run recorded
 * with `fsi run --log-traffic` alone, against the recorded messages, and says
 * whether it reproduced its recorded messages and HDF5 output bit for bit.
 * The bus does the replaying (FSI_REPLAY_LOG, core/bus_replay.h); this program
 * checks the input, starts the participant as `fsi run` did and judges the result.
 * Exit status: 0 reproduced, 1 a difference or a failed participant, 2 bad input. */
#define _GNU_SOURCE
#include <dirent.h>
#include <errno.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "bus_replay.h"
#include "case_file.h"
#include "log.h"
#include "output_folder.h"
#include "private_network.h"
#include "run_plan.h"
#include "supervisor.h"
#include "timers.h"

typedef struct {
    const char *run_dir;
    const char *participant;
    launch_options common;   /* --out, --set, --threads, --force */
} replay_options;

/* What the participant's bus wrote in FSI_REPLAY_REPORT. */
typedef struct {
    long compared, differences;
    char first[1200];
} replay_verdict;

static volatile int interrupted;

static void usage(FILE *out)
{
    fprintf(out,
            "usage: fsi replay RUN_DIR --participant fluid|solid [--out DIR]\n"
            "                  [--set section.key=value ...] [--threads N] [--force]\n"
            "  RUN_DIR           output folder of a run made with fsi run --log-traffic\n"
            "  --participant P   the participant to run again, alone\n"
            "  --out DIR         output folder (default: RUN_DIR/replay_P)\n"
            "  --set s.k=v       change a key of the recorded case (the replay then differs)\n"
            "  --threads N       OpenMP threads (default: the recorded case's)\n"
            "  --force           replace the results of an earlier replay in DIR\n"
            "  An option's value may also follow '=': --out=DIR.\n");
}

static int parse_options(int argc, char **argv, replay_options *o)
{
    fsi_args a = fsi_args_begin(argc, argv, "fsi replay", usage);
    while (fsi_args_next(&a)) {
        const char *v;
        if (fsi_parse_launch_option(&a, &o->common))
            continue;
        if (fsi_arg_value(&a, "--participant", &v))
            o->participant = v;
        else if (fsi_arg_positional(&a) && !o->run_dir)
            o->run_dir = a.arg;
        else
            fsi_arg_unknown(&a);
    }
    if (a.error)
        return -1;
    if (!o->run_dir || !o->participant) {
        usage(stderr);
        return -1;
    }
    if (strcmp(o->participant, "fluid") != 0 && strcmp(o->participant, "solid") != 0) {
        fprintf(stderr, "fsi replay: --participant must be fluid or solid, not '%s'\n",
                o->participant);
        return -1;
    }
    return 0;
}

/* The recorded run's id, from its run.log: every recorded header carries it, and
 * the replayed participant must stamp the same one into what it publishes. */
static int recorded_run_id(const char *run_dir, int64_t *id)
{
    char path[PATH_MAX + 16], line[1024];
    snprintf(path, sizeof path, "%s/run.log", run_dir);
    FILE *f = fopen(path, "r");
    if (!f) {
        fprintf(stderr, "fsi replay: cannot read %s: %s\n", path, strerror(errno));
        return -1;
    }
    long long value = 0;
    int found = 0;
    while (!found && fgets(line, sizeof line, f))
        found = sscanf(line, "run_id = %lld", &value) == 1 && value > 0;
    fclose(f);
    if (!found) {
        fprintf(stderr, "fsi replay: %s has no run_id line\n", path);
        return -1;
    }
    *id = value;
    return 0;
}

/* Every check that needs no output folder: bad input is found before anything is
 * written. Returns the checked case (with the --set changes) or NULL. */
static fsi_case *check_input(const replay_options *o, char *log_path, int64_t *run_id,
                             participant_plan *plan)
{
    char path[PATH_MAX + 32];
    snprintf(path, sizeof path, "%s/traffic.lcmlog", o->run_dir);
    if (!realpath(path, log_path) || access(log_path, R_OK) != 0) {
        fprintf(stderr, "fsi replay: %s: %s (record the run with fsi run --log-traffic)\n", path,
                strerror(errno));
        return NULL;
    }
    snprintf(path, sizeof path, "%s/case.resolved.ini", o->run_dir);
    fsi_case *c = fsi_load_case(path, o->common.sets, o->common.n_sets, "fsi replay");
    if (!c)
        return NULL;
    if (!fsi_case_has_section(c, o->participant)) {
        fprintf(stderr, "fsi replay: the recorded case %s has no [%s] section\n", path,
                o->participant);
    } else if (recorded_run_id(o->run_dir, run_id) == 0 &&
               fsi_plan_participant(c, o->participant, o->common.threads, plan) == 0) {
        /* The participant must be in the recording, not only in the case. */
        fsi_replay *r = fsi_replay_open(log_path, o->participant, *run_id);
        if (r) {
            fsi_replay_free(r);
            return c;
        }
    }
    fsi_case_free(c);
    return NULL;
}

/* Creates the output folder (refusing the recorded one) with the case to run. */
static int prepare_output(const replay_options *o, const fsi_case *c, char *out_abs)
{
    char out[PATH_MAX], recorded[PATH_MAX], path[PATH_MAX + 32];
    if (o->common.out_dir)
        snprintf(out, sizeof out, "%s", o->common.out_dir);
    else
        snprintf(out, sizeof out, "%s/replay_%s", o->run_dir, o->participant);
    /* Checked before --force could remove the recorded results. */
    if (realpath(out, out_abs) && realpath(o->run_dir, recorded) &&
        strcmp(recorded, out_abs) == 0) {
        fprintf(stderr, "fsi replay: the output folder must not be the recorded run's\n");
        return FSI_EXIT_BAD_INPUT;
    }
    /* The lock is held until this process ends: the descriptor stays open. */
    if (fsi_claim_output_dir(out, o->common.force, "fsi replay") < 0)
        return FSI_EXIT_BAD_INPUT;
    if (!realpath(out, out_abs)) {
        fprintf(stderr, "fsi replay: cannot resolve the output folder %s: %s\n", out,
                strerror(errno));
        return FSI_EXIT_BAD_INPUT;
    }
    snprintf(path, sizeof path, "%s/case.resolved.ini", out_abs);
    FILE *f = fopen(path, "w");
    if (!f) {
        fprintf(stderr, "fsi replay: cannot write %s\n", path);
        return FSI_EXIT_RUN_FAILURE;
    }
    fsi_case_write_resolved(c, f);
    fclose(f);
    return FSI_EXIT_OK;
}

static void read_verdict(const char *path, replay_verdict *v)
{
    char line[1200];
    *v = (replay_verdict){-1, -1, ""};
    FILE *f = fopen(path, "r");
    if (!f)
        return;
    while (fgets(line, sizeof line, f)) {
        line[strcspn(line, "\n")] = '\0';
        sscanf(line, "compared = %ld", &v->compared);
        sscanf(line, "differences = %ld", &v->differences);
        if (strncmp(line, "first_difference = ", 19) == 0)
            snprintf(v->first, sizeof v->first, "%s", line + 19);
    }
    fclose(f);
}

/* Runs `h5diff -q [--exclude-attribute /] a b`; 1 when it finds them identical. */
static int h5diff_same(const char *a, const char *b, int skip_root_attributes)
{
    fflush(NULL);
    pid_t pid = fork();
    if (pid == 0) {
        char *full[] = {"h5diff", "-q", (char *)a, (char *)b, NULL};
        char *data[] = {"h5diff", "-q", "--exclude-attribute", "/", (char *)a, (char *)b, NULL};
        execvp("h5diff", skip_root_attributes ? data : full);
        _exit(2);
    }
    int status = 0;
    if (pid < 0 || waitpid(pid, &status, 0) < 0)
        return 0;
    return WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

typedef enum {
    H5_NOT_RECORDED = -1,   /* the recorded run has no such file: nothing to compare */
    H5_IDENTICAL = 0,
    H5_DIFFERS = 1,
    H5_OTHER_BUILD = 2      /* identical data; only the file's root attributes differ */
} h5_verdict;

/* Number of HDF5 files (*.h5) in DIR/NAME.frames; with 'other' set, -1 as soon as one
 * of them differs from (or is missing in) OTHER/NAME.frames. */
static int frame_files(const char *dir, const char *other, const char *name)
{
    char folder[PATH_MAX + 80], a[PATH_MAX + 400], b[PATH_MAX + 400];
    snprintf(folder, sizeof folder, "%s/%s.frames", dir, name);
    DIR *d = opendir(folder);
    if (!d)
        return 0;
    int n = 0;
    struct dirent *e;
    while ((e = readdir(d)) != NULL) {
        size_t len = strlen(e->d_name);
        if (len < 4 || strcmp(e->d_name + len - 3, ".h5") != 0)
            continue;
        n++;
        snprintf(a, sizeof a, "%s/%s", folder, e->d_name);
        snprintf(b, sizeof b, "%s/%s.frames/%s", other ? other : "", name, e->d_name);
        if (other && !h5diff_same(a, b, 0)) {
            n = -1;
            break;
        }
    }
    closedir(d);
    return n;
}

/* The data of NAME.h5 lives in the files of NAME.frames that its external links name
 * (docs/output.md); h5diff on NAME.h5 alone compares the link targets' names, and
 * even with --follow-symlinks only the first frame (it takes the frames' root groups,
 * at the same address in every file, for one object). So every file is compared.
 * The root attributes name the build (fsi_version holds the git commit), so a
 * replay by a newer build of the same computation differs only there. */
static h5_verdict compare_h5(const char *run_dir, const char *out_dir, const char *name)
{
    char recorded[PATH_MAX + 80], replayed[PATH_MAX + 80];
    snprintf(recorded, sizeof recorded, "%s/%s.h5", run_dir, name);
    snprintf(replayed, sizeof replayed, "%s/%s.h5", out_dir, name);
    if (access(recorded, R_OK) != 0)
        return H5_NOT_RECORDED;
    if (access(replayed, R_OK) != 0)
        return H5_DIFFERS;
    int n = frame_files(run_dir, out_dir, name);
    if (n < 0 || n != frame_files(out_dir, NULL, name))
        return H5_DIFFERS;
    if (h5diff_same(recorded, replayed, 0))
        return H5_IDENTICAL;
    return h5diff_same(recorded, replayed, 1) ? H5_OTHER_BUILD : H5_DIFFERS;
}

static const char *h5_verdict_text(h5_verdict v)
{
    switch (v) {
    case H5_NOT_RECORDED:
        return "not in the recorded run (not compared)";
    case H5_IDENTICAL:
        return "identical to the recorded one (h5diff)";
    case H5_OTHER_BUILD:
        return "identical data (h5diff); only its root attributes differ: written by another "
               "build";
    default:
        return "differs from the recorded one (h5diff)";
    }
}

static void log_printf(const char *path, const char *mode, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));

static void log_printf(const char *path, const char *mode, const char *fmt, ...)
{
    FILE *f = fopen(path, mode);
    if (!f)
        return;
    va_list ap;
    va_start(ap, fmt);
    vfprintf(f, fmt, ap);
    va_end(ap);
    fclose(f);
}

/* Runs the participant against the recording; returns the supervisor's verdict. */
static int run_participant(participant_plan *plan, const char *out_abs, const char *log_path,
                           int64_t run_id, const char *report, char *failure, size_t len)
{
    char env_case[PATH_MAX + 64], env_out[PATH_MAX + 16], env_id[64];
    char env_log[PATH_MAX + 32], env_report[PATH_MAX + 64], path[PATH_MAX + 32];
    snprintf(env_case, sizeof env_case, "FSI_CASE=%s/case.resolved.ini", out_abs);
    snprintf(env_out, sizeof env_out, "FSI_OUT=%s", out_abs);
    snprintf(env_id, sizeof env_id, "FSI_RUN_ID=%lld", (long long)run_id);
    snprintf(env_log, sizeof env_log, "FSI_REPLAY_LOG=%s", log_path);
    snprintf(env_report, sizeof env_report, "FSI_REPLAY_REPORT=%s", report);
    putenv(env_case);
    putenv(env_out);
    putenv(env_id);
    putenv(env_log);
    putenv(env_report);
    unsetenv("FSI_LCM_URL");

    fsi_supervisor_catch_signals(&interrupted);

    static fsi_supervisor sup;
    fsi_plan_environment(plan);
    char *argv[] = {plan->program, NULL};
    snprintf(path, sizeof path, "%s/%s.log", out_abs, plan->role);
    int failed = fsi_supervisor_start(&sup, plan->role, plan->program, argv, plan->env, path, 0,
                                      0) != 0;
    if (failed)
        snprintf(sup.failure, sizeof sup.failure, "could not start the participant");
    failed = fsi_supervisor_wait(&sup, &interrupted) != 0 || failed;
    snprintf(failure, len, "%s", sup.failure);
    return failed;
}

int main(int argc, char **argv)
{
    fsi_log_set_name("fsi replay");
    replay_options o = {0};
    if (parse_options(argc, argv, &o) != 0)
        return FSI_EXIT_BAD_INPUT;
    /* realpath() fills PATH_MAX bytes */
    char log_path[PATH_MAX], out_abs[PATH_MAX];
    int64_t run_id = 0;
    participant_plan plan = {0};
    fsi_case *c = check_input(&o, log_path, &run_id, &plan);
    if (!c)
        return FSI_EXIT_BAD_INPUT;
    int rc = prepare_output(&o, c, out_abs);
    fsi_case_free(c);
    if (rc != FSI_EXIT_OK)
        return rc;

    char run_log[PATH_MAX + 16], report[PATH_MAX + 16];
    snprintf(run_log, sizeof run_log, "%s/run.log", out_abs);
    snprintf(report, sizeof report, "%s/replay.log", out_abs);
    log_printf(run_log, "w", "# fsi replay log\nrecorded_run = %s\nparticipant = %s\n"
                             "run_id = %lld\nsets = %d\n",
               log_path, o.participant, (long long)run_id, o.common.n_sets);
    for (int i = 0; i < o.common.n_sets; i++)
        log_printf(run_log, "a", "set = %s\n", o.common.sets[i]);
    /* The replay bus opens no network; without one, not even a bug could reach it. */
    if (fsi_leave_network() != 0)
        return FSI_EXIT_RUN_FAILURE;

    double started = fsi_wall_seconds();
    char failure[2048];
    int failed = run_participant(&plan, out_abs, log_path, run_id, report, failure,
                                 sizeof failure);
    replay_verdict v;
    read_verdict(report, &v);
    h5_verdict h5 = compare_h5(o.run_dir, out_abs, o.participant);
    int same = !failed && v.differences == 0 && h5 != H5_DIFFERS;

    printf("fsi replay: %s: %ld messages compared, %ld differ%s%s\n", o.participant,
           v.compared < 0 ? 0 : v.compared, v.differences < 0 ? 0 : v.differences,
           v.differences > 0 ? "; first: " : "", v.differences > 0 ? v.first : "");
    printf("fsi replay: %s.h5 %s\n", o.participant, h5_verdict_text(h5));
    if (failed)
        printf("fsi replay: the participant failed: %s (see %s/%s.log)\n", failure, out_abs,
               o.participant);
    log_printf(run_log, "a",
               "messages_compared = %ld\nmessages_differing = %ld\nfirst_difference = %s\n"
               "h5 = %s\nexit = %s (%.2f s wall)\n",
               v.compared, v.differences, v.differences > 0 ? v.first : "none",
               h5_verdict_text(h5),
               same ? "reproduced" : failed ? failure : "differs", fsi_wall_seconds() - started);
    printf("fsi replay: %s; output in %s\n", same ? "reproduced bit for bit" : "NOT reproduced",
           out_abs);
    return same ? FSI_EXIT_OK : FSI_EXIT_RUN_FAILURE;
}
