/* `fsi-record URL FILE`: writes every message on an LCM network to FILE in LCM's
 * event-log format (what `fsi run --log-traffic` starts, `fsi inspect` reads and
 * `fsi replay` replays), until SIGINT or SIGTERM.
 *
 * Why not lcm-logger: a replay needs every message, and nobody asks again for what
 * a listener missed. LCM queues at most 30 received messages per subscription by
 * default and drops the rest; lcm-logger 1.3 keeps that limit, and when it was not
 * scheduled for a few milliseconds it lost bursts of messages (2 to 14 of the 300
 * steps in about half of the 0.3 s demo runs on 2 cores). This recorder lifts the
 * limit; the kernel's receive buffer (recv_buf_size of the URL) is the only one. */
#include <lcm/eventlog.h>
#include <lcm/lcm.h>
#include <signal.h>
#include <stdio.h>
#include <string.h>

#include "cli_args.h"
#include "log.h"
#include "timers.h"

/* The file is flushed this often, so a run's log can be read while it runs and
 * holds everything but the last moments after a crash. */
#define FLUSH_INTERVAL_S 0.05

static volatile sig_atomic_t stop;
static long write_failures;

static void on_signal(int sig)
{
    (void)sig;
    stop = 1;
}

static void record(const lcm_recv_buf_t *rbuf, const char *channel, void *user)
{
    lcm_eventlog_event_t e = {0};
    e.timestamp = rbuf->recv_utime;
    e.channellen = (int32_t)strlen(channel);
    e.datalen = (int32_t)rbuf->data_size;
    e.channel = (char *)channel;
    e.data = rbuf->data;
    lcm_eventlog_t *log = *(lcm_eventlog_t **)user;
    if (lcm_eventlog_write_event(log, &e) != 0)
        write_failures++;
}

static void usage(FILE *out)
{
    fprintf(out, "usage: fsi-record LCM_URL FILE   (started by fsi run --log-traffic)\n");
}

int main(int argc, char **argv)
{
    fsi_log_set_name("fsi record");
    const char *positional[2] = {NULL, NULL};
    int n = 0;
    fsi_args a = fsi_args_begin(argc, argv, "fsi-record", usage);
    while (fsi_args_next(&a)) {
        if (fsi_arg_positional(&a) && n < 2)
            positional[n++] = a.arg;
        else
            fsi_arg_unknown(&a);
    }
    if (a.error || n != 2) {
        if (!a.error)
            usage(stderr);
        return FSI_EXIT_BAD_INPUT;
    }
    const char *url = positional[0], *path = positional[1];
    struct sigaction sa = {0};
    sa.sa_handler = on_signal;
    sigaction(SIGINT, &sa, NULL);
    sigaction(SIGTERM, &sa, NULL);
    lcm_t *lcm = lcm_create(url);
    if (!lcm) {
        fsi_error("cannot open LCM URL '%s'", url);
        return FSI_EXIT_RUN_FAILURE;
    }
    /* The file appears only once we listen: `fsi run` waits for it before it starts
     * anyone, so that the first message is recorded too. */
    static lcm_eventlog_t *log;   /* messages are handled only once it is open */
    lcm_subscription_t *all = lcm_subscribe(lcm, ".*", record, &log);
    if (!all || lcm_subscription_set_queue_capacity(all, 0) != 0 ||
        !(log = lcm_eventlog_create(path, "w"))) {
        fsi_error("cannot record '%s' to %s", url, path);
        lcm_destroy(lcm);
        return FSI_EXIT_RUN_FAILURE;
    }
    double next_flush = fsi_wall_seconds() + FLUSH_INTERVAL_S;
    int rc = 0;
    while (!stop && rc >= 0) {
        rc = lcm_handle_timeout(lcm, 10);
        if (fsi_wall_seconds() >= next_flush) {
            fflush(log->f);
            next_flush = fsi_wall_seconds() + FLUSH_INTERVAL_S;
        }
    }
    /* Whatever arrived before the stop is still recorded. */
    while (rc >= 0 && lcm_handle_timeout(lcm, 0) > 0)
        ;
    lcm_eventlog_destroy(log);
    lcm_destroy(lcm);
    if (write_failures)
        fsi_error("%ld messages could not be written to %s", write_failures, path);
    return rc < 0 || write_failures ? FSI_EXIT_RUN_FAILURE : FSI_EXIT_OK;
}
