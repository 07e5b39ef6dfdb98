/* Prescribed external loads of the load regions ([solid.region NAME] action = load):
 * each region's total force is spread equally over the particles it selects and
 * grows linearly from 0 over its ramp_time, then holds (quasi-static loading, S1).
 *
 * Ownership: solid_loads owns its index lists (solid_loads_free). */
#ifndef FSI_SOLID_LOADS_H
#define FSI_SOLID_LOADS_H

#include <stddef.h>
#include <stdint.h>

#include "geometry.h"

typedef struct {
    const char *section;
    int n;                      /* particles of the region */
    int32_t *index;             /* their indices */
    double each[FSI_DIM];       /* full force per particle [N] = total / n */
    double ramp_time;           /* [s] */
} solid_load_region;

typedef struct {
    int n_regions;
    solid_load_region *regions;
} solid_loads;

/* Collects the load regions of g over the particles p. Returns 0, or -1 with a
 * message (a load region without particles, out of memory). */
int solid_loads_init(solid_loads *l, const solid_geometry *g, const solid_particles *p,
                     char *msg, size_t msg_size);
void solid_loads_free(solid_loads *l);

/* Ramp factor at time t: t / ramp_time until ramp_time, then 1 (1 when ramp_time is 0). */
double solid_load_ramp(double t, double ramp_time);

/* force[i * FSI_DIM + d] += the ramped prescribed load at time t. */
void solid_loads_add(const solid_loads *l, double t, double *force);

/* The total prescribed force at time t (sum over regions), into total[FSI_DIM]. */
void solid_loads_total(const solid_loads *l, double t, double *total);

#endif
