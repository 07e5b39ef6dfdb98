/* Bonds in CSR form and the crack rule: see solid_bonds.h. */
#include "solid_bonds.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "geometry.h"
#include "lattice_ball.h"
#include "neighbour_grid.h"

void solid_bonds_free(solid_bonds *b)
{
    free(b->offset);
    free(b->neighbour);
    free(b->xi);
    free(b->length);
    free(b->weight);
    free(b->intact);
    memset(b, 0, sizeof *b);
}

int solid_bonds_build(solid_bonds *b, const double *x0, const double *volume, int n,
                      double reach, double dx)
{
    memset(b, 0, sizeof *b);
    b->n_points = n;
    b->offset = calloc((size_t)n + 1, sizeof *b->offset);
    if (!b->offset)
        return -1;
    fsi_neighbour_grid grid;
    fsi_grid_init(&grid);
    const double r = reach + SOLID_BONDS_TOLERANCE * dx;
    if (fsi_grid_build(&grid, x0, n, r) != 0) {
        solid_bonds_free(b);
        return -1;
    }
    /* Pass 1: count; pass 2: fill. The grid's order (by cell, then index) is
     * deterministic, so the rows are too. */
    int64_t total = 0;
    for (int i = 0; i < n; i++) {
        fsi_grid_query q;
        fsi_grid_query_begin(&q, &grid, x0 + (int64_t)i * FSI_DIM, r);
        int j;
        double r2;
        while (fsi_grid_query_next(&q, &j, &r2))
            if (j != i)
                total++;
        b->offset[i + 1] = total;
    }
    b->n_bonds = total;
    const size_t nb = total > 0 ? (size_t)total : 1;
    b->neighbour = malloc(nb * sizeof *b->neighbour);
    b->xi = malloc(nb * FSI_DIM * sizeof *b->xi);
    b->length = malloc(nb * sizeof *b->length);
    b->weight = malloc(nb * sizeof *b->weight);
    b->intact = malloc(nb * sizeof *b->intact);
    if (!b->neighbour || !b->xi || !b->length || !b->weight || !b->intact) {
        fsi_grid_free(&grid);
        solid_bonds_free(b);
        return -1;
    }
    for (int i = 0; i < n; i++) {
        fsi_grid_query q;
        fsi_grid_query_begin(&q, &grid, x0 + (int64_t)i * FSI_DIM, r);
        int64_t k = b->offset[i];
        int j;
        double r2;
        while (fsi_grid_query_next(&q, &j, &r2)) {
            if (j == i)
                continue;
            double len2 = 0.0;
            for (int d = 0; d < FSI_DIM; d++) {
                const double e = x0[(int64_t)j * FSI_DIM + d] - x0[(int64_t)i * FSI_DIM + d];
                b->xi[k * FSI_DIM + d] = e;
                len2 += e * e;
            }
            b->neighbour[k] = j;
            b->length[k] = sqrt(len2);
            b->weight[k] = volume[j];
            b->intact[k] = 1;
            k++;
        }
    }
    fsi_grid_free(&grid);
    return 0;
}

int64_t *solid_bonds_reverse(const solid_bonds *b)
{
    int64_t *reverse = malloc((b->n_bonds > 0 ? (size_t)b->n_bonds : 1) * sizeof *reverse);
    if (!reverse)
        return NULL;
    for (int i = 0; i < b->n_points; i++)
        for (int64_t q = b->offset[i]; q < b->offset[i + 1]; q++) {
            const int j = b->neighbour[q];
            int64_t s = b->offset[j];
            while (s < b->offset[j + 1] && b->neighbour[s] != i)
                s++;
            if (s == b->offset[j + 1]) {
                free(reverse);
                return NULL;
            }
            reverse[q] = s;
        }
    return reverse;
}

int64_t solid_bonds_cut(solid_bonds *b, const double *x0, const double *from,
                        const double *to)
{
    int64_t pairs = 0;
    for (int i = 0; i < b->n_points; i++)
        for (int64_t k = b->offset[i]; k < b->offset[i + 1]; k++) {
            const int j = b->neighbour[k];
            if (b->intact[k] &&
                solid_crack_cuts(x0 + (int64_t)i * FSI_DIM, x0 + (int64_t)j * FSI_DIM, from, to)) {
                b->intact[k] = 0;
                pairs += i < j;
            }
        }
    return pairs;
}

int solid_bonds_cut_cracks(solid_bonds *b, const fsi_case *c, const char *role,
                           const double *x0, const char *model, char *msg, size_t msg_size)
{
    solid_geometry g;
    if (solid_geometry_read(&g, c, role, msg, msg_size) != 0)
        return -1;
    for (int i = 0; i < g.n_cracks; i++) {
        const int64_t pairs = solid_bonds_cut(b, x0, g.cracks[i].from, g.cracks[i].to);
        fprintf(stderr, "%s: [%s] breaks %lld bonds from the start\n", model,
                g.cracks[i].section, (long long)pairs);
    }
    solid_geometry_free(&g);
    return 0;
}

int solid_bonds_full_count(double reach, double dx)
{
    int count = 0;
    fsi_lattice_ball ball;
    double len;
    fsi_lattice_ball_begin(&ball, reach + SOLID_BONDS_TOLERANCE * dx, dx);
    while (fsi_lattice_ball_next(&ball, &len))
        count++;
    return count;
}
