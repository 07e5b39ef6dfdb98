/* When to ask again for a message that has not arrived (docs/protocol.md,
 * "Reliability"): not before it is overdue, judged against how long this kind of wait
 * took before, then again at short, slowly growing intervals.
 *
 * The estimate is TCP's retransmission timeout (RFC 6298): a smoothed wait and its
 * mean deviation, updated only from waits that ended with the original message; a
 * wait that ended with a resent copy says nothing about when the original would have
 * come (Karn's rule). A message is taken for an original when its sequence number is
 * newer than any seen from its sender (fsi_bus_message_is_new). */
#ifndef FSI_REQUEST_TIMER_H
#define FSI_REQUEST_TIMER_H

/* First request of a wait never before this [s]: below it, a loss-free run on a
 * loaded machine would ask for messages that are only late. */
#define FSI_REQUEST_OVERDUE_MIN_S 0.002
/* ... and never later than this [s], however long such waits took before. */
#define FSI_REQUEST_OVERDUE_MAX_S 1.0
/* Before any wait of this kind was measured. */
#define FSI_REQUEST_OVERDUE_FIRST_S 0.01
/* From this measured loss on, a message that arrived after requests may have been a
 * resent copy even when it looks new (see fsi_request_timer_arrived); below it, it
 * was late, and the estimate learns that fully. */
#define FSI_REQUEST_LATE_IS_LOST_FROM 0.02
/* Repeated requests: a first interval, then growth by a factor to a cap. On a bus
 * that loses messages, growth by 1.5 to 20 ms: it keeps the expected recovery time
 * finite for a per-attempt failure up to 2/3, where doubling diverges above 1/2 and
 * heavy loss ended at the cap. On a loss-free bus a missing message is late, not
 * lost (the first request finds a lost one), so the repeats start at the overdue
 * time and double to 0.25 s: a partner's long computation costs a few requests, not
 * 50 a second. */
#define FSI_REQUEST_REPEAT_FIRST_S 0.0005
#define FSI_REQUEST_REPEAT_GROWTH_LOSSY 1.5
#define FSI_REQUEST_REPEAT_MAX_LOSSY_S 0.02
#define FSI_REQUEST_REPEAT_GROWTH 2.0
#define FSI_REQUEST_REPEAT_MAX_S 0.25

/* How long one kind of wait has taken. Zero-initialised: nothing measured yet. */
typedef struct {
    double smoothed, deviation;   /* [s] */
    int samples;
} fsi_wait_estimate;

/* One wait. */
typedef struct {
    fsi_wait_estimate *estimate;
    double started, overdue, next_request, interval;
    double growth, interval_max;
    int lossy;         /* repeating on the schedule for a bus that loses messages */
    int requests;
} fsi_request_timer;

/* The overdue time of the next wait of this kind [s]; 'e' may be NULL (not measured). */
double fsi_wait_overdue(const fsi_wait_estimate *e);

/* 'e' may be NULL: the wait is not measured. 'measured_loss' is the bus's
 * (fsi_bus_measured_loss). */
void fsi_request_timer_start(fsi_request_timer *t, fsi_wait_estimate *e, double now,
                             double measured_loss);
/* 1 when a request is due at 'now' (and schedules the next one), else 0. A wait
 * that started on a loss-free bus turns to the lossy schedule once loss is measured. */
int fsi_request_timer_due(fsi_request_timer *t, double now, double measured_loss);
/* The message arrived at 'now'; 'original' is 0 when it was a resent copy;
 * 'measured_loss' is the bus's (fsi_bus_measured_loss). */
void fsi_request_timer_arrived(fsi_request_timer *t, double now, int original,
                               double measured_loss);

#endif
