/* The families of NOSB-PD points: every pair of points closer than the horizon
 * delta = horizon_factor * dx in the reference configuration is a bond (000 §2.2,
 * Fig. 2), in the shared CSR form of solid_bonds.h (each pair stored twice, so each
 * point gathers over its own row without write races; lattice points exactly on the
 * horizon belong to it whatever the round-off; bonds across a [solid.crack] start
 * broken). No partial-volume correction: each neighbour counts with its full volume
 * V_J. The shape tensor and the deformation gradient are sums over exactly the same
 * bonds with the same weights, so affine motions are reproduced exactly either way; a
 * correction would only change how the horizon edge is sampled.
 *
 * Influence function omega(|xi|) (key influence_function), in the bond weight
 * omega V_J:
 *   one       omega = 1
 *   inverse   omega = delta / |xi|   (Silling's 1/|xi| scaled to 1 at the horizon)
 *   gaussian  omega = exp(-(2 |xi| / delta)^2)   (exp(-4) = 0.018 at the horizon) */
#ifndef NOSBPD_BONDS_H
#define NOSBPD_BONDS_H

#include <stdint.h>

#include "dim.h"
#include "solid_bonds.h"

typedef enum { NOSBPD_INFLUENCE_ONE, NOSBPD_INFLUENCE_INVERSE, NOSBPD_INFLUENCE_GAUSSIAN } nosbpd_influence;

/* weight = omega(|xi|) V_J [m^DIM]. */
typedef solid_bonds nosbpd_bonds;

double nosbpd_influence_value(nosbpd_influence kind, double r, double delta);

/* Parses "one" | "inverse" | "gaussian"; returns 0, or -1 for anything else. */
int nosbpd_influence_parse(const char *name, nosbpd_influence *kind);

/* Builds the families of the n points x0 with volumes 'volume' (solid_bonds_build
 * with reach delta) and their weights omega V_J. Returns 0, or -1 when memory runs
 * out or a position is not finite. Freed with solid_bonds_free. */
int nosbpd_bonds_build(nosbpd_bonds *b, const double *x0, const double *volume, int n,
                       double delta, double dx, nosbpd_influence kind);

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
