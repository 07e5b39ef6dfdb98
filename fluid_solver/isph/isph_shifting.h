/* Particle shifting (003 Eqs. 20-30, docs/isph.md): after the position update every
 * fluid particle is moved by
 *     dr_a = C zeta R_a,   R_a = sum_b (rbar_a / r_ab)^2 e_ab,   zeta = |u|max dt
 * (Xu et al. 2009; 003 Eqs. 21-23: rbar_a the mean distance to its neighbours, e_ab the
 * unit vector from b to a, the sum over every neighbour, walls and solid included, so
 * that no particle is pushed into them), capped at cap (0.2 h, Lind et al. 2012);
 *   - surface and near-surface particles keep only the tangential part,
 *     dr (I - n (x) n) (003 Eq. 24, Khayyer et al. 2017);
 *   - a fluid particle next to the solid (a solid particle within its support) has the
 *     normal part dn = dr . n_s (n_s from the nearest solid particle) damped over the
 *     layer of depth |d| = layer zeta / |R_a . n_s| (003 Eqs. 27-30, our reading):
 *       dn' = sign(dn) |d| (x - 1 + exp(-x)),  x = |dn| / |d|,
 *     which is dn^2 / (2 |d|) for a small shift and never reverses it.
 * Splash particles are not shifted. The fields follow by Taylor's first order (003
 * Eqs. 20, 31-32), which the caller applies with its gradients. */
#ifndef ISPH_SHIFTING_H
#define ISPH_SHIFTING_H

#include "fluid_particles.h"
#include "isph_operators.h"
#include "isph_pairs.h"

typedef struct {
    double coefficient;     /* C */
    double cap;             /* largest |dr| [m] */
    double layer;           /* |d| |R_n| / zeta */
} isph_shifting;

/* The shift of every fluid particle into shift (FSI_DIM each, zero for the others),
 * zeta = |u|max dt. Pair vectors from q (the projection's positions). */
void isph_shifting_compute(const isph_shifting *c, const isph_pairs *q, const fluid_particles *p,
                           const isph_fields *f, double zeta, double *shift);

#endif
