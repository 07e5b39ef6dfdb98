#include "timers.h"

#include <string.h>
#include <time.h>

double fsi_wall_seconds(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

int fsi_timer_index(fsi_timers *t, const char *name)
{
    for (int i = 0; i < t->n; i++)
        if (strcmp(t->name[i], name) == 0)
            return i;
    if (t->n == FSI_TIMERS_MAX)
        return FSI_TIMERS_MAX - 1;
    t->name[t->n] = name;
    t->seconds[t->n] = 0.0;
    return t->n++;
}

void fsi_timer_start(fsi_timers *t, int phase)
{
    t->started[phase] = fsi_wall_seconds();
}

void fsi_timer_stop(fsi_timers *t, int phase)
{
    t->seconds[phase] += fsi_wall_seconds() - t->started[phase];
}
