/* The neighbour pairs of one evaluation of the rates, as every scheme and the shared
 * walls read them: a compressed row (CSR) list of every pair closer than the kernel's
 * support, stored as I -> J in I's row and J -> I in J's row, with the kernel value of
 * each pair. A scheme builds it (from the Verlet candidates, verlet_list.h) together
 * with whatever it keeps per pair (ULPH: g_IJ; WCSPH: the kernel gradient). */
#ifndef FSI_FLUID_PAIRS_H
#define FSI_FLUID_PAIRS_H

#include <stdint.h>

#include "dim.h"
#include "periodic.h"

typedef struct {
    int n;                  /* particles */
    int64_t n_pairs;        /* directed pairs (each pair twice) */
    int64_t *offset;        /* n + 1: I's neighbours are offset[I] .. offset[I+1]-1 */
    int32_t *neighbour;     /* J */
    double *w;              /* the kernel w(|x_IJ|) [1/m^DIM] */
    fsi_periodic periodic;  /* the periodic axes the pairs were found with */
} fluid_pairs;

/* x_IJ = x_J - x_I, the nearest periodic image along periodic axes: every pair
 * computation takes its vector from here. */
static inline void fluid_pair_vector(const fluid_pairs *pairs, const double *x, int i, int j,
                                     double *rel)
{
    for (int d = 0; d < FSI_DIM; d++)
        rel[d] = x[(int64_t)j * FSI_DIM + d] - x[(int64_t)i * FSI_DIM + d];
    fsi_periodic_min_image(&pairs->periodic, rel);
}

/* The same from a periodic description (NULL: none), with |x_IJ|^2 returned: for a
 * scheme that walks its own rows (WCSPH); a pair seen from either row gives the same
 * numbers. */
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

/* The entry of J in I's row (the same pair data every pass over I's row reads), or -1
 * when J is not I's neighbour. */
static inline int64_t fluid_pairs_find(const fluid_pairs *pairs, int i, int j)
{
    for (int64_t k = pairs->offset[i]; k < pairs->offset[i + 1]; k++)
        if (pairs->neighbour[k] == j)
            return k;
    return -1;
}

#endif
