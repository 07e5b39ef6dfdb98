/* `fsi run`: checks a case, creates the output folder, isolates the run in a private
 * network namespace, starts the coupler and the participants, and stops them all
 * when one fails. Exit status: 0 success, 1 run failure, 2 bad input. */
#define _GNU_SOURCE
#include <errno.h>
#include <fcntl.h>
#include <dirent.h>
#include <fnmatch.h>
#include <hdf5.h>
#include <lcm/lcm.h>
#include <libgen.h>
#include <limits.h>
#include <signal.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "case_file.h"
#include "checkpoint_folder.h"
#include "log.h"
#include "output_folder.h"
#include "private_network.h"
#include "protocol.h"
#include "run_plan.h"
#include "run_xmf.h"
#include "solver_registry.h"
#include "supervisor.h"
#include "timers.h"
#include "write_initial.h"

typedef struct {
    const char *case_path;
    launch_options common;   /* --out, --set, --threads, --force */
    int log_traffic;
    const char *lcm_url;   /* NULL: private namespace with the default URL */
    int check_only;
    int write_initial;          /* --write-initial: frame 0 of everyone, no run */
    const char *restart;        /* --restart OUT */
    char checkpoint_set[96];    /* --checkpoint-interval T as run.checkpoint_interval=T */
} run_options;

static volatile int interrupted;

static void usage(FILE *out)
{
    fprintf(out,
            "usage: fsi run CASE [--out DIR] [--set section.key=value ...] [--threads N]\n"
            "               [--log-traffic] [--lcm-url URL] [--force] [--check]\n"
            "               [--checkpoint-interval T]\n"
            "       fsi run --restart OUT [--threads N] [--log-traffic] [--lcm-url URL]\n"
            "  --out DIR         output folder (default: out/<case name>)\n"
            "  --set s.k=v       override a case key (repeatable)\n"
            "  --threads N       OpenMP threads of every participant\n"
            "  --log-traffic     record every bus message to DIR/traffic.lcmlog\n"
            "  --lcm-url URL     use this LCM network instead of a private namespace\n"
            "  --force           replace the results of an earlier run in DIR\n"
            "  --check           only check the case, run nothing\n"
            "  --write-initial   with --check: also write frame 0 of every participant\n"
            "                    to DIR (the particles as built), run nothing\n"
            "  --checkpoint-interval T\n"
            "                    a coupled checkpoint every T of simulated time (at the\n"
            "                    first frame time from each multiple of T on)\n"
            "  --restart OUT     go on with the run in OUT from its newest complete\n"
            "                    checkpoint (docs/checkpoints.md)\n"
            "  An option's value may also follow '=': --out=DIR.\n");
}

/* --checkpoint-interval T becomes --set run.checkpoint_interval=T. */
static void set_checkpoint_interval(fsi_args *a, const char *v, run_options *o)
{
    if (!v)
        return;   /* the message is printed */
    char *end;
    const double t = strtod(v, &end);
    if (*end || !(t > 0.0))
        fsi_arg_bad_value(a, "--checkpoint-interval", v, "needs a time > 0 in seconds");
    else if (o->common.n_sets >= FSI_MAX_SETS)
        fsi_arg_bad_value(a, "--checkpoint-interval", v, "is one --set too many");
    else {
        snprintf(o->checkpoint_set, sizeof o->checkpoint_set, "run.checkpoint_interval=%.17g",
                 t);
        o->common.sets[o->common.n_sets++] = o->checkpoint_set;
    }
}

static int parse_options(int argc, char **argv, run_options *o)
{
    fsi_args a = fsi_args_begin(argc, argv, "fsi run", usage);
    while (fsi_args_next(&a)) {
        const char *v;
        if (fsi_parse_launch_option(&a, &o->common))
            continue;
        if (fsi_arg_flag(&a, "--log-traffic"))
            o->log_traffic = 1;
        else if (fsi_arg_value(&a, "--lcm-url", &v))
            o->lcm_url = v;
        else if (fsi_arg_flag(&a, "--check"))
            o->check_only = 1;
        else if (fsi_arg_flag(&a, "--write-initial"))
            o->write_initial = 1;
        else if (fsi_arg_value(&a, "--restart", &v))
            o->restart = v;
        else if (fsi_arg_value(&a, "--checkpoint-interval", &v))
            set_checkpoint_interval(&a, v, o);
        else if (fsi_arg_positional(&a) && !o->case_path)
            o->case_path = a.arg;
        else
            fsi_arg_unknown(&a);
    }
    if (a.error)
        return -1;
    if (o->restart) {
        /* The run goes on with its own resolved case: nothing about it may change. */
        if (o->case_path || o->common.n_sets > 0 || o->common.out_dir || o->common.force ||
            o->check_only || o->write_initial) {
            fprintf(stderr, "fsi run: --restart OUT takes the case, the output folder and "
                            "the checkpoint interval from OUT; give none of CASE, --out, "
                            "--set, --checkpoint-interval, --force or --check with it\n");
            return -1;
        }
        static char resolved[PATH_MAX + 32];
        snprintf(resolved, sizeof resolved, "%s/case.resolved.ini", o->restart);
        o->case_path = resolved;
        o->common.out_dir = o->restart;
    }
    if (!o->case_path) {
        usage(stderr);
        return -1;
    }
    if (o->write_initial && !o->check_only) {
        fprintf(stderr, "fsi run: --write-initial goes with --check (fsi run CASE --check "
                        "--write-initial [--out DIR])\n");
        return -1;
    }
    return 0;
}

/* The newest complete checkpoint of OUT for --restart, written by this very code
 * version; sets FSI_RESTART_DIR and FSI_RESTART_FRAMES for every process. 0, or -1
 * with a message. */
static int prepare_restart(const char *out, fsi_checkpoint_info *info)
{
    char msg[4600];
    if (fsi_checkpoint_latest(out, info, msg, sizeof msg) != 0) {
        fprintf(stderr, "fsi run: --restart: %s\n", msg);
        return -1;
    }
    if (strcmp(info->version, FSI_VERSION) != 0) {
        fprintf(stderr, "fsi run: --restart: %s/COMPLETE: the checkpoint was written by "
                        "version %s of the code, this is %s; a checkpoint restarts only the "
                        "build that wrote it\n", info->dir, info->version, FSI_VERSION);
        return -1;
    }
    static char env_dir[4400], env_frames[64];
    snprintf(env_dir, sizeof env_dir, "FSI_RESTART_DIR=%s", info->dir);
    snprintf(env_frames, sizeof env_frames, "FSI_RESTART_FRAMES=%d", info->frames);
    putenv(env_dir);
    putenv(env_frames);
    return 0;
}

/* Finds each participant's program; returns the number of problems (bad input). */
static int plan_participants(const fsi_case *c, const run_options *o, participant_plan *plan,
                             int *n_plan)
{
    const fsi_case_schema *schema = fsi_project_schema();
    int errors = 0;
    *n_plan = 0;
    for (int r = 0; r < schema->n_roles; r++) {
        const char *role = schema->roles[r];
        if (fsi_case_has_section(c, role) &&
            fsi_plan_participant(c, role, o->common.threads, &plan[(*n_plan)++]) != 0)
            errors++;
    }
    if (*n_plan == 0) {
        fprintf(stderr, "%s: the case has neither a [fluid] nor a [solid] section\n",
                fsi_case_path(c));
        errors++;
    }
    return errors;
}

static void default_out_dir(const char *case_path, char *out, size_t len)
{
    char copy[PATH_MAX];
    snprintf(copy, sizeof copy, "%s", case_path);
    char *base = basename(copy);
    char *dot = strrchr(base, '.');
    if (dot && dot != base)
        *dot = '\0';
    snprintf(out, len, "out/%s", base);
}

static int64_t new_run_id(void)
{
    uint64_t id = 0;
    int fd = open("/dev/urandom", O_RDONLY);
    if (fd < 0 || read(fd, &id, sizeof id) != (ssize_t)sizeof id)
        id = (uint64_t)time(NULL) ^ ((uint64_t)getpid() << 32);
    if (fd >= 0)
        close(fd);
    return (int64_t)(id >> 1) | 1;   /* positive and never 0 */
}

/* Flushes and closes a log written with stdio; 0, or -1 after a message naming the
 * file and the system's reason (a full disk shows up here at the latest). */
static int close_log(FILE *log, const char *path)
{
    int err = fsi_fclose_checked(log);
    if (err)
        fprintf(stderr, "fsi run: cannot write %s: %s\n", path, strerror(err));
    return err ? -1 : 0;
}

static int write_log_header(const char *path, int argc, char **argv, int64_t run_id,
                            const char *url, int isolated, const fsi_case *c)
{
    FILE *log = fsi_fopen_checked(path, "w");
    if (!log) {
        fprintf(stderr, "fsi run: cannot create %s: %s\n", path, strerror(errno));
        return -1;
    }
    time_t now = time(NULL);
    char date[64];
    strftime(date, sizeof date, "%Y-%m-%dT%H:%M:%SZ", gmtime(&now));
    unsigned h5maj, h5min, h5rel;
    H5get_libversion(&h5maj, &h5min, &h5rel);
    char host[256] = "";
    gethostname(host, sizeof host - 1);
    fprintf(log, "# fsi run log\ndate = %s\nhost = %s\ncommand = fsi run", date, host);
    for (int i = 1; i < argc; i++)
        fprintf(log, " %s", argv[i]);
    fprintf(log,
            "\nfsi_version = %s\nprotocol_version = %d\nlcm_version = %d.%d.%d\n"
            "hdf5_version = %u.%u.%u\ncompiler = gcc %s\ndimension = %d\nrun_id = %lld\n"
            "lcm_url = %s\nisolation = %s\n",
            FSI_VERSION, FSI_PROTOCOL_VERSION, LCM_MAJOR_VERSION, LCM_MINOR_VERSION,
            LCM_MICRO_VERSION, h5maj, h5min, h5rel, __VERSION__, FSI_DIM, (long long)run_id,
            url, isolated ? "private network namespace" : "user-given LCM URL");
    const char *drop = getenv("FSI_TEST_DROP_FRACTION");
    if (drop && *drop)
        fprintf(log, "test_drop_fraction = %s (seed %s)\n", drop,
                getenv("FSI_TEST_DROP_SEED") ? getenv("FSI_TEST_DROP_SEED") : "1");
    fprintf(log, "\n# resolved case\n");
    fsi_case_write_resolved(c, log);
    return close_log(log, path);
}

static int append_log(const char *path, const char *fmt, ...) __attribute__((format(printf, 2, 3)));

static int append_log(const char *path, const char *fmt, ...)
{
    FILE *log = fsi_fopen_checked(path, "a");
    if (!log) {
        fprintf(stderr, "fsi run: cannot append to %s: %s\n", path, strerror(errno));
        return -1;
    }
    va_list ap;
    va_start(ap, fmt);
    vfprintf(log, fmt, ap);
    va_end(ap);
    return close_log(log, path);
}

/* The coupler's own account of a failure, from its 'coupler_exit = failure: ...'
 * line in run.log; empty when it has none. */
static void coupler_verdict(const char *log_path, char *out, size_t size)
{
    static const char tag[] = "coupler_exit = failure: ";
    char line[2048];
    out[0] = '\0';
    FILE *f = fopen(log_path, "r");
    if (!f)
        return;
    while (fgets(line, sizeof line, f))
        if (strncmp(line, tag, sizeof tag - 1) == 0) {
            line[strcspn(line, "\n")] = '\0';
            size_t len = strlen(line + sizeof tag - 1);
            if (len >= size)
                len = size - 1;
            memcpy(out, line + sizeof tag - 1, len);
            out[len] = '\0';
        }
    fclose(f);
}

static void print_log_tail(const char *path)
{
    FILE *f = fopen(path, "r");
    if (!f)
        return;
    char lines[10][512];
    int n = 0;
    while (fgets(lines[n % 10], sizeof lines[0], f))
        n++;
    fclose(f);
    if (n == 0)
        return;
    fprintf(stderr, "--- last lines of %s ---\n", path);
    for (int i = n > 10 ? n - 10 : 0; i < n; i++)
        fputs(lines[i % 10], stderr);
}

/* The warnings of a participant's log (at most a few), repeated on stderr after a run
 * that finished: a run can end well and still have left its method's range (a Mach
 * number past the weakly compressible one, fluid inside the solid). */
static void print_log_warnings(const char *path)
{
    enum { MAX_SHOWN = 5 };
    FILE *f = fopen(path, "r");
    if (!f)
        return;
    char line[1024];
    int n = 0;
    while (fgets(line, sizeof line, f))
        if (strstr(line, "] warning: ") && n++ < MAX_SHOWN)
            fprintf(stderr, "fsi run: %s: %s", path, line);
    if (n > MAX_SHOWN)
        fprintf(stderr, "fsi run: %s: %d warnings in all\n", path, n);
    fclose(f);
}

static int wait_for_file(const char *path, double seconds)
{
    double deadline = fsi_wall_seconds() + seconds;
    while (access(path, F_OK) != 0) {
        if (fsi_wall_seconds() > deadline)
            return -1;
        usleep(10000);
    }
    return 0;
}

static int start_processes(fsi_supervisor *sup, const char *out, const char *url,
                           int log_traffic, participant_plan *plan, int n_plan)
{
    char bin[PATH_MAX], program[PATH_MAX + 32], path[PATH_MAX + 32];
    fsi_bin_dir(bin, sizeof bin);
    if (log_traffic) {
        snprintf(path, sizeof path, "%s/traffic.lcmlog", out);
        snprintf(program, sizeof program, "%s/fsi-record", bin);
        char *argv[] = {"fsi-record", (char *)url, path, NULL};
        char recorder_log[PATH_MAX + 32];
        snprintf(recorder_log, sizeof recorder_log, "%s/traffic.log", out);
        unlink(path);
        if (fsi_supervisor_start(sup, "fsi-record", program, argv, NULL, recorder_log, 0, 1) !=
                0 ||
            wait_for_file(path, 5.0) != 0) {
            fsi_error("the traffic recorder did not start (see %s)", recorder_log);
            return -1;
        }
    }
    snprintf(program, sizeof program, "%s/fsi-coupler", bin);
    char *coupler_argv[] = {"fsi-coupler", NULL};
    char *coupler_env[] = {"FSI_PARTICIPANT=" FSI_COUPLER_NAME, NULL};
    if (fsi_supervisor_start(sup, FSI_COUPLER_NAME, program, coupler_argv, coupler_env, NULL,
                             1, 0) != 0)
        return -1;
    for (int i = 0; i < n_plan; i++) {
        fsi_plan_environment(&plan[i]);
        char *argv[] = {plan[i].program, NULL};
        snprintf(path, sizeof path, "%s/%s.log", out, plan[i].role);
        if (fsi_supervisor_start(sup, plan[i].role, plan[i].program, argv, plan[i].env, path, 0,
                                 0) != 0)
            return -1;
    }
    return 0;
}

int main(int argc, char **argv)
{
    fsi_log_set_name("fsi run");
    run_options o = {0};
    if (parse_options(argc, argv, &o) != 0)
        return FSI_EXIT_BAD_INPUT;

    fsi_case *c = fsi_load_case(o.case_path, o.common.sets, o.common.n_sets, "fsi run");
    if (!c)
        return FSI_EXIT_BAD_INPUT;
    participant_plan plan[8];
    int n_plan = 0;
    int errors = plan_participants(c, &o, plan, &n_plan);
    if (errors) {
        fprintf(stderr, "fsi run: %s has %d error%s; nothing was run\n", o.case_path, errors,
                errors == 1 ? "" : "s");
        fsi_case_free(c);
        return FSI_EXIT_BAD_INPUT;
    }
    if (o.check_only && !o.write_initial) {
        printf("%s: valid (%d participant%s)\n", o.case_path, n_plan, n_plan == 1 ? "" : "s");
        fsi_case_free(c);
        return FSI_EXIT_OK;
    }

    char out[PATH_MAX], out_abs[PATH_MAX], path[PATH_MAX + 32];
    if (o.common.out_dir)
        snprintf(out, sizeof out, "%s", o.common.out_dir);
    else
        default_out_dir(o.case_path, out, sizeof out);
    /* Held until this process ends, through the namespace steps and the run. */
    int lock = fsi_claim_output_dir(out, o.restart ? FSI_CLAIM_KEEP : o.common.force, "fsi run");
    if (lock < 0) {
        fsi_case_free(c);
        return FSI_EXIT_BAD_INPUT;
    }
    if (!realpath(out, out_abs)) {
        fprintf(stderr, "fsi run: cannot resolve the output folder %s: %s\n", out,
                strerror(errno));
        fsi_case_free(c);
        return FSI_EXIT_BAD_INPUT;
    }

    fsi_checkpoint_info restart;
    if (o.restart && prepare_restart(out_abs, &restart) != 0) {
        fsi_case_free(c);
        return FSI_EXIT_BAD_INPUT;
    }
    snprintf(path, sizeof path, "%s/case.resolved.ini", out_abs);
    if (!o.restart) {
        FILE *resolved = fopen(path, "w");
        if (!resolved) {
            fprintf(stderr, "fsi run: cannot write %s\n", path);
            fsi_case_free(c);
            return FSI_EXIT_RUN_FAILURE;
        }
        fsi_case_write_resolved(c, resolved);
        fclose(resolved);
    }
    /* Fluid and solid in one file for ParaView; written again on a restart (the same). */
    const char *roles[8];
    for (int i = 0; i < n_plan; i++)
        roles[i] = plan[i].role;
    if (fsi_write_run_xmf(out_abs, roles, n_plan) != 0) {
        fsi_case_free(c);
        return FSI_EXIT_RUN_FAILURE;
    }

    int isolated = o.lcm_url == NULL;
    const char *url = isolated ? FSI_DEFAULT_LCM_URL : o.lcm_url;
    int64_t run_id = new_run_id();
    char log_path[PATH_MAX + 32];
    snprintf(log_path, sizeof log_path, "%s/run.log", out_abs);
    int header = o.restart
                     ? append_log(log_path, "\n# restart from %s (window %d, t = %.9g s), run_id "
                                  "= %lld\n", restart.dir, restart.window, restart.time,
                                  (long long)run_id)
                     : write_log_header(log_path, argc, argv, run_id, url, isolated, c);
    fsi_case_free(c);
    if (header != 0)
        return FSI_EXIT_RUN_FAILURE;

    if (isolated && fsi_enter_private_network() != 0) {
        append_log(log_path, "\nexit = failure: no private network namespace\n");
        return FSI_EXIT_RUN_FAILURE;
    }
    char env_case[PATH_MAX + 64], env_out[PATH_MAX + 16], env_url[600], env_id[64];
    snprintf(env_case, sizeof env_case, "FSI_CASE=%s", path);
    snprintf(env_out, sizeof env_out, "FSI_OUT=%s", out_abs);
    snprintf(env_url, sizeof env_url, "FSI_LCM_URL=%s", url);
    snprintf(env_id, sizeof env_id, "FSI_RUN_ID=%lld", (long long)run_id);
    putenv(env_case);
    putenv(env_out);
    putenv(env_url);
    putenv(env_id);
    /* Variables of `fsi replay` would make every process replay a recording. */
    unsetenv("FSI_REPLAY_LOG");
    unsetenv("FSI_REPLAY_REPORT");
    if (o.write_initial) {
        /* Each participant alone, no coupler and no bus traffic (write_initial.h). */
        if (fsi_write_initial_frames(plan, n_plan, out_abs) != 0) {
            append_log(log_path, "\nexit = failure: --write-initial\n");
            return FSI_EXIT_RUN_FAILURE;
        }
        printf("%s: valid (%d participant%s); frame 0 in %s\n", o.case_path, n_plan,
               n_plan == 1 ? "" : "s", out_abs);
        return append_log(log_path, "\nexit = ok (--write-initial: frame 0 only)\n") == 0
                   ? FSI_EXIT_OK
                   : FSI_EXIT_RUN_FAILURE;
    }

    fsi_supervisor_catch_signals(&interrupted);

    static fsi_supervisor sup;
    int failed = start_processes(&sup, out_abs, url, o.log_traffic, plan, n_plan) != 0;
    if (failed)
        snprintf(sup.failure, sizeof sup.failure, "could not start every process");
    /* Even after a failed start, wait: whatever did start must be stopped and reaped. */
    int rc = fsi_supervisor_wait(&sup, &interrupted);
    failed = failed || rc != 0;
    fsi_supervisor_stop_helpers(&sup);

    double wall = fsi_wall_seconds() - sup.started;
    if (failed) {
        /* The coupler knows who failed when a process hung rather than died. */
        char verdict[1024] = "";
        coupler_verdict(log_path, verdict, sizeof verdict);
        append_log(log_path, "\nexit = failure: %s%s%s\n", sup.failure,
                   verdict[0] ? "; coupler: " : "", verdict);
        fprintf(stderr, "fsi run: run failed: %s\n", sup.failure);
        if (verdict[0])
            fprintf(stderr, "fsi run: coupler: %s\n", verdict);
        for (int i = 0; i < n_plan; i++) {
            snprintf(path, sizeof path, "%s/%s.log", out_abs, plan[i].role);
            print_log_tail(path);
        }
        fprintf(stderr, "fsi run: output written so far is in %s\n", out_abs);
        return FSI_EXIT_RUN_FAILURE;
    }
    for (int i = 0; i < n_plan; i++) {
        snprintf(path, sizeof path, "%s/%s.log", out_abs, plan[i].role);
        print_log_warnings(path);
    }
    if (append_log(log_path, "\nexit = ok (%.2f s wall)\n", wall) != 0) {
        fprintf(stderr, "fsi run: run failed: cannot record its end in %s\n", log_path);
        return FSI_EXIT_RUN_FAILURE;
    }
    printf("fsi run: finished in %.1f s; output in %s\n", wall, out_abs);
    return FSI_EXIT_OK;
}
