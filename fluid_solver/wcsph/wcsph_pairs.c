/* The WCSPH pair list from Verlet candidates (wcsph_pairs.h). */
#include "wcsph_pairs.h"

#include <stdlib.h>

#include "fluid_parallel.h"
#include "grow.h"

void wcsph_pairs_init(wcsph_pairs *pl)
{
    *pl = (wcsph_pairs){0};
}

void wcsph_pairs_free(wcsph_pairs *pl)
{
    free(pl->pairs.offset);
    free(pl->pairs.neighbour);
    free(pl->pairs.w);
    free(pl->f);
    free(pl->rel);
    wcsph_pairs_init(pl);
}

/* Room for n particles and n_pairs pairs; 0, or -1. */
static int reserve(wcsph_pairs *pl, int n, int64_t n_pairs)
{
    int failed = 0;
    if (!pl->pairs.offset || n > pl->point_capacity) {
        const size_t cap = fsi_grown_capacity((size_t)n);
        pl->pairs.offset = fsi_grow(pl->pairs.offset, (cap + 1) * sizeof *pl->pairs.offset,
                                    &failed);
        pl->point_capacity = failed ? 0 : (int)cap;
    }
    if (!failed && (!pl->f || n_pairs > pl->pair_capacity)) {
        const size_t cap = fsi_grown_capacity((size_t)n_pairs);
        pl->pairs.neighbour = fsi_grow(pl->pairs.neighbour, cap * sizeof *pl->pairs.neighbour,
                                       &failed);
        pl->pairs.w = fsi_grow(pl->pairs.w, cap * sizeof *pl->pairs.w, &failed);
        pl->f = fsi_grow(pl->f, cap * sizeof *pl->f, &failed);
        pl->rel = fsi_grow(pl->rel, cap * FSI_DIM * sizeof *pl->rel, &failed);
        pl->pair_capacity = failed ? 0 : (int64_t)cap;
    }
    return failed ? -1 : 0;
}

/* |x_IJ|^2 of candidate c of particle i, x_IJ into rel. */
static inline double candidate_r2(const wcsph_pairs *pl, const fluid_verlet *list,
                                  const double *x, int i, int64_t c, double *rel)
{
    fluid_pair_vector(&pl->pairs, x, i, list->candidate[c], rel);
    double r2 = 0.0;
    for (int d = 0; d < FSI_DIM; d++)
        r2 += rel[d] * rel[d];
    return r2;
}

int wcsph_pairs_update(wcsph_pairs *pl, const wendland_c2_kernel *k, const fluid_verlet *list,
                       const fluid_particles *p)
{
    const int n = p->n;
    if (list->n != n || reserve(pl, n, 0) != 0)
        return -1;
    pl->pairs.n = 0;
    pl->pairs.periodic = list->periodic;
    int64_t *offset = pl->pairs.offset;
    const int parallel = n >= FLUID_PARALLEL_MIN_PARTICLES;
    offset[0] = 0;
#pragma omp parallel for schedule(dynamic, FLUID_CHUNK) if (parallel)
    for (int i = 0; i < n; i++) {
        int64_t count = 0;
        double rel[FSI_DIM];
        for (int64_t c = list->offset[i]; c < list->offset[i + 1]; c++)
            count += candidate_r2(pl, list, p->x, i, c, rel) < k->support2;
        offset[i + 1] = count;
    }
    for (int i = 0; i < n; i++)
        offset[i + 1] += offset[i];
    if (reserve(pl, n, offset[n]) != 0)
        return -1;
#pragma omp parallel for schedule(dynamic, FLUID_CHUNK) if (parallel)
    for (int i = 0; i < n; i++) {
        int64_t e = offset[i];
        for (int64_t c = list->offset[i]; c < list->offset[i + 1]; c++) {
            double rel[FSI_DIM];
            const double r2 = candidate_r2(pl, list, p->x, i, c, rel);
            if (!(r2 < k->support2))
                continue;
            for (int d = 0; d < FSI_DIM; d++)
                pl->rel[e * FSI_DIM + d] = rel[d];
            pl->pairs.neighbour[e] = list->candidate[c];
            wendland_c2_eval2(k, r2, &pl->pairs.w[e], &pl->f[e]);
            e++;
        }
    }
    pl->pairs.n = n;
    pl->pairs.n_pairs = offset[n];
    return 0;
}
