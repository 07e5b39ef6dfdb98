/* Pair-once rows and their blocks (fluid_rows.h). */
#include "fluid_rows.h"

#include <stdlib.h>

#include "fluid_parallel.h"
#include "grow.h"

/* The smallest block: a block costs a little scheduling, and blocks far below the
 * reach of a row would not make the phases any shorter. */
#define FLUID_ROWS_MIN_BLOCK 256

void fluid_rows_init(fluid_rows *r)
{
    *r = (fluid_rows){0};
}

void fluid_rows_free(fluid_rows *r)
{
    free(r->offset);
    free(r->split);
    free(r->neighbour);
    free(r->block_start);
    free(r->fluid_end);
    free(r->boundary_end);
    free(r->pair);
    free(r->f);
    fluid_rows_init(r);
}

static int reserve(fluid_rows *r, int n, int64_t n_pairs)
{
    int failed = 0;
    if (!r->offset || n > r->point_capacity) {
        const size_t cap = fsi_grown_capacity((size_t)n);
        r->offset = fsi_grow(r->offset, (cap + 1) * sizeof *r->offset, &failed);
        r->split = fsi_grow(r->split, (cap + 1) * sizeof *r->split, &failed);
        r->block_start = fsi_grow(r->block_start, (cap + 2) * sizeof *r->block_start, &failed);
        r->fluid_end = fsi_grow(r->fluid_end, (cap + 1) * sizeof *r->fluid_end, &failed);
        r->boundary_end = fsi_grow(r->boundary_end, (cap + 1) * sizeof *r->boundary_end,
                                   &failed);
        r->point_capacity = failed ? 0 : (int)cap;
    }
    if (!failed && (!r->neighbour || n_pairs > r->pair_capacity)) {
        const size_t cap = fsi_grown_capacity((size_t)n_pairs);
        r->neighbour = fsi_grow(r->neighbour, cap * sizeof *r->neighbour, &failed);
        r->pair = fsi_grow(r->pair, cap * sizeof *r->pair, &failed);
        r->f = fsi_grow(r->f, cap * sizeof *r->f, &failed);
        r->pair_capacity = failed ? 0 : (int64_t)cap;
    }
    return failed ? -1 : 0;
}

/* Whether candidate j belongs to i's row. */
static inline int in_row(const fluid_particles *p, int boundary_rows, int i, int j)
{
    if (!(p->flags[i] & FLUID_PARTICLE_FLUID))
        return boundary_rows;
    return !(p->flags[j] & FLUID_PARTICLE_FLUID) || j > i;
}

int fluid_rows_build(fluid_rows *r, const fluid_verlet *list, const fluid_particles *p,
                     int boundary_rows)
{
    const int n = p->n;
    r->n = 0;
    if (list->n != n || reserve(r, n, 0) != 0)
        return -1;
    const int parallel = n >= FLUID_PARALLEL_MIN_PARTICLES;
    int64_t *offset = r->offset;
    offset[0] = 0;
#pragma omp parallel for schedule(dynamic, FLUID_CHUNK) if (parallel)
    for (int i = 0; i < n; i++) {
        int64_t count = 0;
        for (int64_t c = list->offset[i]; c < list->offset[i + 1]; c++)
            count += in_row(p, boundary_rows, i, list->candidate[c]);
        offset[i + 1] = count;
    }
    for (int i = 0; i < n; i++)
        offset[i + 1] += offset[i];
    if (reserve(r, n, offset[n]) != 0)
        return -1;
    /* Fluid neighbours first, in the candidates' order, then the boundary ones. */
#pragma omp parallel for schedule(dynamic, FLUID_CHUNK) if (parallel)
    for (int i = 0; i < n; i++) {
        int64_t e = offset[i];
        if (p->flags[i] & FLUID_PARTICLE_FLUID) {
            for (int64_t c = list->offset[i]; c < list->offset[i + 1]; c++) {
                const int j = list->candidate[c];
                if ((p->flags[j] & FLUID_PARTICLE_FLUID) && j > i)
                    r->neighbour[e++] = j;
            }
            r->split[i] = e;
            for (int64_t c = list->offset[i]; c < list->offset[i + 1]; c++) {
                const int j = list->candidate[c];
                if (!(p->flags[j] & FLUID_PARTICLE_FLUID))
                    r->neighbour[e++] = j;
            }
        } else {
            r->split[i] = e;
            for (int64_t c = list->offset[i]; boundary_rows && c < list->offset[i + 1]; c++)
                r->neighbour[e++] = list->candidate[c];
        }
    }
    /* Blocks: block b + 1 ends beyond the farthest fluid neighbour of every particle
     * before it (reach: the running maximum of the rows' last fluid neighbour). */
    int nb = 0, reach = 0, i = 0;
    r->block_start[nb++] = 0;
    while (i < n) {
        int end = i + FLUID_ROWS_MIN_BLOCK;
        if (nb >= 2 && end <= reach)
            end = reach + 1;
        end = end < n ? end : n;
        for (; i < end; i++)
            for (int64_t k = offset[i]; k < r->split[i]; k++)
                reach = r->neighbour[k] > reach ? r->neighbour[k] : reach;
        r->block_start[nb++] = end;
    }
    r->n_blocks = nb - 1;
    r->boundary_rows = boundary_rows;
    r->n = n;
    return 0;
}
