/* Neighbour rows that visit each fluid pair once, derived from the Verlet candidates
 * (verlet_list.h) at each of their builds, for schemes whose pair terms are written to
 * both particles (WCSPH, 004 Eqs. 6-7; ULPH's shape tensors and pair forces, 000
 * Eqs. 15, 23): what I gets from J, J gets with the other particle's mass or volume.
 *
 * A fluid particle I's row holds
 *   - its fluid segment: the fluid candidates J > I (each fluid pair once), and
 *   - its boundary segment: every wall and solid candidate (those pairs are written on
 *     I's side only).
 * A wall or solid particle's row is empty, or, with boundary_rows, all its candidates
 * in its boundary segment (for a scheme that needs the walls' own sums over the rows,
 * ULPH's M of a wall particle); either way it writes only its own sums.
 *
 * At every evaluation fluid_rows_filter_row keeps, in place of each segment, the
 * candidates now within the support, with their squared distance in f for the scheme
 * to turn into its kernel's values in a loop of its own (no call, no branch: it
 * vectorises). The passes then walk only pairs, with neither a square root nor a branch
 * on the distance (about a quarter of the candidates are outside; mispredicting them
 * stalled the passes). The filter is itself branch-free: it writes every candidate and
 * advances over those inside.
 *
 * Writing J's share of a fluid pair makes the order of additions matter. To stay the
 * same on any number of threads, the rows are cut into blocks such that every fluid
 * pair of block b has J in block b or b + 1 (the particles are sorted by cell, so J - I
 * is bounded by about a row of cells). The even blocks then run in parallel, each
 * alone on its particles, then the odd ones: every particle's
 * sum is added in an order that depends on the particles only. */
#ifndef FSI_FLUID_ROWS_H
#define FSI_FLUID_ROWS_H

#include <stdint.h>

#include "fluid_particles.h"
#include "fluid_pairs.h"
#include "verlet_list.h"

typedef struct {
    int n;                  /* particles of the last build */
    int boundary_rows;      /* 1: wall and solid particles have their full rows */
    int64_t *offset;        /* n + 1: I's row is neighbour[offset[I] .. offset[I+1]-1] */
    int64_t *split;         /* n: fluid segment offset[I] .. split[I]-1, boundary
                             * segment split[I] .. offset[I+1]-1 */
    int32_t *neighbour;
    /* of the last filter: I's pairs are pair[offset[I] .. fluid_end[I]-1] and
     * pair[split[I] .. boundary_end[I]-1], with f their r^2 (the scheme may overwrite
     * it with its kernel's values) */
    int64_t *fluid_end, *boundary_end;
    int32_t *pair;
    double *f;
    int n_blocks;
    int *block_start;       /* n_blocks + 1 */
    int point_capacity;
    int64_t pair_capacity;
} fluid_rows;

void fluid_rows_init(fluid_rows *r);
void fluid_rows_free(fluid_rows *r);

/* The rows of p from its Verlet candidates (rebuilt by the caller whenever the list
 * is), with the walls' and solid's full rows when boundary_rows. 0, or -1 when memory
 * runs out or the list is not for p->n particles. */
int fluid_rows_build(fluid_rows *r, const fluid_verlet *list, const fluid_particles *p,
                     int boundary_rows);

/* The candidates of neighbour[lo .. hi-1] closer than sqrt(support2) into pair and f
 * (their r^2) from lo on; returns the end. */
static inline int64_t fluid_rows_filter_segment(fluid_rows *r, double support2,
                                                const fsi_periodic *per, const double *x,
                                                int i, int64_t lo, int64_t hi)
{
    int64_t m = lo;
    for (int64_t e = lo; e < hi; e++) {
        const int j = r->neighbour[e];
        double rel[FSI_DIM];
        const double r2 = fluid_pair_vector_r2(per, x, i, j, rel);
        r->pair[m] = j;
        r->f[m] = r2;
        m += r2 < support2; /* no branch */
    }
    return m;
}

/* I's row filtered (both segments). */
static inline void fluid_rows_filter_row(fluid_rows *r, double support2, const fsi_periodic *per,
                                         const double *x, int i)
{
    r->fluid_end[i] = fluid_rows_filter_segment(r, support2, per, x, i, r->offset[i],
                                                r->split[i]);
    r->boundary_end[i] = fluid_rows_filter_segment(r, support2, per, x, i, r->split[i],
                                                   r->offset[i + 1]);
}

#endif
