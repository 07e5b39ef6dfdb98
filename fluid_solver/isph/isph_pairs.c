/* Full neighbour rows (isph_pairs.h): a count pass, offsets, then a fill pass, both
 * over the particles in parallel, each writing only its own row. */
#include "isph_pairs.h"

#include <stdlib.h>

#include "fluid_pairs.h"
#include "fluid_parallel.h"
#include "grow.h"

void isph_pairs_init(isph_pairs *q)
{
    *q = (isph_pairs){0};
}

void isph_pairs_free(isph_pairs *q)
{
    free(q->start);
    free(q->j);
    free(q->xij);
    free(q->w);
    free(q->f);
    isph_pairs_init(q);
}

static const fsi_periodic *periodic_of(const fluid_verlet *list)
{
    return fsi_periodic_any(&list->periodic) ? &list->periodic : NULL;
}

int isph_pairs_build(isph_pairs *q, const fluid_verlet *list, const cubic_spline_kernel *k,
                     const fluid_particles *p)
{
    const int n = p->n;
    int failed = 0;
    if (n + 1 > q->capacity) {
        const size_t cap = fsi_grown_capacity((size_t)n + 1);
        q->start = fsi_grow(q->start, cap * sizeof *q->start, &failed);
        if (failed)
            return -1;
        q->capacity = (int)cap;
    }
    const fsi_periodic *per = periodic_of(list);
    const double support2 = k->support2;
#pragma omp parallel for schedule(static) if (n >= FLUID_PARALLEL_MIN_PARTICLES)
    for (int i = 0; i < n; i++) {
        int64_t count = 0;
        for (int64_t e = list->offset[i]; e < list->offset[i + 1]; e++) {
            double rel[FSI_DIM];
            count += fluid_pair_vector_r2(per, p->x, i, list->candidate[e], rel) < support2;
        }
        q->start[i + 1] = count;
    }
    q->start[0] = 0;
    for (int i = 0; i < n; i++)
        q->start[i + 1] += q->start[i];
    const int64_t total = q->start[n];
    if (total > q->pair_capacity) {
        const size_t cap = fsi_grown_capacity((size_t)total);
        q->j = fsi_grow(q->j, cap * sizeof *q->j, &failed);
        q->xij = fsi_grow(q->xij, cap * FSI_DIM * sizeof *q->xij, &failed);
        q->w = fsi_grow(q->w, cap * sizeof *q->w, &failed);
        q->f = fsi_grow(q->f, cap * sizeof *q->f, &failed);
        if (failed)
            return -1;
        q->pair_capacity = (int64_t)cap;
    }
#pragma omp parallel for schedule(static) if (n >= FLUID_PARALLEL_MIN_PARTICLES)
    for (int i = 0; i < n; i++) {
        int64_t m = q->start[i];
        for (int64_t e = list->offset[i]; e < list->offset[i + 1]; e++) {
            const int j = list->candidate[e];
            double *rel = &q->xij[m * FSI_DIM];
            const double r2 = fluid_pair_vector_r2(per, p->x, i, j, rel);
            if (!(r2 < support2))
                continue;
            q->j[m] = j;
            cubic_spline_eval2(k, r2, &q->w[m], &q->f[m]);
            m++;
        }
    }
    q->n = n;
    return 0;
}
