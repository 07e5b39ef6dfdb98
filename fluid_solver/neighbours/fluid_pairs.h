/* The vector of a neighbour pair, as every scheme and the shared walls take it
 * (the pairs themselves: fluid_rows.h). */
#ifndef FSI_FLUID_PAIRS_H
#define FSI_FLUID_PAIRS_H

#include <stdint.h>

#include "dim.h"
#include "periodic.h"

/* x_IJ = x_J - x_I, the nearest periodic image along the periodic axes of per (NULL:
 * none), and |x_IJ|^2: every pair computation takes its vector from here, so a pair
 * seen from either row gives the same numbers. */
static inline double fluid_pair_vector_r2(const fsi_periodic *per, const double *x, int i,
                                          int j, double *rel)
{
    double r2 = 0.0;
    for (int d = 0; d < FSI_DIM; d++)
        rel[d] = x[(int64_t)j * FSI_DIM + d] - x[(int64_t)i * FSI_DIM + d];
    if (per)
        fsi_periodic_min_image(per, rel);
    for (int d = 0; d < FSI_DIM; d++)
        r2 += rel[d] * rel[d];
    return r2;
}

#endif
