/* Families in CSR form: see nosbpd_bonds.h. */
#include "nosbpd_bonds.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "geometry.h"
#include "lattice_ball.h"
#include "neighbour_grid.h"

double nosbpd_influence_value(nosbpd_influence kind, double r, double delta)
{
    switch (kind) {
    case NOSBPD_INFLUENCE_INVERSE:
        return delta / r;
    case NOSBPD_INFLUENCE_GAUSSIAN: {
        const double q = 2.0 * r / delta;
        return exp(-q * q);
    }
    case NOSBPD_INFLUENCE_ONE:
    default:
        return 1.0;
    }
}

int nosbpd_influence_parse(const char *name, nosbpd_influence *kind)
{
    if (!name)
        return -1;
    if (strcmp(name, "one") == 0)
        *kind = NOSBPD_INFLUENCE_ONE;
    else if (strcmp(name, "inverse") == 0)
        *kind = NOSBPD_INFLUENCE_INVERSE;
    else if (strcmp(name, "gaussian") == 0)
        *kind = NOSBPD_INFLUENCE_GAUSSIAN;
    else
        return -1;
    return 0;
}

void nosbpd_bonds_free(nosbpd_bonds *b)
{
    free(b->offset);
    free(b->neighbour);
    free(b->xi);
    free(b->length);
    free(b->weight);
    free(b->intact);
    memset(b, 0, sizeof *b);
}

int nosbpd_bonds_build(nosbpd_bonds *b, const double *x0, const double *volume, int n,
                       double delta, double dx, nosbpd_influence kind)
{
    memset(b, 0, sizeof *b);
    b->n_points = n;
    b->offset = calloc((size_t)n + 1, sizeof *b->offset);
    if (!b->offset)
        return -1;
    fsi_neighbour_grid grid;
    fsi_grid_init(&grid);
    const double reach = delta + NOSBPD_HORIZON_TOLERANCE * dx;
    if (fsi_grid_build(&grid, x0, n, reach) != 0) {
        nosbpd_bonds_free(b);
        return -1;
    }
    /* Pass 1: count; pass 2: fill. The grid's order (by cell, then index) is
     * deterministic, so the rows are too. */
    int64_t total = 0;
    for (int i = 0; i < n; i++) {
        fsi_grid_query q;
        fsi_grid_query_begin(&q, &grid, x0 + (int64_t)i * FSI_DIM, reach);
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
        nosbpd_bonds_free(b);
        return -1;
    }
    for (int i = 0; i < n; i++) {
        fsi_grid_query q;
        fsi_grid_query_begin(&q, &grid, x0 + (int64_t)i * FSI_DIM, reach);
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
            const double len = sqrt(len2);
            b->neighbour[k] = j;
            b->length[k] = len;
            /* Coincident points (len 0) would make 'inverse' infinite: such a bond
             * gets no weight (and the geometry check should not let it happen). */
            b->weight[k] = len > 0.0 ? nosbpd_influence_value(kind, len, delta) * volume[j] : 0.0;
            b->intact[k] = 1;
            k++;
        }
    }
    fsi_grid_free(&grid);
    return 0;
}

int64_t nosbpd_bonds_cut(nosbpd_bonds *b, const double *x0, const double *from,
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

nosbpd_full_family nosbpd_full_family_of_lattice(double delta, double dx, nosbpd_influence kind)
{
    nosbpd_full_family f = {0, 0.0, 0.0};
    const double vol = pow(dx, FSI_DIM);
    fsi_lattice_ball ball;
    double len;
    fsi_lattice_ball_begin(&ball, delta + NOSBPD_HORIZON_TOLERANCE * dx, dx);
    while (fsi_lattice_ball_next(&ball, &len)) {
        f.count++;
        f.sum_volume_over_length += vol / len;
        f.sum_weight += nosbpd_influence_value(kind, len, delta) * vol;
    }
    return f;
}
