#include "window_schedule.h"

#include <float.h>
#include <math.h>

/* Event times closer than this fraction of a window count as hit: floating-point
 * sums of windows must not leave slivers of 1e-17 s before an output time. */
#define EVENT_TOLERANCE 1e-9

void fsi_window_schedule_init(fsi_window_schedule *s, double t_end, double output_interval,
                              double probe_interval, double max_window)
{
    s->t_end = t_end;
    s->output_interval = output_interval;
    s->probe_interval = probe_interval;
    s->max_window = max_window;
    s->next_frame = 1;
    s->next_probe = 1;
}

double fsi_window_smallest_proposal(const double *proposals, int n)
{
    double dt = DBL_MAX;
    for (int i = 0; i < n; i++)
        dt = fmin(dt, proposals[i]);
    return dt;
}

static double frame_time(const fsi_window_schedule *s)
{
    return s->output_interval > 0 ? (double)s->next_frame * s->output_interval : INFINITY;
}

static double probe_time(const fsi_window_schedule *s)
{
    return s->probe_interval > 0 ? (double)s->next_probe * s->probe_interval : INFINITY;
}

fsi_window_plan fsi_window_schedule_next(fsi_window_schedule *s, double t, double dt_proposed)
{
    double dt = fmin(dt_proposed, s->max_window);
    double t_event = fmin(s->t_end, fmin(frame_time(s), probe_time(s)));
    fsi_window_plan plan = {dt, t + dt, -1, s->probe_interval <= 0, 0};
    if (t + dt < t_event - EVENT_TOLERANCE * dt) {
        /* A full window would leave less than half a window before the event: the two
         * windows up to it share the remainder instead. A sliver of a window is a
         * sliver of a step, and a projection scheme's pressure grows as 1 / dt there
         * (ISPH's load on C1's plate rose tenfold in windows of a fifth of the others,
         * docs/isph.md); windows stay at least half the proposal. A remainder of half
         * a window up to round-off keeps its full window: windows that divide the
         * event interval into whole and half windows (2e-4 s against probes every
         * 5e-4 s) keep that pattern instead of one decided by the sums' last bits
         * (which made C4's ISPH + TLSPH plate unstable at 0.18 s, docs/isph.md). */
        if (t_event - t < (1.5 - EVENT_TOLERANCE) * dt) {
            plan.dt = 0.5 * (t_event - t);
            plan.t_next = t + plan.dt;
        }
        return plan;
    }

    /* Several events can fall on one time (a frame that is also a probe time); the
     * window then ends on the frame's own exact multiple, which outputs line up on. */
    double tol = EVENT_TOLERANCE * fmax(dt, 1e-300);
    if (fabs(frame_time(s) - t_event) <= tol) {
        t_event = frame_time(s);
        plan.frame = (int)s->next_frame++;
        plan.probe = 1;
    }
    while (probe_time(s) <= t_event + tol) {
        s->next_probe++;
        plan.probe = 1;
    }
    if (t_event >= s->t_end - tol) {
        /* The final state is always written and probed, whatever the intervals. */
        t_event = s->t_end;
        plan.last = 1;
        plan.probe = 1;
        if (plan.frame < 0)
            plan.frame = (int)s->next_frame++;
    }
    plan.t_next = t_event;
    plan.dt = t_event - t;
    return plan;
}
