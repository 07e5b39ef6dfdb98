/* The replay transport (core/bus_replay.h) on a hand-made traffic log: which
 * recorded messages a participant gets and when, what is compared and what is
 * not, a message recorded late because it was lost and resent, and the verdict;
 * a solid state whose density differs from the recorded one in the last bit is
 * reported by that field. */
#include <lcm/eventlog.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "bus_replay.h"
#include "messages.h"

#include "unit_check.h"
#include "unit_traffic_log.h"

#define RUN 4242

static double probe = 0.5, force[2] = {1.0, -2.0}, pressure[1] = {3.0};
/* Three components, enough for FSI_DIM 2 or 3. */
static double state_x[3] = {0.1, 0.2, 0.3}, state_v[3] = {0.0, -1e-3, 0.0},
              state_a[3] = {0.0, 9.81, 0.0}, state_volume[1] = {1e-4};
static int32_t ids[1] = {7};
static char *probe_names[1] = {"p"};
static char *names[2] = {"fluid", "solid"}, *roles[2] = {"fluid", "solid"};

static fsi_register_t reg(const char *host, int pid)
{
    fsi_register_t r = {0};
    r.role = "fluid";
    r.host = (char *)host;
    r.pid = pid;
    r.dt_proposed = 1e-3;
    r.n_probes = 1;
    r.probe_names = probe_names;
    return r;
}

static fsi_fluid_load_t load(void)
{
    fsi_fluid_load_t m = {0};
    m.dim = FSI_DIM;
    m.n = 1;
    m.n_components = FSI_DIM;
    m.id = ids;
    m.pressure = pressure;
    m.force = force;
    return m;
}

static fsi_done_t done(double *value)
{
    fsi_done_t d = {0};
    d.dt_next_max = 1e-3;
    d.n_probes = 1;
    d.probe_values = value;
    d.message = "";
    return d;
}

static fsi_welcome_t welcome(const char *participant)
{
    fsi_welcome_t w = {0};
    w.participant = (char *)participant;
    w.n_participants = 2;
    w.participant_names = names;
    w.participant_roles = roles;
    return w;
}

static fsi_step_t step(double t, double dt)
{
    fsi_step_t s = {0};
    s.t = t;
    s.dt = dt;
    s.frame = -1;
    return s;
}

/* The fluid's side of a run whose fluid_load of window 0 was lost once: the log
 * holds its resent copy after the fluid's done, and then a duplicate. */
static void write_log(const char *path)
{
    lcm_eventlog_t *log = lcm_eventlog_create(path, "w");
    fsi_register_t r = reg("recorded-host", 100);
    unit_log_put(log, FSI_MSG_REGISTER, &r, "fluid", RUN, -1, 1);
    fsi_register_t again = reg("recorded-host", 100);
    unit_log_put(log, FSI_MSG_REGISTER, &again, "fluid", RUN, -1, 2);
    fsi_welcome_t w = welcome("solid");
    unit_log_put(log, FSI_MSG_WELCOME, &w, "coupler", RUN, -1, 1);
    w = welcome("fluid");
    unit_log_put(log, FSI_MSG_WELCOME, &w, "coupler", RUN, -1, 2);
    fsi_step_t s0 = step(0.0, 0.0);
    unit_log_put(log, FSI_MSG_STEP, &s0, "coupler", RUN, 0, 3);
    fsi_heartbeat_t hb = {0};
    hb.state = FSI_STATE_RUNNING;
    unit_log_put(log, FSI_MSG_HEARTBEAT, &hb, "coupler", RUN, 0, 4);
    fsi_solid_state_t ss = {0};
    ss.dim = FSI_DIM;
    unit_log_put(log, FSI_MSG_SOLID_STATE, &ss, "solid", RUN, 0, 1);
    double recorded_probe = probe;
    fsi_done_t d = done(&recorded_probe);
    unit_log_put(log, FSI_MSG_DONE, &d, "fluid", RUN, 0, 5);
    fsi_fluid_load_t l = load();
    unit_log_put(log, FSI_MSG_FLUID_LOAD, &l, "fluid", RUN, 0, 3);
    fsi_step_t foreign = step(9.0, 9.0);
    unit_log_put(log, FSI_MSG_STEP, &foreign, "coupler", RUN + 1, 1, 9);
    fsi_step_t s1 = step(0.0, 1e-3);
    unit_log_put(log, FSI_MSG_STEP, &s1, "coupler", RUN, 1, 5);
    unit_log_put(log, FSI_MSG_FLUID_LOAD, &l, "fluid", RUN, 0, 3);
    lcm_eventlog_destroy(log);
}

/* The solid's side of a window whose fluid_load the recorder logged after the
 * solid's done of that window (datagrams from two senders reach the recorder in
 * either order), with step 1 before that load. */
static void write_late_input_log(const char *path)
{
    lcm_eventlog_t *log = lcm_eventlog_create(path, "w");
    fsi_welcome_t w = welcome("solid");
    unit_log_put(log, FSI_MSG_WELCOME, &w, "coupler", RUN, -1, 1);
    fsi_step_t s0 = step(0.0, 0.0);
    unit_log_put(log, FSI_MSG_STEP, &s0, "coupler", RUN, 0, 2);
    double density = 2700.0;
    fsi_solid_state_t ss =
        unit_solid_state(1, ids, state_x, state_v, state_a, state_volume, &density);
    unit_log_put(log, FSI_MSG_SOLID_STATE, &ss, "solid", RUN, 0, 1);
    double value = probe;
    fsi_done_t d = done(&value);
    unit_log_put(log, FSI_MSG_DONE, &d, "solid", RUN, 0, 2);
    fsi_step_t s1 = step(0.0, 1e-3);
    unit_log_put(log, FSI_MSG_STEP, &s1, "coupler", RUN, 1, 3);
    fsi_fluid_load_t l = load();
    unit_log_put(log, FSI_MSG_FLUID_LOAD, &l, "fluid", RUN, 0, 1);
    lcm_eventlog_destroy(log);
}

/* The kinds of the inputs due now, as a string of kind initials; 'waiting' as a
 * participant blocked in fsi_bus_poll, else as one draining the bus. */
static void due_as(fsi_replay *r, int waiting, char *kinds, size_t len)
{
    size_t n = 0;
    fsi_msg_type type;
    const void *bytes;
    int size;
    while (n + 1 < len && fsi_replay_next_input(r, waiting, &type, &bytes, &size))
        kinds[n++] = fsi_msg_name(type)[0];
    kinds[n] = '\0';
}

static void due(fsi_replay *r, char *kinds, size_t len)
{
    due_as(r, 0, kinds, len);
}

static void publish_as(fsi_replay *r, const char *self, fsi_msg_type type, void *msg,
                       int window, int64_t seq)
{
    unit_set_header(msg, self, RUN, window, seq);
    fsi_replay_compare(r, type, msg);
}

static void publish(fsi_replay *r, fsi_msg_type type, void *msg, int window, int64_t seq)
{
    publish_as(r, "fluid", type, msg, window, seq);
}

int main(void)
{
    const char *tmp = getenv("FSI_TEST_TMP") ? getenv("FSI_TEST_TMP") : ".";
    char log_path[512], report[512], text[2048], kinds[16];
    snprintf(log_path, sizeof log_path, "%s/test_bus_replay.lcmlog", tmp);
    snprintf(report, sizeof report, "%s/test_bus_replay.report", tmp);
    mkdir(tmp, 0755);   /* ctest's scratch folder; may exist already */
    write_log(log_path);
    setenv("FSI_REPLAY_REPORT", report, 1);

    CHECK(fsi_replay_open("no/such.lcmlog", "fluid", RUN) == NULL, "a missing log opened");
    CHECK(fsi_replay_open(log_path, "fluid", RUN + 7) == NULL, "another run's replay opened");
    CHECK(fsi_replay_open(log_path, "nobody", RUN) == NULL, "a replay of nobody opened");

    fsi_replay *r = fsi_replay_open(log_path, "fluid", RUN);
    CHECK(r != NULL, "cannot open the replay");
    if (!r)
        return unit_check_report("test_bus_replay");
    due(r, kinds, sizeof kinds);
    CHECK(strcmp(kinds, "") == 0, "due before the register: '%s'", kinds);
    /* pid, host and seq are the machine's, not the computation's. */
    fsi_register_t mine = reg("another-host", 200);
    publish(r, FSI_MSG_REGISTER, &mine, -1, 1);
    publish(r, FSI_MSG_REGISTER, &mine, -1, 2);   /* a repeat: not compared */
    due(r, kinds, sizeof kinds);
    /* welcome (for us only), step 0, solid state 0; not the heartbeat */
    CHECK(strcmp(kinds, "wss") == 0, "due after the register: '%s'", kinds);
    fsi_fluid_load_t l = load();
    publish(r, FSI_MSG_FLUID_LOAD, &l, 0, 3);     /* recorded only after the done */
    due(r, kinds, sizeof kinds);
    CHECK(strcmp(kinds, "") == 0, "due before the done: '%s'", kinds);
    double changed = probe + 1e-12;
    fsi_done_t d = done(&changed);
    publish(r, FSI_MSG_DONE, &d, 0, 4);
    due(r, kinds, sizeof kinds);
    CHECK(strcmp(kinds, "s") == 0, "due after the done: '%s' (step 1 only)", kinds);
    CHECK(fsi_replay_finish(r) == 1, "differences: expected 1 (the probe)");
    fsi_replay_free(r);
    unit_read_text(report, text, sizeof text);
    CHECK(strstr(text, "compared = 3\n") != NULL, "report: %s", text);
    CHECK(strstr(text, "differences = 1\n") != NULL, "report: %s", text);
    CHECK(strstr(text, "first_difference_window = 0\n") != NULL, "report: %s", text);
    CHECK(strstr(text, "first_difference = done of window 0: probe_values[0] = "
                       "0.50000000000099998, recorded 0.5\n") != NULL,
          "report: %s", text);

    /* A participant that stops early: its recorded messages count as missing. */
    r = fsi_replay_open(log_path, "fluid", RUN);
    publish(r, FSI_MSG_REGISTER, &mine, -1, 1);
    CHECK(fsi_replay_finish(r) == 2, "a replay that stopped early: expected 2 differences");
    fsi_replay_free(r);
    unit_read_text(report, text, sizeof text);
    CHECK(strstr(text, "missing = 2\n") != NULL, "report: %s", text);
    CHECK(strstr(text, "first_difference = done of window 0 is recorded but was not "
                       "published\n") != NULL,
          "report: %s", text);

    /* The load of window 0, logged after the solid's done of window 0 and after
     * step 1, is due before that done; step 1 only after it. */
    write_late_input_log(log_path);
    r = fsi_replay_open(log_path, "solid", RUN);
    CHECK(r != NULL, "cannot open the late-input replay");
    if (!r)
        return unit_check_report("test_bus_replay");
    due(r, kinds, sizeof kinds);
    CHECK(strcmp(kinds, "ws") == 0, "late input: due at the start: '%s'", kinds);
    double density = 2700.0;
    fsi_solid_state_t state =
        unit_solid_state(1, ids, state_x, state_v, state_a, state_volume, &density);
    publish_as(r, "solid", FSI_MSG_SOLID_STATE, &state, 0, 1);
    due(r, kinds, sizeof kinds);
    CHECK(strcmp(kinds, "") == 0, "late input: due to a drain before the done: '%s'", kinds);
    due_as(r, 1, kinds, sizeof kinds);
    CHECK(strcmp(kinds, "f") == 0, "late input: due to a wait before the done: '%s'", kinds);
    double same = probe;
    fsi_done_t solid_done = done(&same);
    publish_as(r, "solid", FSI_MSG_DONE, &solid_done, 0, 2);
    due(r, kinds, sizeof kinds);
    CHECK(strcmp(kinds, "s") == 0, "late input: due after the done: '%s'", kinds);
    CHECK(fsi_replay_finish(r) == 0, "late input: differences in an identical replay");
    fsi_replay_free(r);

    /* The same window with the density one bit off: named as that field. */
    r = fsi_replay_open(log_path, "solid", RUN);
    due(r, kinds, sizeof kinds);
    density = nextafter(2700.0, 3000.0);
    state = unit_solid_state(1, ids, state_x, state_v, state_a, state_volume, &density);
    publish_as(r, "solid", FSI_MSG_SOLID_STATE, &state, 0, 1);
    due_as(r, 1, kinds, sizeof kinds);
    publish_as(r, "solid", FSI_MSG_DONE, &solid_done, 0, 2);
    CHECK(fsi_replay_finish(r) == 1, "a changed density: expected 1 difference");
    fsi_replay_free(r);
    unit_read_text(report, text, sizeof text);
    CHECK(strstr(text, "first_difference = solid_state of window 0: density[0] = "
                       "2700.0000000000005, recorded 2700\n") != NULL,
          "report: %s", text);
    return unit_check_report("test_bus_replay");
}
