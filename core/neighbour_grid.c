/* Sorted-cell neighbour search: see neighbour_grid.h. */
#include "neighbour_grid.h"

#include <stdlib.h>

/* At most this many cells per point (plus a few): beyond, the cells grow. */
#define CELLS_PER_POINT 4
#define EXTRA_CELLS 64

void fsi_grid_init(fsi_neighbour_grid *g)
{
    g->cell_size = 0.0;
    for (int d = 0; d < FSI_DIM; d++) {
        g->origin[d] = 0.0;
        g->dims[d] = 0;
    }
    g->n_cells = 0;
    g->n = 0;
    g->cell_start = NULL;
    g->sorted = NULL;
    g->sorted_x = NULL;
    g->cell_of = NULL;
    g->point_capacity = 0;
    g->cell_capacity = 0;
    g->periodic = (fsi_periodic){{0}, {0}, {0}};
}

void fsi_grid_set_periodic(fsi_neighbour_grid *g, const fsi_periodic *per)
{
    if (per)
        g->periodic = *per;
    else
        g->periodic = (fsi_periodic){{0}, {0}, {0}};
}

void fsi_grid_free(fsi_neighbour_grid *g)
{
    free(g->cell_start);
    free(g->sorted);
    free(g->sorted_x);
    free(g->cell_of);
    fsi_grid_init(g);
}

static int reserve(fsi_neighbour_grid *g, int n, long n_cells)
{
    if (n > g->point_capacity) {
        const int cap = n + n / 4 + 16;
        int *sorted = realloc(g->sorted, (size_t)cap * sizeof *sorted);
        if (sorted)
            g->sorted = sorted;
        int *cell_of = realloc(g->cell_of, (size_t)cap * sizeof *cell_of);
        if (cell_of)
            g->cell_of = cell_of;
        double *xs = realloc(g->sorted_x, (size_t)cap * FSI_DIM * sizeof *xs);
        if (xs)
            g->sorted_x = xs;
        if (!sorted || !cell_of || !xs)
            return -1;
        g->point_capacity = cap;
    }
    if (n_cells + 1 > g->cell_capacity) {
        const long cap = n_cells + 1 + n_cells / 4 + 16;
        int *cs = realloc(g->cell_start, (size_t)cap * sizeof *cs);
        if (!cs)
            return -1;
        g->cell_start = cs;
        g->cell_capacity = cap;
    }
    return 0;
}

/* Position i's coordinate d, wrapped into the period along a periodic axis. */
static double coordinate(const fsi_neighbour_grid *g, const double *x, long i, int d)
{
    const double v = x[i * FSI_DIM + d];
    return g->periodic.on[d] ? fsi_periodic_wrap_axis(&g->periodic, d, v) : v;
}

/* Chooses origin, cell size and dims for the bounding box of the points (along a
 * periodic axis: the period). */
static int layout(fsi_neighbour_grid *g, const double *x, int n, double cell_size)
{
    double lo[FSI_DIM], hi[FSI_DIM];
    for (int d = 0; d < FSI_DIM; d++)
        lo[d] = hi[d] = n > 0 ? x[d] : 0.0;
    for (int i = 0; i < n; i++)
        for (int d = 0; d < FSI_DIM; d++) {
            const double v = x[(long)i * FSI_DIM + d];
            if (!isfinite(v))
                return -1;
            if (v < lo[d])
                lo[d] = v;
            if (v > hi[d])
                hi[d] = v;
        }
    for (int d = 0; d < FSI_DIM; d++)
        if (g->periodic.on[d]) {
            if (!(g->periodic.length[d] >= 3.0 * cell_size))
                return -1;
            lo[d] = g->periodic.lo[d];
            /* Cells of size cs from lo; the last one takes the remainder below cs. */
            hi[d] = g->periodic.lo[d] + g->periodic.length[d] - cell_size;
        }
    const double max_cells = (double)CELLS_PER_POINT * n + EXTRA_CELLS;
    double cs = cell_size;
    for (;;) {
        double cells = 1.0;
        for (int d = 0; d < FSI_DIM; d++)
            cells *= floor((hi[d] - lo[d]) / cs) + 1.0;
        if (cells <= max_cells)
            break;
        /* Grow the cells so that their count fits (with a margin for the floors). */
        cs *= 1.01 * pow(cells / max_cells, 1.0 / FSI_DIM);
    }
    g->cell_size = cs;
    g->n_cells = 1;
    for (int d = 0; d < FSI_DIM; d++) {
        g->origin[d] = lo[d];
        g->dims[d] = (int)floor((hi[d] - lo[d]) / cs) + 1;
        if (g->periodic.on[d]) {
            /* Whole cells in the period, the last one stretched to its end. */
            g->dims[d] = (int)floor(g->periodic.length[d] / cs);
            if (g->dims[d] < 3)
                return -1;
        }
        g->n_cells *= g->dims[d];
    }
    return 0;
}

int fsi_grid_build(fsi_neighbour_grid *g, const double *x, int n, double cell_size)
{
    g->n = 0;
    if (!(cell_size > 0.0) || n < 0 || layout(g, x, n, cell_size) != 0 ||
        reserve(g, n, g->n_cells) != 0) {
        g->n = 0;
        return -1;
    }
    const double inv = 1.0 / g->cell_size;
    int *restrict cell_of = g->cell_of;
    int *restrict start = g->cell_start;
    const long n_cells = g->n_cells;

    /* Counting sort: count into start[c + 1], prefix-sum to starts, scatter with
     * start[c] as the cursor (which leaves start[c] = end of c), shift back. */
    for (long c = 0; c <= n_cells; c++)
        start[c] = 0;
    for (int i = 0; i < n; i++) {
        long c = 0;
        for (int d = FSI_DIM - 1; d >= 0; d--) {
            int k = (int)((coordinate(g, x, i, d) - g->origin[d]) * inv);
            if (k >= g->dims[d])
                k = g->dims[d] - 1;
            c = c * g->dims[d] + k;
        }
        cell_of[i] = (int)c;
        start[c + 1]++;
    }
    for (long c = 0; c < n_cells; c++)
        start[c + 1] += start[c];
    for (int i = 0; i < n; i++) {
        const int k = start[cell_of[i]]++;
        g->sorted[k] = i;
        for (int d = 0; d < FSI_DIM; d++)
            g->sorted_x[(long)k * FSI_DIM + d] = coordinate(g, x, i, d);
    }
    for (long c = n_cells; c > 0; c--)
        start[c] = start[c - 1];
    start[0] = 0;
    g->n = n;
    return 0;
}

int fsi_grid_neighbours(const fsi_neighbour_grid *g, const double *p, double r, int *out,
                        double *out_r2, int max_out)
{
    fsi_grid_query q;
    fsi_grid_query_begin(&q, g, p, r);
    int count = 0, j;
    double r2;
    while (fsi_grid_query_next(&q, &j, &r2)) {
        if (count < max_out) {
            out[count] = j;
            if (out_r2)
                out_r2[count] = r2;
        }
        count++;
    }
    return count;
}
