#include "participant_env.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>

#include "log.h"
#include "protocol.h"

static int copy_env(char *dst, size_t len, const char *given, const char *var,
                    const char *fallback)
{
    const char *v = given ? given : getenv(var);
    if (!v || !*v)
        v = fallback;
    if (!v) {
        fsi_error("%s is not set: participants are started by `fsi run` (docs/protocol.md)",
                  var);
        return -1;
    }
    snprintf(dst, len, "%s", v);
    return 0;
}

int fsi_run_env_read(fsi_run_env *env, const char *name, const char *case_path)
{
    if (copy_env(env->participant, sizeof env->participant, name, "FSI_PARTICIPANT", NULL) ||
        copy_env(env->case_path, sizeof env->case_path, case_path, "FSI_CASE", NULL) ||
        copy_env(env->out_dir, sizeof env->out_dir, NULL, "FSI_OUT", ".") ||
        copy_env(env->lcm_url, sizeof env->lcm_url, NULL, "FSI_LCM_URL", FSI_DEFAULT_LCM_URL))
        return -1;
    const char *id = getenv("FSI_RUN_ID");
    char *end = NULL;
    errno = 0;
    env->run_id = id ? strtoll(id, &end, 10) : 0;
    if (!id || !*id || *end || errno) {
        fsi_error("FSI_RUN_ID is not set to a whole number (it is '%s')", id ? id : "");
        return -1;
    }
    env->heartbeat_interval = FSI_DEFAULT_HEARTBEAT_INTERVAL;
    env->watchdog_timeout = FSI_DEFAULT_WATCHDOG_TIMEOUT;
    return 0;
}

void fsi_run_env_read_timing(fsi_run_env *env, const fsi_case *c)
{
    env->heartbeat_interval =
        fsi_case_get_real(c, "run", "heartbeat_interval", FSI_DEFAULT_HEARTBEAT_INTERVAL);
    env->watchdog_timeout =
        fsi_case_get_real(c, "run", "watchdog_timeout", FSI_DEFAULT_WATCHDOG_TIMEOUT);
}
