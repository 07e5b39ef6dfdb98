/* The participant library's interface exchange (core/participant.h) end to end,
 * without a network: each side runs as a replay (core/bus_replay.h) of a hand-made
 * traffic log that holds the registers, the welcomes, window 0's step and the solid's
 * state of that window, with densities that are not round numbers.
 *  - the solid: fsi_write_interface refuses a state of n > 0 without densities
 *    (returns -1, publishes nothing) and publishes the full state exactly as recorded
 *    (the replay finds no difference: every field, density included, is encoded);
 *  - the fluid: fsi_read_interface hands it the recorded state, ids, volumes and
 *    densities bit for bit: the fluid receives what the solid sent. */
#include <lcm/eventlog.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "messages.h"
#include "participant.h"

#include "unit_check.h"
#include "unit_traffic_log.h"

#define RUN 5151
#define N 3
#define DT_FIRST 1e-3

static int32_t ids[N] = {4, 9, 2};
static double x[N * 3] = {0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9};
static double v[N * 3] = {0.0, -1e-3, 0.0, 2e-3, 0.0, 0.0, 0.0, 0.0, 1e-3};
static double a[N * 3] = {0.0, 9.81, 0.0, 0.0, 0.0, 0.0, -1.0, 0.0, 0.0};
static double volume[N] = {1.6e-5, 1.6e-5, 8e-6};
static double density[N] = {2500.0 / 3.0, 2481.9536794656519, 2533.7082391469144};

static void write_log(const char *path)
{
    static char *names[2] = {"fluid", "solid"};
    lcm_eventlog_t *log = lcm_eventlog_create(path, "w");
    for (int k = 0; k < 2; k++) {
        fsi_register_t r = {0};
        r.role = names[k];
        r.host = "recorded-host";
        r.pid = 100 + k;
        r.dt_proposed = DT_FIRST;
        unit_log_put(log, FSI_MSG_REGISTER, &r, names[k], RUN, -1, 1);
    }
    for (int k = 0; k < 2; k++) {
        fsi_welcome_t w = {0};
        w.participant = names[k];
        w.t_end = 1.0;
        w.n_participants = 2;
        w.participant_names = names;
        w.participant_roles = names;
        unit_log_put(log, FSI_MSG_WELCOME, &w, FSI_COUPLER_NAME, RUN, -1, 1 + k);
    }
    fsi_step_t s = {0};
    s.frame = -1;
    unit_log_put(log, FSI_MSG_STEP, &s, FSI_COUPLER_NAME, RUN, 0, 3);
    fsi_solid_state_t m = unit_solid_state(N, ids, x, v, a, volume, density);
    unit_log_put(log, FSI_MSG_SOLID_STATE, &m, "solid", RUN, 0, 2);
    lcm_eventlog_destroy(log);
}

/* Joins the replayed run as 'name' and enters window 0; NULL when it cannot. */
static fsi_participant *join(const char *name, const char *case_path)
{
    fsi_participant *p = fsi_open(name, name, case_path, DT_FIRST);
    if (p && fsi_ongoing(p) != 1) {
        fsi_close(p, NULL);
        return NULL;
    }
    return p;
}

int main(void)
{
    const char *tmp = getenv("FSI_TEST_TMP") ? getenv("FSI_TEST_TMP") : ".";
    char log_path[512], report[512], case_path[512], text[2048];
    snprintf(log_path, sizeof log_path, "%s/test_participant_interface.lcmlog", tmp);
    snprintf(report, sizeof report, "%s/test_participant_interface.report", tmp);
    snprintf(case_path, sizeof case_path, "%s/test_participant_interface.ini", tmp);
    mkdir(tmp, 0755);   /* ctest's scratch folder; may exist already */
    FILE *c = fopen(case_path, "w");
    if (!c) {
        fprintf(stderr, "cannot write %s\n", case_path);
        return 2;
    }
    fputs("[run]\nend_time = 1\n", c);
    fclose(c);
    write_log(log_path);
    char run_id[32];
    snprintf(run_id, sizeof run_id, "%d", RUN);
    setenv("FSI_RUN_ID", run_id, 1);
    setenv("FSI_OUT", tmp, 1);
    setenv("FSI_REPLAY_LOG", log_path, 1);
    setenv("FSI_REPLAY_REPORT", report, 1);

    /* The solid. Closing before the run's end returns 1 and writes the verdict. */
    fsi_participant *p = join("solid", case_path);
    CHECK(p != NULL, "the solid cannot join the replayed run");
    if (!p)
        return unit_check_report("test_participant_interface");
    fsi_interface state = {.n = N, .id = ids, .position = x, .velocity = v,
                           .acceleration = a, .volume = volume};
    CHECK(fsi_write_interface(p, &state) == -1, "a solid state without densities was sent");
    state.density = density;
    CHECK(fsi_write_interface(p, &state) == 0, "the solid state was not sent");
    fsi_close(p, NULL);
    unit_read_text(report, text, sizeof text);
    CHECK(strstr(text, "compared = 2\n") && strstr(text, "differences = 0\n"),
          "the solid's messages are not the recorded ones (register, solid state): %s", text);

    /* The fluid. */
    p = join("fluid", case_path);
    CHECK(p != NULL, "the fluid cannot join the replayed run");
    if (!p)
        return unit_check_report("test_participant_interface");
    fsi_interface got;
    fsi_read_interface(p, &got);
    CHECK(got.n == N, "the fluid received %d particles, the solid sent %d", got.n, N);
    if (got.n == N) {
        CHECK(memcmp(got.id, ids, sizeof ids) == 0, "ids differ from those sent");
        CHECK(memcmp(got.volume, volume, sizeof volume) == 0, "volumes differ from those sent");
        for (int k = 0; k < N; k++)
            CHECK(memcmp(&got.density[k], &density[k], sizeof density[k]) == 0,
                  "density %d: received %.17g kg/m^3, sent %.17g", k, got.density[k],
                  density[k]);
    }
    fsi_close(p, NULL);
    remove(log_path);
    remove(report);
    remove(case_path);
    return unit_check_report("test_participant_interface");
}
