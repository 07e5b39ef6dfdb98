/* Periodic boundaries: which axes wrap, and over what interval. One description is
 * shared by the neighbour grid (which finds neighbours across the boundary) and by
 * every pair computation (which takes the minimum image of x_J - x_I).
 *
 * Along a periodic axis d the domain is [lo[d], lo[d] + length[d]); a particle that
 * leaves at one end re-enters at the other. The minimum image is exact as long as the
 * interaction radius is below length / 2 (the grid asks for three cells per period). */
#ifndef FSI_PERIODIC_H
#define FSI_PERIODIC_H

#include <math.h>

#include "dim.h"

typedef struct {
    int on[FSI_DIM];            /* 1: axis d is periodic */
    double lo[FSI_DIM];         /* start of the period [m] */
    double length[FSI_DIM];     /* period [m], > 0 where on */
} fsi_periodic;

/* True when some axis is periodic (a NULL description has none). */
static inline int fsi_periodic_any(const fsi_periodic *per)
{
    if (!per)
        return 0;
    for (int d = 0; d < FSI_DIM; d++)
        if (per->on[d])
            return 1;
    return 0;
}

/* rel = x_J - x_I becomes the shortest of its periodic images. */
static inline void fsi_periodic_min_image(const fsi_periodic *per, double *rel)
{
    if (!per)
        return;
    for (int d = 0; d < FSI_DIM; d++)
        if (per->on[d])
            rel[d] -= per->length[d] * floor(rel[d] / per->length[d] + 0.5);
}

/* Coordinate v along periodic axis d moved into [lo, lo + length). */
static inline double fsi_periodic_wrap_axis(const fsi_periodic *per, int d, double v)
{
    const double lo = per->lo[d], length = per->length[d];
    v -= length * floor((v - lo) / length);
    /* Round-off can land an ulp outside. */
    if (v >= lo + length || v < lo)
        v = lo;
    return v;
}

/* x is moved into the period [lo, lo + length) along the periodic axes. */
static inline void fsi_periodic_wrap(const fsi_periodic *per, double *x)
{
    if (!per)
        return;
    for (int d = 0; d < FSI_DIM; d++)
        if (per->on[d])
            x[d] = fsi_periodic_wrap_axis(per, d, x[d]);
}

#endif
