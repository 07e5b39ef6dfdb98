/* Periodic axes of core/neighbour_grid (core/periodic.h): for random clouds in a box
 * periodic along x, along y, or both (2D; and z in 3D), the grid must report every
 * point whose nearest periodic image is within r of the query and no other, each
 * once, with that image's squared distance; queries from points outside the period
 * (a particle mid-step past the boundary) must find the same set as from their wrapped
 * position. The grid adds the image offset to the wrapped stored position, brute force
 * takes the minimum image of the difference: the two round differently, so points within
 * 1e-12 r^2 of the sphere are not judged (none are expected; the count is printed). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "neighbour_grid.h"
#include "periodic.h"

#include "unit_check.h"

static unsigned long long rng = 0x2545F4914F6CDD1DULL;

static double uniform(void)
{
    rng ^= rng << 13;
    rng ^= rng >> 7;
    rng ^= rng << 17;
    return (double)(rng >> 11) / 9007199254740992.0;
}

static double image_distance2(const fsi_periodic *per, const double *a, const double *b)
{
    double rel[FSI_DIM], s = 0.0;
    for (int d = 0; d < FSI_DIM; d++)
        rel[d] = b[d] - a[d];
    fsi_periodic_min_image(per, rel);
    for (int d = 0; d < FSI_DIM; d++)
        s += rel[d] * rel[d];
    return s;
}

static int borderline;

/* Grid query at p against brute force; returns 1 when they agree. */
static int agree(const fsi_neighbour_grid *g, const fsi_periodic *per, const double *x, int n,
                 const double *p, double r, char *seen)
{
    memset(seen, 0, (size_t)n);
    fsi_grid_query q;
    fsi_grid_query_begin(&q, g, p, r);
    int j, ok = 1;
    double r2;
    while (fsi_grid_query_next(&q, &j, &r2)) {
        const double b2 = image_distance2(per, p, &x[j * FSI_DIM]);
        ok &= !seen[j] && fabs(r2 - b2) <= 1e-12 * r * r;
        seen[j] = 1;
    }
    for (int k = 0; k < n; k++) {
        const double b2 = image_distance2(per, p, &x[k * FSI_DIM]);
        if (fabs(b2 - r * r) <= 1e-12 * r * r) {
            borderline++;
            continue;
        }
        ok &= (b2 < r * r) == (seen[k] != 0);
    }
    return ok;
}

int main(void)
{
    const int n = 2000;
    double *x = malloc((size_t)n * FSI_DIM * sizeof *x);
    char *seen = malloc((size_t)n);
    const double lo[3] = {-0.3, 1.0, 0.2}, length[3] = {1.0, 0.55, 0.7};
    fsi_neighbour_grid g;
    fsi_grid_init(&g);
    for (int mask = 1; mask < (1 << FSI_DIM); mask++) {
        fsi_periodic per = {{0}, {0}, {0}};
        for (int d = 0; d < FSI_DIM; d++) {
            per.on[d] = (mask >> d) & 1;
            per.lo[d] = lo[d];
            per.length[d] = length[d];
        }
        for (int i = 0; i < n * FSI_DIM; i++)
            x[i] = lo[i % FSI_DIM] + length[i % FSI_DIM] * uniform();
        fsi_grid_set_periodic(&g, &per);
        /* r = cell (ULPH's use), r below the cell, and a period over 3.2 cells. */
        const double radii[3] = {0.09, 0.05, 0.17};
        for (int t = 0; t < 3; t++) {
            const double r = radii[t], cell = t == 1 ? 0.09 : r;
            CHECK(fsi_grid_build(&g, x, n, cell) == 0, "mask %d: build failed", mask);
            int bad = 0;
            for (int i = 0; i < n; i += 7)
                bad += !agree(&g, &per, x, n, &x[i * FSI_DIM], r, seen);
            for (int k = 0; k < 200; k++) {
                double p[FSI_DIM], shifted[FSI_DIM];
                for (int d = 0; d < FSI_DIM; d++) {
                    p[d] = lo[d] + length[d] * uniform();
                    /* The same point one or two periods away along periodic axes. */
                    shifted[d] = p[d] + (per.on[d] ? length[d] * (k % 3 - 1) * (1 + k % 2) : 0.0);
                }
                bad += !agree(&g, &per, x, n, p, r, seen);
                if (per.on[0] || per.on[1])
                    bad += !agree(&g, &per, x, n, shifted, r, seen);
            }
            CHECK(bad == 0, "mask %d, r = %g: %d queries disagree with brute force", mask, r, bad);
        }
    }
    /* Fewer than three cells per period is refused. */
    fsi_periodic narrow = {{1}, {0.0}, {0.25}};
    fsi_grid_set_periodic(&g, &narrow);
    for (int i = 0; i < 10 * FSI_DIM; i++)
        x[i] = 0.02 * i;
    CHECK(fsi_grid_build(&g, x, 10, 0.1) == -1, "a period of 2.5 cells was accepted");
    /* Wrapping puts positions in [lo, lo + length). */
    fsi_periodic both = {{1, 1}, {-0.3, 1.0}, {1.0, 0.55}};
    double w[FSI_DIM] = {0};
    w[0] = 0.7;
    w[1] = 1.0 - 1e-17;
    fsi_periodic_wrap(&both, w);
    CHECK(w[0] >= -0.3 && w[0] < 0.7 && w[1] >= 1.0 && w[1] < 1.55,
          "wrap left (%.17g, %.17g) outside the period", w[0], w[1]);
    printf("periodic grid: %d borderline pairs not judged\n", borderline);
    fsi_grid_free(&g);
    free(x);
    free(seen);
    return unit_check_report("test_periodic_grid");
}
