/* The coupling protocol: message kinds, channels, flags and the rules every
 * process follows (docs/protocol.md). The message layouts are in proto/fsi.lcm. */
#ifndef FSI_PROTOCOL_H
#define FSI_PROTOCOL_H

/* Bump when proto/fsi.lcm or the rules below change incompatibly. History (also in
 * docs/protocol.md): version 2 added impedance to fluid_load_t, version 3 added
 * density to solid_state_t, version 4 the implicit coupling's verdict to done_t
 * (converged, residuals, history) and repeated windows (step_t of the same window
 * with a higher header.iteration), and coupled checkpoints (FSI_STEP_CHECKPOINT,
 * done_t.checkpoint), version 5 every done_t's stats: the sender's step and largest
 * speed of the window ("step", "max_speed"; fsi_set_progress), not only the final
 * report's timers. */
#define FSI_PROTOCOL_VERSION 5

/* Message kinds; each travels on its own channel (fsi_msg_channel). */
typedef enum {
    FSI_MSG_REGISTER = 0,
    FSI_MSG_WELCOME,
    FSI_MSG_STEP,
    FSI_MSG_SOLID_STATE,
    FSI_MSG_FLUID_LOAD,
    FSI_MSG_DONE,
    FSI_MSG_RESEND,
    FSI_MSG_HEARTBEAT,
    FSI_MSG_ABORT,
    FSI_MSG_COUNT
} fsi_msg_type;

/* step_t.flags */
enum {
    FSI_STEP_PROBE = 1,   /* sample probes at the end of the window (sent in done_t) */
    FSI_STEP_FINISH = 2,  /* the run is over: send the final done_t with stats, then close */
    FSI_STEP_CHECKPOINT = 4 /* write a coupled checkpoint of the state at this window's
                             * start (docs/checkpoints.md) */
};

/* done_t.status */
enum {
    FSI_STATUS_OK = 0,
    FSI_STATUS_FINISHED = 1
};

/* heartbeat_t.state */
enum {
    FSI_STATE_STARTING = 0,
    FSI_STATE_RUNNING = 1,
    FSI_STATE_FINISHED = 2    /* from the coupler: every final done_t arrived; exit now */
};

/* Name of the coupler on the bus (participants are named after their role). */
#define FSI_COUPLER_NAME "coupler"

/* Default LCM URL; `fsi run` uses it inside its private network namespace.
 * recv_buf_size: large interface messages arrive as bursts of fragments; with the
 * kernel default receive buffer (~200 kB) a 10000-particle window lost fragments in
 * most windows (median round trip 4 ms, p90 95 ms) against 0.7 ms with 4 MB
 * (bench/window_roundtrip.sh). The kernel caps it at net.core.rmem_max. */
#define FSI_DEFAULT_LCM_URL "udpm://239.255.76.67:7667?ttl=0&recv_buf_size=4194304"

/* Default liveness timing ([run] heartbeat_interval, watchdog_timeout, seconds of wall
 * time). 10 s, not less: on a machine running more processes than it has cores,
 * coupled runs at 3 s were stopped as hung twice (a fluid of 57 000 particles unheard
 * for 3.6 s, with the load average at 7 on 2 cores) while every process was alive. */
#define FSI_DEFAULT_HEARTBEAT_INTERVAL 0.25
#define FSI_DEFAULT_WATCHDOG_TIMEOUT 10.0

const char *fsi_msg_channel(fsi_msg_type type);
const char *fsi_msg_name(fsi_msg_type type);
/* The kind of message a channel carries, or -1 for a channel that is not ours. */
int fsi_msg_type_of_channel(const char *channel);

#endif
