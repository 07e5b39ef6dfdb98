/* The neighbour rows the WCSPH passes walk (wcsph_rates.h), derived from the Verlet
 * candidates (neighbours/verlet_list.h) at each of their builds.
 *
 * Every pair between two fluid particles is evaluated once (its terms are
 * antisymmetric, 004 Eqs. 6-7: what I gets from J, J gets with the other sign and the
 * other particle's mass or volume), so a fluid particle I's row holds
 *   - its fluid segment: the fluid candidates J > I (each fluid pair once), and
 *   - its boundary segment: every wall and solid candidate (those pairs change only
 *     I's rates: a boundary particle has none).
 * A wall or solid particle's own sums (its pressure, 000 Eq. 52; its velocity gradient)
 * walk its full Verlet row. Candidates are filtered against the support in the passes:
 * no per-pair data is stored, so a pass streams 4 bytes per candidate.
 *
 * Writing J's share of a fluid pair makes the order of additions matter. To stay the
 * same on any number of threads, the fluid rows are cut into blocks such that every
 * pair of block b has J in block b or b + 1 (the particles are sorted by cell, so J - I
 * is bounded by about a row of cells). The even blocks then run in parallel, each
 * alone on its particles, then the odd ones: every particle's sum is added in an order
 * that depends on the particles only. */
#ifndef WCSPH_ROWS_H
#define WCSPH_ROWS_H

#include <stdint.h>

#include "fluid_particles.h"
#include "verlet_list.h"

typedef struct {
    int n;                  /* particles of the last build */
    int64_t *offset;        /* n + 1: I's row is neighbour[offset[I] .. offset[I+1]-1] */
    int64_t *split;         /* n: fluid segment offset[I] .. split[I]-1, boundary
                             * segment split[I] .. offset[I+1]-1 */
    int32_t *neighbour;
    int n_blocks;
    int *block_start;       /* n_blocks + 1 */
    int point_capacity, block_capacity;
    int64_t pair_capacity;
} wcsph_rows;

void wcsph_rows_init(wcsph_rows *r);
void wcsph_rows_free(wcsph_rows *r);

/* The rows of p from its Verlet candidates (rebuilt by the caller whenever the list
 * is). 0, or -1 when memory runs out or the list is not for p->n particles. */
int wcsph_rows_build(wcsph_rows *r, const fluid_verlet *list, const fluid_particles *p);

#endif
