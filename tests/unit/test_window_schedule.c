/* The coupler's window schedule: the grant is the smallest proposal, windows never
 * exceed the proposals or max_window, end exactly on every output, probe and end
 * time without slivers before them, and number frames 1, 2, ... */
#include <float.h>
#include <math.h>
#include <stdio.h>

#include "window_schedule.h"

#include "unit_check.h"

/* Runs a whole schedule and checks its invariants; returns the window count. */
static double shortest;     /* the shortest window of the last schedule run */
static double longest_short; /* its longest window below 0.99 of the proposal */

static long run_schedule(double t_end, double out, double probe, double max_window,
                         double proposal, int *frames, long *probes)
{
    shortest = INFINITY;
    longest_short = 0.0;
    fsi_window_schedule s;
    fsi_window_schedule_init(&s, t_end, out, probe, max_window);
    double t = 0.0;
    long windows = 0;
    *frames = 0;
    *probes = 0;
    for (;;) {
        fsi_window_plan p = fsi_window_schedule_next(&s, t, proposal);
        windows++;
        CHECK(p.dt > 0, "window %ld has dt %g", windows, p.dt);
        shortest = fmin(shortest, p.dt);
        if (p.dt < 0.99 * fmin(proposal, max_window))
            longest_short = fmax(longest_short, p.dt);
        CHECK(p.dt <= fmin(proposal, max_window) * (1 + 1e-12), "dt %.17g exceeds %.17g",
              p.dt, fmin(proposal, max_window));
        if (p.frame >= 0) {
            (*frames)++;
            CHECK(p.frame == *frames, "frame %d where %d expected", p.frame, *frames);
            /* Frame times are exact multiples, not sums of windows. */
            CHECK(p.t_next == p.frame * out || p.last, "frame %d at %.17g, not %.17g", p.frame,
                  p.t_next, p.frame * out);
        }
        if (p.probe)
            (*probes)++;
        t = p.t_next;
        if (p.last)
            break;
        CHECK(windows < 10000000, "schedule does not end");
        if (windows >= 10000000)
            break;
    }
    CHECK(t == t_end, "ends at %.17g instead of %.17g", t, t_end);
    return windows;
}

/* The grant of proposals p[0..n-1] must be the smallest: a larger one is a window
 * over which some participant is not stable. */
static void check_grant(const double *p, int n, double expected)
{
    double g = fsi_window_smallest_proposal(p, n);
    CHECK(g == expected, "grant of %d proposals is %g s, not the smallest %g s: a "
          "participant would run beyond its stable step", n, g, expected);
}

int main(void)
{
    int frames;
    long probes;

    const double fluid_first[] = {2.8e-5, 1e-3}, solid_first[] = {1e-3, 2.8e-5};
    check_grant(fluid_first, 2, 2.8e-5);
    check_grant(solid_first, 2, 2.8e-5);
    const double three[] = {4e-4, 1e-4, 7e-4};
    check_grant(three, 3, 1e-4);
    const double one[] = {3e-4};
    check_grant(one, 1, 3e-4);
    CHECK(fsi_window_smallest_proposal(NULL, 0) == DBL_MAX, "no proposal grants %g s",
          fsi_window_smallest_proposal(NULL, 0));
    /* The grant then bounds the window the schedule plans. */
    fsi_window_schedule g;
    fsi_window_schedule_init(&g, 1.0, 0.1, 0.0, 1e-3);
    fsi_window_plan gp = fsi_window_schedule_next(&g, 0.0,
                                                  fsi_window_smallest_proposal(solid_first, 2));
    CHECK(gp.dt == 2.8e-5, "the window after a grant of 2.8e-5 s is %g s", gp.dt);

    /* Proposal below max_window: 0.004 s windows, frames every 0.1 s, probes every 0.03 s. */
    long w = run_schedule(1.0, 0.1, 0.03, 0.007, 0.004, &frames, &probes);
    CHECK(frames == 10, "%d frames, expected 10", frames);
    /* Probe rows: 33 multiples of 0.03 up to 0.99, plus frames not on them, plus the end.
     * Multiples of 0.03 that are also frame times (0.3, 0.6, 0.9) count once. */
    CHECK(probes == 33 + 10 - 3, "%ld probe rows, expected 40", probes);
    /* 250 windows of 0.004 s, plus the extra cuts at probe times not on the 0.004 grid. */
    CHECK(w >= 250 && w <= 250 + 40, "%ld windows", w);

    /* No sliver before a probe time: 0.007 s windows would leave 0.002 s before 0.03;
     * the two windows up to it share the remainder, so none is shorter than half the
     * proposal (the events are 0.01 s apart or more). */
    w = run_schedule(1.0, 0.1, 0.03, 0.007, 0.007, &frames, &probes);
    CHECK(shortest >= 0.5 * 0.007 * (1 - 1e-12), "a window of %g s, below half the "
          "proposal 0.007 s", shortest);
    CHECK(frames == 10 && probes == 40, "%d frames and %ld probe rows, expected 10 and 40",
          frames, probes);
    /* A remainder of exactly half a window keeps its full window whatever the last bits
     * of the sums: 2e-4 s windows against probes every 5e-4 s go 2, 2, 1 (1e-4 s the
     * shortest), not 2, 1.5, 1.5 where the sum falls a bit short. */
    w = run_schedule(0.2, 0.02, 5e-4, 2e-4, 2e-4, &frames, &probes);
    CHECK(w == 1200 && longest_short < 1e-4 * (1 + 1e-9), "%ld windows, a window before a "
          "probe time of %.17g s: expected 1200, each 2e-4 or 1e-4 s (C4's schedule)", w,
          longest_short);

    /* max_window below the proposal. */
    w = run_schedule(0.5, 0.25, 0.0, 0.01, 1.0, &frames, &probes);
    CHECK(w == 50, "%ld windows, expected 50", w);
    CHECK(frames == 2, "%d frames, expected 2", frames);
    CHECK(probes == 50, "probe_interval 0 gives %ld probe rows, expected one per window", probes);

    /* An end time that is not a multiple of the output interval. */
    w = run_schedule(0.33, 0.1, 0.1, 0.05, 0.05, &frames, &probes);
    CHECK(frames == 4, "%d frames, expected 0.1, 0.2, 0.3 and the final state", frames);
    CHECK(probes == 4, "%ld probe rows, expected 0.1, 0.2, 0.3 and the end", probes);

    /* Windows of 0.1 s summed in floating point would miss 0.3 exactly; the schedule must
     * still land on it rather than leave a 1e-17 s sliver. */
    w = run_schedule(1.0, 0.1, 0.1, 0.1, 0.1, &frames, &probes);
    CHECK(w == 10, "%ld windows of 0.1 s, expected 10 (a sliver window appeared)", w);

    if (failures) {
        printf("%d check(s) failed\n", failures);
        return 1;
    }
    printf("window schedule: all checks passed\n");
    return 0;
}
