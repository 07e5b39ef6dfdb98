/* The loads on the moving boundary (the solid seen by the fluid) as the exact reaction of
 * a scheme's pair terms, which every scheme's fluid_scheme_boundary_loads needs: for
 * every moving boundary particle B,
 *
 *     F_B = - sum_I weight_I term(I, k_IB)
 *
 * over its fluid neighbours I, k_IB the entry of B in I's row (the same pair data the
 * scheme's rates read) and weight_I term the force on I from B in the rates (ULPH: the
 * volume times a force density; WCSPH: the mass times an acceleration). The forces on
 * fluid and boundary therefore balance to round-off. Parallel over B, each writing its
 * own row of force; zero for the other particles. */
#ifndef FSI_PAIR_REACTION_H
#define FSI_PAIR_REACTION_H

#include "fluid_pairs.h"
#include "fluid_particles.h"

/* The term of entry k of fluid particle I's row into out[FSI_DIM]. */
typedef void (*fluid_pair_term)(const void *context, int i, int64_t k, double *out);

void fluid_pair_reaction(const fluid_pairs *pairs, const fluid_particles *p,
                         const double *weight, fluid_pair_term term, const void *context,
                         double *force);

#endif
