/* Neighbour search by sorted cells (cell-linked list in counting-sort form), shared
 * by every particle process: the solid builds it once for its bonds, the fluid
 * rebuilds it every step.
 *
 * A build bins the points into cubic cells of edge >= the requested size over their
 * bounding box, counting-sorts them by cell (stable: ascending index within a cell)
 * and keeps, per cell, the range of the sorted order it holds (cell_start) and a copy
 * of the positions in that order. Rebuilding allocates only when the number of
 * points or cells grows past what an earlier build allocated. When the box would
 * need more than about 4 cells per point (a few points far from the rest), the cells
 * are made larger: queries stay exact, only slower.
 *
 * Queries visit, strip by strip (cells contiguous along x), the cells that can hold
 * points within r of a position p and report each point j with |x_j - p| <= r,
 * p's own point included (distance 0) when p is a point of the grid. The order is
 * deterministic: by cell, then by index.
 *
 *     fsi_grid_query q;
 *     fsi_grid_query_begin(&q, &grid, x + i * FSI_DIM, r);
 *     int j; double r2;
 *     while (fsi_grid_query_next(&q, &j, &r2))
 *         if (j != i) ...
 *
 * A grid is read-only during queries, so any number of threads may query at once.
 *
 * Periodic axes (fsi_grid_set_periodic, core/periodic.h): along them the cells tile the
 * period and queries wrap around it, reporting the points whose nearest periodic image
 * is within r (with the squared distance to that image). The grid stores positions
 * wrapped into the period; callers take the minimum image of x_J - x_I
 * (fsi_periodic_min_image). A periodic axis needs at least three cells (period >=
 * 3 cell sizes): otherwise the build fails. */
#ifndef FSI_NEIGHBOUR_GRID_H
#define FSI_NEIGHBOUR_GRID_H

#include <math.h>

#include "dim.h"
#include "periodic.h"

typedef struct {
    double cell_size;           /* cell edge [m], >= the size asked for */
    double origin[FSI_DIM];     /* lower corner of cell (0, ..., 0) */
    int dims[FSI_DIM];          /* cells along each axis; cell index = x fastest */
    long n_cells;
    int n;                      /* points of the last build */
    int *cell_start;            /* n_cells + 1: cell c holds sorted[cell_start[c] ..
                                 * cell_start[c + 1] - 1] */
    int *sorted;                /* point indices in cell order */
    double *sorted_x;           /* their positions, sorted_x[k * FSI_DIM + d] */
    int *cell_of;               /* cell of each point, by point index */
    int point_capacity;         /* allocated sizes */
    long cell_capacity;
    fsi_periodic periodic;      /* axes that wrap (none by default) */
} fsi_neighbour_grid;

/* An empty grid (no allocation). */
void fsi_grid_init(fsi_neighbour_grid *g);

/* Bins n points x[n * FSI_DIM] into cells of edge >= cell_size (> 0). Returns 0, or
 * -1 when cell_size is not positive, a coordinate is not finite (the grid is then
 * empty) or memory runs out. The grid does not keep x. */
int fsi_grid_build(fsi_neighbour_grid *g, const double *x, int n, double cell_size);

/* Makes the axes of per periodic for the following builds (NULL: none). */
void fsi_grid_set_periodic(fsi_neighbour_grid *g, const fsi_periodic *per);

/* Frees the grid's arrays and leaves it empty (init state, no periodic axes). */
void fsi_grid_free(fsi_neighbour_grid *g);

/* Collects the points within r of p (p's own point included): writes at most
 * max_out indices to out (and squared distances to out_r2 unless NULL) and returns
 * how many there are in all (which may exceed max_out). */
int fsi_grid_neighbours(const fsi_neighbour_grid *g, const double *p, double r, int *out,
                        double *out_r2, int max_out);

/* Iterator over the points within r of p. */
typedef struct {
    const fsi_neighbour_grid *g;
    double p[FSI_DIM];
    double r2;
    int lo[FSI_DIM], hi[FSI_DIM];   /* box of cells to visit, inclusive (unwrapped
                                     * along periodic axes: may be -1 or dims) */
    int c[FSI_DIM];                 /* current strip: c[first..] */
    int first;                      /* 1: strips run along x; 0: single cells (x periodic) */
    double shift[FSI_DIM];          /* image offset of the current strip's points */
    int k, end;                     /* current position in the sorted order, strip end */
    int done;
} fsi_grid_query;

/* Cell index along axis d of coordinate v (inside the grid's span along d). */
static inline int fsi_grid_axis_cell(const fsi_neighbour_grid *g, int d, double v)
{
    const double k = floor((v - g->origin[d]) / g->cell_size);
    return k > (double)(g->dims[d] - 1) ? g->dims[d] - 1 : (int)k;
}

static inline void fsi_grid_query_begin(fsi_grid_query *q, const fsi_neighbour_grid *g,
                                        const double *p, double r)
{
    q->g = g;
    q->r2 = r * r;
    q->k = q->end = 0;
    q->done = 1;
    q->first = g->periodic.on[0] ? 0 : 1;
    for (int d = 0; d < FSI_DIM; d++)
        q->p[d] = 0.0, q->lo[d] = q->hi[d] = q->c[d] = 0, q->shift[d] = 0.0;
    if (g->n == 0 || !(r >= 0.0))
        return;
    /* The cell box is padded a little so that rounding never drops a point at
     * distance exactly r. */
    const double rc = r + 1e-9 * g->cell_size;
    for (int d = 0; d < FSI_DIM; d++) {
        q->p[d] = p[d];
        if (g->periodic.on[d]) {
            const double length = g->periodic.length[d];
            if (!isfinite(p[d]))
                return;
            q->p[d] = fsi_periodic_wrap_axis(&g->periodic, d, p[d]);
            /* Unwrapped cell indices of p - r and p + r: the span of a cell along d
             * is the same in every image. */
            const double below = q->p[d] - rc, above = q->p[d] + rc;
            const double m_lo = floor((below - g->periodic.lo[d]) / length);
            const double m_hi = floor((above - g->periodic.lo[d]) / length);
            q->lo[d] = fsi_grid_axis_cell(g, d, below - m_lo * length) + (int)m_lo * g->dims[d];
            q->hi[d] = fsi_grid_axis_cell(g, d, above - m_hi * length) + (int)m_hi * g->dims[d];
            if (q->hi[d] - q->lo[d] >= g->dims[d])
                q->hi[d] = q->lo[d] + g->dims[d] - 1; /* r above a period: each cell once */
        } else {
            const double lo = floor((p[d] - rc - g->origin[d]) / g->cell_size);
            const double hi = floor((p[d] + rc - g->origin[d]) / g->cell_size);
            if (!(lo <= (double)(g->dims[d] - 1)) || !(hi >= 0.0))
                return; /* outside the box, or not finite */
            q->lo[d] = lo < 0.0 ? 0 : (int)lo;
            q->hi[d] = hi > (double)(g->dims[d] - 1) ? g->dims[d] - 1 : (int)hi;
        }
        q->c[d] = q->lo[d];
    }
    q->done = 0;
    /* The first strip is opened by _next: set the strip counter one before it. */
    q->c[q->first] = q->lo[q->first] - 1;
}

/* Cell c (unwrapped) along axis d: the stored cell index, and the image offset of
 * its points in shift. */
static inline int fsi_grid_wrap_cell(const fsi_neighbour_grid *g, int d, int c, double *shift)
{
    *shift = 0.0;
    if (!g->periodic.on[d])
        return c;
    const int dims = g->dims[d];
    const int m = c >= 0 ? c / dims : -((-c + dims - 1) / dims);
    *shift = (double)m * g->periodic.length[d];
    return c - m * dims;
}

/* Opens the next strip of cells (lo[0]..hi[0] at c[1..]); returns 0 after the last. */
static inline int fsi_grid_query_next_strip(fsi_grid_query *q)
{
    const fsi_neighbour_grid *g = q->g;
    /* Advance the odometer c[first..FSI_DIM-1]. */
    int d = q->first;
    while (d < FSI_DIM) {
        if (++q->c[d] <= q->hi[d])
            break;
        q->c[d] = q->lo[d];
        d++;
    }
    if (d == FSI_DIM)
        return 0;
    long base = 0; /* index of cell (0, c[1], ...) */
    for (int e = FSI_DIM - 1; e >= 1; e--)
        base = base * g->dims[e] + fsi_grid_wrap_cell(g, e, q->c[e], &q->shift[e]);
    base *= g->dims[0];
    if (q->first == 0) {
        /* x periodic: one cell at a time, each with its own image. */
        const int c0 = fsi_grid_wrap_cell(g, 0, q->c[0], &q->shift[0]);
        q->k = g->cell_start[base + c0];
        q->end = g->cell_start[base + c0 + 1];
    } else {
        q->k = g->cell_start[base + q->lo[0]];
        q->end = g->cell_start[base + q->hi[0] + 1];
    }
    return 1;
}

/* Next point within r: its index and squared distance; 0 when there are no more. */
static inline int fsi_grid_query_next(fsi_grid_query *q, int *j, double *r2)
{
    if (q->done)
        return 0;
    const double *restrict xs = q->g->sorted_x;
    for (;;) {
        while (q->k < q->end) {
            const int k = q->k++;
            double s = 0.0;
            for (int d = 0; d < FSI_DIM; d++) {
                const double dx = xs[(long)k * FSI_DIM + d] + q->shift[d] - q->p[d];
                s += dx * dx;
            }
            if (s <= q->r2) {
                *j = q->g->sorted[k];
                *r2 = s;
                return 1;
            }
        }
        if (!fsi_grid_query_next_strip(q)) {
            q->done = 1;
            return 0;
        }
    }
}

#endif
