/* Named wall-clock phase timers (monotonic clock), reported in the run log. */
#ifndef FSI_TIMERS_H
#define FSI_TIMERS_H

#define FSI_TIMERS_MAX 32

typedef struct {
    int n;
    const char *name[FSI_TIMERS_MAX];
    double seconds[FSI_TIMERS_MAX];
    double started[FSI_TIMERS_MAX];
} fsi_timers;

double fsi_wall_seconds(void);

/* Returns the index of the named phase, adding it on first use. */
int fsi_timer_index(fsi_timers *t, const char *name);
void fsi_timer_start(fsi_timers *t, int phase);
void fsi_timer_stop(fsi_timers *t, int phase);

#endif
