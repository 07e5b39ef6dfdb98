#include "run_plan.h"

#include <errno.h>
#include <libgen.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "run_keys.h"
#include "solver_registry.h"

int fsi_parse_launch_option(fsi_args *a, launch_options *o)
{
    const char *v;
    if (fsi_arg_value(a, "--out", &v)) {
        o->out_dir = v;
    } else if (fsi_arg_value(a, "--set", &v)) {
        if (v && o->n_sets >= FSI_MAX_SETS) {
            char what[64];
            snprintf(what, sizeof what, "is one too many (at most %d)", FSI_MAX_SETS);
            fsi_arg_bad_value(a, "--set", v, what);
        } else if (v)
            o->sets[o->n_sets++] = v;
    } else if (fsi_arg_value(a, "--threads", &v)) {
        char *end = NULL;
        long n = v ? strtol(v, &end, 10) : 0;
        if (v && (*end || n < 1 || n > 1024))
            fsi_arg_bad_value(a, "--threads", v, "needs a whole number from 1 to 1024");
        o->threads = (int)n;
    } else if (fsi_arg_flag(a, "--force")) {
        o->force = 1;
    } else {
        return 0;
    }
    return 1;
}

fsi_case *fsi_load_case(const char *path, const char *const *sets, int n_sets,
                        const char *command)
{
    fsi_case *c = fsi_case_read(path, stderr);
    if (!c)
        return NULL;
    int errors = 0;
    for (int i = 0; i < n_sets; i++)
        errors += fsi_case_override(c, sets[i], stderr) != 0;
    errors += fsi_case_validate(c, fsi_project_schema(), stderr);
    if (errors == 0)
        errors += fsi_run_keys_check(c, stderr);
    if (errors == 0)
        return c;
    fprintf(stderr, "%s: %s has %d error%s; nothing was run\n", command, path, errors,
            errors == 1 ? "" : "s");
    fsi_case_free(c);
    return NULL;
}

void fsi_bin_dir(char *dir, size_t len)
{
    char self[PATH_MAX];
    ssize_t n = readlink("/proc/self/exe", self, sizeof self - 1);
    self[n > 0 ? n : 0] = '\0';
    snprintf(dir, len, "%s", dirname(self));
}

int fsi_plan_participant(const fsi_case *c, const char *role, int threads,
                         participant_plan *p)
{
    char bin[PATH_MAX];
    fsi_bin_dir(bin, sizeof bin);
    p->role = role;
    p->threads = threads ? threads : (int)fsi_case_get_int(c, role, "threads", 1);
    const char *solver = fsi_case_get(c, role, "solver");
    const fsi_solver_spec *spec = fsi_find_solver(solver);
    int len = spec ? snprintf(p->program, sizeof p->program, "%s/%s", bin, spec->executable)
                   : snprintf(p->program, sizeof p->program, "%s",
                              fsi_case_get(c, role, "executable"));
    if (len >= (int)sizeof p->program) {
        fprintf(stderr, "%s: [%s] program path is too long\n", fsi_case_path(c), role);
        return -1;
    }
    if (access(p->program, X_OK) != 0) {
        fprintf(stderr, "%s: [%s] %s: program '%s' is not executable: %s\n", fsi_case_path(c),
                role, spec ? "solver" : "executable", p->program, strerror(errno));
        return -1;
    }
    return 0;
}

void fsi_plan_environment(participant_plan *p)
{
    /* Waiting OpenMP threads sleep instead of spinning (unless the user chose): on
     * a machine shared with other jobs a barrier spun for whole time slices while
     * the thread it waited for was descheduled (F1 on 2 threads beside two other
     * simulations: 6.6e4 particle-steps/s spinning, 5.1e5 sleeping;
     * docs/performance.md). */
    static char wait_policy[] = "OMP_WAIT_POLICY=passive";
    snprintf(p->env_name, sizeof p->env_name, "FSI_PARTICIPANT=%s", p->role);
    snprintf(p->env_threads, sizeof p->env_threads, "OMP_NUM_THREADS=%d", p->threads);
    p->env[0] = p->env_name;
    p->env[1] = p->env_threads;
    p->env[2] = getenv("OMP_WAIT_POLICY") ? NULL : wait_policy;
    p->env[3] = NULL;
}
