/* The environment `fsi run` gives every process of a run (docs/protocol.md), read
 * in one place for the coupler and the participant library. */
#ifndef FSI_PARTICIPANT_ENV_H
#define FSI_PARTICIPANT_ENV_H

#include <limits.h>
#include <stdint.h>

#include "case_file.h"

typedef struct {
    char participant[64];        /* FSI_PARTICIPANT */
    char case_path[PATH_MAX];    /* FSI_CASE */
    char out_dir[PATH_MAX];      /* FSI_OUT (default ".") */
    char lcm_url[512];           /* FSI_LCM_URL (default FSI_DEFAULT_LCM_URL) */
    int64_t run_id;              /* FSI_RUN_ID */
    double heartbeat_interval;   /* [run] heartbeat_interval */
    double watchdog_timeout;     /* [run] watchdog_timeout */
} fsi_run_env;

/* Reads the environment; name/case_path override FSI_PARTICIPANT/FSI_CASE when not
 * NULL. Returns 0, or -1 with a message naming the missing variable. */
int fsi_run_env_read(fsi_run_env *env, const char *name, const char *case_path);

/* Liveness timing from the case's [run] section. */
void fsi_run_env_read_timing(fsi_run_env *env, const fsi_case *c);

#endif
