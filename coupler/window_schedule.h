/* Which window comes next: the participants' proposals, the largest window the case
 * allows, and the output, probe and end times, which windows end on exactly so
 * that fluid and solid frames line up in time. */
#ifndef FSI_WINDOW_SCHEDULE_H
#define FSI_WINDOW_SCHEDULE_H

typedef struct {
    double t_end;
    double output_interval;   /* frames at j * output_interval, j = 1, 2, ... */
    double probe_interval;    /* probe rows at i * probe_interval; 0: every window */
    double max_window;
    long next_frame;          /* j of the next output time */
    long next_probe;          /* i of the next probe time */
} fsi_window_schedule;

typedef struct {
    double dt;
    double t_next;            /* t + dt, set exactly to an event time when one is hit */
    int frame;                /* output frame at the end of the window, or -1 */
    int probe;                /* sample probes at the end of the window */
    int last;                 /* the window ends at t_end */
} fsi_window_plan;

void fsi_window_schedule_init(fsi_window_schedule *s, double t_end, double output_interval,
                              double probe_interval, double max_window);

/* The grant: the smallest of the n participants' proposals for the next window
 * (every one of them must stay stable over it), DBL_MAX when n is 0. */
double fsi_window_smallest_proposal(const double *proposals, int n);

/* The window after time t, given the smallest proposal of the participants. */
fsi_window_plan fsi_window_schedule_next(fsi_window_schedule *s, double t, double dt_proposed);

#endif
