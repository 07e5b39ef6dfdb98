/* The families of NOSB-PD points: every pair of points closer than the horizon
 * delta = horizon_factor * dx in the reference configuration is a bond (000 §2.2,
 * Fig. 2), stored twice (I -> J in I's row, J -> I in J's row) in compressed rows
 * (CSR), so that each point gathers over its own row without write races.
 *
 * Horizon membership: a point J is in I's family when |xi| <= delta + 1e-6 dx
 * (lattice points exactly on the horizon belong to it, whatever the round-off). No
 * partial-volume correction: each neighbour counts with its full volume V_J. The
 * shape tensor and the deformation gradient are sums over exactly the same bonds
 * with the same weights, so affine motions are reproduced exactly either way; a
 * correction would only change how the horizon edge is sampled.
 *
 * Influence function omega(|xi|) (key influence_function):
 *   one       omega = 1
 *   inverse   omega = delta / |xi|   (Silling's 1/|xi| scaled to 1 at the horizon)
 *   gaussian  omega = exp(-(2 |xi| / delta)^2)   (exp(-4) = 0.018 at the horizon) */
#ifndef NOSBPD_BONDS_H
#define NOSBPD_BONDS_H

#include <stdint.h>

#include "dim.h"

typedef enum { NOSBPD_INFLUENCE_ONE, NOSBPD_INFLUENCE_INVERSE, NOSBPD_INFLUENCE_GAUSSIAN } nosbpd_influence;

/* Lattice points on the horizon edge count when |xi| <= delta + this * dx. */
#define NOSBPD_HORIZON_TOLERANCE 1e-6

typedef struct {
    int n_points;
    int64_t n_bonds;            /* directed bonds (each pair twice) */
    int64_t *offset;            /* n_points + 1: point I's bonds are offset[I] .. offset[I+1]-1 */
    int32_t *neighbour;         /* J */
    double *xi;                 /* reference bond vector x0_J - x0_I, n_bonds * FSI_DIM [m] */
    double *length;             /* |xi| [m] */
    double *weight;             /* omega(|xi|) V_J [m^DIM] */
    uint8_t *intact;            /* 1 while the bond carries force; 0 once broken (permanent) */
} nosbpd_bonds;

double nosbpd_influence_value(nosbpd_influence kind, double r, double delta);

/* Parses "one" | "inverse" | "gaussian"; returns 0, or -1 for anything else. */
int nosbpd_influence_parse(const char *name, nosbpd_influence *kind);

/* Builds the families of the n points x0 with volumes 'volume' (neighbour grid of
 * cell delta). Returns 0, or -1 when memory runs out or a position is not finite. */
int nosbpd_bonds_build(nosbpd_bonds *b, const double *x0, const double *volume, int n,
                       double delta, double dx, nosbpd_influence kind);

void nosbpd_bonds_free(nosbpd_bonds *b);

/* Breaks every bond whose reference segment crosses the crack from-to
 * (solid_crack_cuts); returns how many pairs it broke (each pair is two directed
 * bonds). */
int64_t nosbpd_bonds_cut(nosbpd_bonds *b, const double *x0, const double *from,
                         const double *to);

/* The family of a point deep inside a regular lattice of spacing dx, over the
 * integer lattice vectors n != 0 with |n| dx within the horizon (the same test as
 * the build): its bond count, and the sums of V / |xi| and omega V with V = dx^DIM
 * (the stabilisation and the stable step scale with them). */
typedef struct {
    int count;
    double sum_volume_over_length;  /* sum V / |xi| [m^(DIM-1)] */
    double sum_weight;              /* sum omega V [m^DIM] */
} nosbpd_full_family;

nosbpd_full_family nosbpd_full_family_of_lattice(double delta, double dx, nosbpd_influence kind);

#endif
