/* Progress line of a running case: simulated time, percent, windows per second, the
 * caller's detail (the step sizes and largest speeds), and the estimated time left,
 * printed at most every interval seconds of wall time. */
#ifndef FSI_PROGRESS_H
#define FSI_PROGRESS_H

#include <stddef.h>
#include <stdio.h>

typedef struct {
    FILE *out;
    double interval;
    double t_end;
    double wall_start;
    double wall_last;
    long windows_last;
    int tty;
    /* Printed between the rate and the elapsed time when not empty: the coupler's
     * window and what the participants report of their steps and speeds. */
    char detail[256];
} fsi_progress;

/* Durations from this on (a thousand hours) are not worth a number: the ETA of a run
 * that has barely started. */
#define FSI_PROGRESS_MAX_SECONDS 3.6e6

/* "H:MM:SS" of s seconds into buf, or "--:--:--" when s is negative, not a number or
 * at least FSI_PROGRESS_MAX_SECONDS. */
void fsi_duration_text(char *buf, size_t len, double s);

void fsi_progress_init(fsi_progress *p, FILE *out, double interval, double t_end);
/* Prints when the interval has passed (or always when force is set). */
void fsi_progress_update(fsi_progress *p, double t, long windows, int force);

#endif
