/* Pairs of solid points that interact, fixed in the reference configuration: every
 * pair closer than a reach (NOSB-PD: its horizon delta; pseudo-spring SPH: the
 * immediate lattice neighbours, sqrt(FSI_DIM) dx), stored twice (I -> J in I's row,
 * J -> I in J's row) in compressed rows (CSR), so that each point gathers over its
 * own row without write races and the results do not depend on the thread count.
 *
 * Membership: J is in I's row when |xi| <= reach + SOLID_BONDS_TOLERANCE dx, so that
 * lattice points exactly at the reach belong to it whatever the round-off.
 *
 * A bond is intact (1) until the model breaks it (0, for good). Bonds whose
 * reference segment crosses a [solid.crack] segment start broken
 * (solid_bonds_cut_cracks), the same rule for every bond-based model. Shared by the
 * model folders (nosbpd/, pseudo_spring/), so there is one copy of the search and
 * of the crack rule. */
#ifndef FSI_SOLID_BONDS_H
#define FSI_SOLID_BONDS_H

#include <stddef.h>
#include <stdint.h>

#include "case_file.h"
#include "dim.h"

/* Lattice points at the reach count when |xi| <= reach + this * dx. */
#define SOLID_BONDS_TOLERANCE 1e-6

typedef struct {
    int n_points;
    int64_t n_bonds;            /* directed bonds (each pair twice) */
    int64_t *offset;            /* n_points + 1: point I's bonds are offset[I] .. offset[I+1]-1 */
    int32_t *neighbour;         /* J */
    double *xi;                 /* reference bond vector x0_J - x0_I, n_bonds * FSI_DIM [m] */
    double *length;             /* |xi| [m] */
    double *weight;             /* V_J [m^DIM] after the build; a model may scale it */
    uint8_t *intact;            /* 1 while the bond carries force; 0 once broken (permanent) */
} solid_bonds;

/* Builds the rows of the n points x0 with volumes 'volume' (neighbour grid of cell
 * reach + tolerance). Returns 0, or -1 when memory runs out or a position is not
 * finite (b is then empty). */
int solid_bonds_build(solid_bonds *b, const double *x0, const double *volume, int n,
                      double reach, double dx);

void solid_bonds_free(solid_bonds *b);

/* Breaks every intact bond whose reference segment crosses the crack from-to
 * (solid_crack_cuts); returns how many pairs it broke (each pair is two directed
 * bonds). */
int64_t solid_bonds_cut(solid_bonds *b, const double *x0, const double *from,
                        const double *to);

/* Breaks the bonds across every [role.crack NAME] segment of the case (a validated
 * case has checked that each separates neighbouring points) and reports on stderr
 * "MODEL: [solid.crack NAME] breaks N bonds from the start". Returns 0, or -1 with
 * msg when the case's geometry cannot be read. */
int solid_bonds_cut_cracks(solid_bonds *b, const fsi_case *c, const char *role,
                           const double *x0, const char *model, char *msg, size_t msg_size);

/* The reverse of every bond: reverse[q] is the position of J -> I in J's row for the
 * bond q = I -> J (rows are symmetric: J is in I's row when I is in J's). A model
 * that evaluates a pair's quantities once and stores them at both of its slots uses
 * it (each slot written once: no write races, the same result on any thread count).
 * Returns a malloc'ed array of n_bonds entries (the caller frees it), or NULL when
 * memory runs out or a bond has no reverse. */
int64_t *solid_bonds_reverse(const solid_bonds *b);

/* Number of bonds of a point deep inside a regular lattice: the integer lattice
 * vectors n != 0 with |n| dx <= reach (+ tolerance), as the build counts them. */
int solid_bonds_full_count(double reach, double dx);

#endif
