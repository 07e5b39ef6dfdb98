/* core/neighbour_grid: the sorted-cell search must report exactly the points a brute
 * force search reports (no tolerance: both use the same squared-distance test
 * |x_j - p|^2 <= r^2 in the same arithmetic), for random clouds, radii smaller and
 * larger than the cells, query points off the grid, rebuilds that shrink and grow,
 * degenerate clouds (all points equal, a far outlier that forces larger cells). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "neighbour_grid.h"

#include "unit_check.h"

static unsigned long long rng = 88172645463325252ULL;

static double uniform(void)
{
    rng ^= rng << 13;
    rng ^= rng >> 7;
    rng ^= rng << 17;
    return (double)(rng >> 11) / 9007199254740992.0;
}

static int cmp_int(const void *a, const void *b)
{
    const int x = *(const int *)a, y = *(const int *)b;
    return (x > y) - (x < y);
}

static int brute(const double *x, int n, const double *p, double r, int *out)
{
    int c = 0;
    for (int j = 0; j < n; j++) {
        double s = 0.0;
        for (int d = 0; d < FSI_DIM; d++) {
            const double dx = x[j * FSI_DIM + d] - p[d];
            s += dx * dx;
        }
        if (s <= r * r)
            out[c++] = j;
    }
    return c;
}

/* Compares grid and brute force for queries at every point and at random positions. */
static void compare(const fsi_neighbour_grid *g, const double *x, int n, double r,
                    const char *what)
{
    int *a = malloc((size_t)(n + 1) * sizeof *a), *b = malloc((size_t)(n + 1) * sizeof *b);
    double *r2 = malloc((size_t)(n + 1) * sizeof *r2);
    int bad = 0;
    for (int q = 0; q < n + 50 && !bad; q++) {
        double p[FSI_DIM];
        for (int d = 0; d < FSI_DIM; d++)
            p[d] = q < n ? x[q * FSI_DIM + d] : -0.5 + 2.0 * uniform();
        const int na = fsi_grid_neighbours(g, p, r, a, r2, n + 1);
        const int nb = brute(x, n, p, r, b);
        qsort(a, (size_t)na, sizeof *a, cmp_int);
        if (na != nb || memcmp(a, b, (size_t)na * sizeof *a) != 0) {
            CHECK(0, "%s: query %d: grid finds %d points, brute force %d", what, q, na, nb);
            bad = 1;
        }
        for (int k = 0; k < na && !bad; k++)
            if (!(r2[k] <= r * r)) {
                CHECK(0, "%s: reported distance^2 %g > r^2 %g", what, r2[k], r * r);
                bad = 1;
            }
    }
    free(a);
    free(b);
    free(r2);
}

int main(void)
{
    fsi_neighbour_grid g;
    fsi_grid_init(&g);
    const int nmax = 3000;
    double *x = malloc((size_t)nmax * FSI_DIM * sizeof *x);

    /* Random clouds of several sizes, rebuilt in the same grid (shrinking and growing). */
    const int sizes[] = {1000, 200, 3000, 17, 0, 2500};
    for (unsigned s = 0; s < sizeof sizes / sizeof sizes[0]; s++) {
        const int n = sizes[s];
        for (int i = 0; i < n * FSI_DIM; i++)
            x[i] = uniform();
        const double cell = 0.03 + 0.05 * uniform();
        CHECK(fsi_grid_build(&g, x, n, cell) == 0, "build of %d points failed", n);
        char what[64];
        snprintf(what, sizeof what, "cloud of %d, r = cell", n);
        compare(&g, x, n, cell, what);
        snprintf(what, sizeof what, "cloud of %d, r = 2.7 cell", n);
        compare(&g, x, n, 2.7 * cell, what);
        snprintf(what, sizeof what, "cloud of %d, r = 0.3 cell", n);
        compare(&g, x, n, 0.3 * cell, what);
    }

    /* A regular lattice: many points exactly at distance r (the boundary case). */
    {
        const int side = 20;
        int n = 0;
        for (int i = 0; i < side; i++)
            for (int j = 0; j < side; j++) {
                x[n * FSI_DIM + 0] = 0.1 * i + 0.05;
                x[n * FSI_DIM + 1] = 0.1 * j + 0.05;
                for (int d = 2; d < FSI_DIM; d++)
                    x[n * FSI_DIM + d] = 0.0;
                n++;
            }
        CHECK(fsi_grid_build(&g, x, n, 0.3) == 0, "lattice build failed");
        compare(&g, x, n, 0.3, "lattice, r = 3 dx");
        compare(&g, x, n, 0.1, "lattice, r = dx");
        /* Interior point of a 3 dx horizon: 29 lattice points in 2D (itself included). */
        if (FSI_DIM == 2) {
            const int i = 10 * side + 10;
            int out[64];
            const int c = fsi_grid_neighbours(&g, x + i * FSI_DIM, 0.3 + 1e-9, out, NULL, 64);
            CHECK(c == 29, "interior lattice point has %d points within 3 dx, expected 29", c);
        }
    }

    /* All points at one place. */
    {
        const int n = 50;
        for (int i = 0; i < n * FSI_DIM; i++)
            x[i] = 0.25;
        CHECK(fsi_grid_build(&g, x, n, 0.1) == 0, "coincident build failed");
        compare(&g, x, n, 0.0, "coincident points, r = 0");
        compare(&g, x, n, 0.1, "coincident points, r = 0.1");
    }

    /* A far outlier: the cell count must stay bounded, results exact. */
    {
        const int n = 500;
        for (int i = 0; i < n * FSI_DIM; i++)
            x[i] = uniform();
        x[0] = 1e6;
        CHECK(fsi_grid_build(&g, x, n, 0.01) == 0, "outlier build failed");
        CHECK(g.n_cells <= 4L * n + 64, "%ld cells for %d points", g.n_cells, n);
        compare(&g, x, n, 0.05, "outlier cloud");
    }

    /* Non-finite coordinates and bad cell sizes are refused. */
    {
        for (int i = 0; i < 10 * FSI_DIM; i++)
            x[i] = uniform();
        x[3] = NAN;
        CHECK(fsi_grid_build(&g, x, 10, 0.1) == -1, "NaN coordinate accepted");
        int out[4];
        CHECK(fsi_grid_neighbours(&g, x, 0.5, out, NULL, 4) == 0, "failed grid is not empty");
        x[3] = 0.5;
        CHECK(fsi_grid_build(&g, x, 10, 0.0) == -1, "zero cell size accepted");
        double p[FSI_DIM];
        for (int d = 0; d < FSI_DIM; d++)
            p[d] = NAN;
        CHECK(fsi_grid_build(&g, x, 10, 0.1) == 0, "rebuild failed");
        CHECK(fsi_grid_neighbours(&g, p, 0.5, out, NULL, 4) == 0, "NaN query found points");
    }

    fsi_grid_free(&g);
    free(x);
    if (failures)
        printf("%d failure(s)\n", failures);
    else
        printf("neighbour grid: all checks passed\n");
    return failures ? 1 : 0;
}
