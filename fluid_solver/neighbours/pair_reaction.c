/* Boundary loads as the reaction of the pair terms (pair_reaction.h). */
#include "pair_reaction.h"

#include <string.h>

#include "fluid_parallel.h"

void fluid_pair_reaction(const fluid_pairs *pairs, const fluid_particles *p,
                         const double *weight, fluid_pair_term term, const void *context,
                         double *force)
{
    const int n = p->n;
#pragma omp parallel for schedule(dynamic, FLUID_CHUNK) if (n >= FLUID_PARALLEL_MIN_PARTICLES)
    for (int b = 0; b < n; b++) {
        double *f_b = &force[b * FSI_DIM];
        memset(f_b, 0, FSI_DIM * sizeof *f_b);
        if (!(p->flags[b] & FLUID_PARTICLE_MOVING_BOUNDARY))
            continue;
        for (int64_t kb = pairs->offset[b]; kb < pairs->offset[b + 1]; kb++) {
            const int i = pairs->neighbour[kb];
            if (!(p->flags[i] & FLUID_PARTICLE_FLUID))
                continue;
            const int64_t k = fluid_pairs_find(pairs, i, b);
            if (k < 0)
                continue;
            double f[FSI_DIM];
            term(context, i, k, f);
            for (int d = 0; d < FSI_DIM; d++)
                f_b[d] -= weight[i] * f[d];
        }
    }
}
