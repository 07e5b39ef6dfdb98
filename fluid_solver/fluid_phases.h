/* The phases of a scheme's evaluation, each timed on its own in the run log
 * (fluid_scheme_use_timers): a scheme names them once and starts and stops them by
 * index; without timers nothing is timed. */
#ifndef FSI_FLUID_PHASES_H
#define FSI_FLUID_PHASES_H

#include "timers.h"

#define FLUID_MAX_PHASES 8

typedef struct {
    fsi_timers *timers;             /* NULL: not timed */
    int index[FLUID_MAX_PHASES];    /* each phase's index in timers */
} fluid_phases;

/* Times the n (<= FLUID_MAX_PHASES) phases named in t from now on; t NULL stops it. */
static inline void fluid_phases_use(fluid_phases *ph, fsi_timers *t, const char *const *names,
                                    int n)
{
    ph->timers = t;
    for (int k = 0; t && k < n && k < FLUID_MAX_PHASES; k++)
        ph->index[k] = fsi_timer_index(t, names[k]);
}

static inline void fluid_phase_start(const fluid_phases *ph, int k)
{
    if (ph->timers)
        fsi_timer_start(ph->timers, ph->index[k]);
}

static inline void fluid_phase_stop(const fluid_phases *ph, int k)
{
    if (ph->timers)
        fsi_timer_stop(ph->timers, ph->index[k]);
}

#endif
