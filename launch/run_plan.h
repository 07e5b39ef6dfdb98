/* What `fsi run` and `fsi replay` share to start participants: the checked case,
 * each participant's program and its environment (the output folder:
 * output_folder.h). */
#ifndef FSI_RUN_PLAN_H
#define FSI_RUN_PLAN_H

#include <limits.h>
#include <stddef.h>

#include "case_file.h"
#include "cli_args.h"

#define FSI_MAX_SETS 256

/* The options `fsi run` and `fsi replay` share. */
typedef struct {
    const char *out_dir;
    const char *sets[FSI_MAX_SETS];   /* "section.key=value" */
    int n_sets;
    int threads;                      /* 0: from the case */
    int force;
} launch_options;

/* Takes the current argument when it is one of the shared options (--out, --set,
 * --threads, --force; cli_args.h), with its value. Returns 1 when taken (a bad value
 * sets a->error with a message), 0 when it is not one of them. */
int fsi_parse_launch_option(fsi_args *a, launch_options *o);

typedef struct {
    const char *role;
    char program[PATH_MAX];
    int threads;
    /* the extra environment of its process, NULL-terminated (fsi_plan_environment) */
    char env_name[80], env_threads[64];
    char *env[4];
} participant_plan;

/* Reads a case file, applies the "section.key=value" overrides and validates it;
 * every problem is reported on stderr under 'command'. Returns NULL on any error. */
fsi_case *fsi_load_case(const char *path, const char *const *sets, int n_sets,
                        const char *command);

/* The folder of the running program, where the other programs are built. */
void fsi_bin_dir(char *dir, size_t len);

/* Finds the program of the participant 'role' (a named solver or an executable)
 * with 'threads' (0: the section's own). Returns 0, or -1 with a message. */
int fsi_plan_participant(const fsi_case *c, const char *role, int threads,
                         participant_plan *p);

/* Fills p->env: FSI_PARTICIPANT, OMP_NUM_THREADS and the OpenMP wait policy. */
void fsi_plan_environment(participant_plan *p);

#endif
