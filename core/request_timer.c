#include "request_timer.h"

#include <math.h>

double fsi_wait_overdue(const fsi_wait_estimate *e)
{
    if (!e || e->samples == 0)
        return FSI_REQUEST_OVERDUE_FIRST_S;
    double rto = e->smoothed + 4.0 * e->deviation;
    return fmin(fmax(rto, FSI_REQUEST_OVERDUE_MIN_S), FSI_REQUEST_OVERDUE_MAX_S);
}

/* The repeat schedule for the loss the bus measures now. */
static void set_schedule(fsi_request_timer *t, double measured_loss)
{
    t->lossy = measured_loss >= FSI_REQUEST_LATE_IS_LOST_FROM;
    t->growth = t->lossy ? FSI_REQUEST_REPEAT_GROWTH_LOSSY : FSI_REQUEST_REPEAT_GROWTH;
    t->interval_max = t->lossy ? FSI_REQUEST_REPEAT_MAX_LOSSY_S : FSI_REQUEST_REPEAT_MAX_S;
    /* On a loss-free bus the first request finds a lost message; when it does not,
     * the message is late, and asking again sooner than it was overdue is noise. */
    double first = t->lossy ? FSI_REQUEST_REPEAT_FIRST_S : fmin(t->overdue, t->interval_max);
    t->interval = t->requests == 0 ? first : fmin(t->interval, t->interval_max);
}

void fsi_request_timer_start(fsi_request_timer *t, fsi_wait_estimate *e, double now,
                             double measured_loss)
{
    t->estimate = e;
    t->started = now;
    t->overdue = fsi_wait_overdue(e);
    t->next_request = now + t->overdue;
    t->requests = 0;
    set_schedule(t, measured_loss);
}

int fsi_request_timer_due(fsi_request_timer *t, double now, double measured_loss)
{
    /* Loss found during a long wait (the first one: registration) shortens it. */
    if (!t->lossy && measured_loss >= FSI_REQUEST_LATE_IS_LOST_FROM) {
        set_schedule(t, measured_loss);
        t->next_request = fmin(t->next_request, now + t->interval);
    }
    if (now < t->next_request)
        return 0;
    t->requests++;
    t->next_request = now + t->interval;
    t->interval = fmin(t->interval * t->growth, t->interval_max);
    return 1;
}

/* RFC 6298, section 2: gains 1/8 for the mean and 1/4 for the deviation. */
void fsi_request_timer_arrived(fsi_request_timer *t, double now, int original,
                               double measured_loss)
{
    fsi_wait_estimate *e = t->estimate;
    if (!original || !e)
        return;
    double s = fmax(now - t->started, 0.0);
    /* After requests, on a bus that loses messages, an original from a sender none
     * of whose later messages got through cannot be told from a resent copy, whose
     * wait includes a recovery: no sample (Karn). Feeding such waits in, even
     * clipped, ratchets the estimate up to its cap at 80 % loss. */
    if (t->requests > 0 && measured_loss >= FSI_REQUEST_LATE_IS_LOST_FROM)
        return;
    if (e->samples == 0) {
        e->smoothed = s;
        e->deviation = s / 2;
    } else {
        e->deviation = 0.75 * e->deviation + 0.25 * fabs(e->smoothed - s);
        e->smoothed = 0.875 * e->smoothed + 0.125 * s;
    }
    e->samples++;
}
