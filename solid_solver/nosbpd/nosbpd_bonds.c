/* Families in CSR form: see nosbpd_bonds.h. */
#include "nosbpd_bonds.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "lattice_ball.h"

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

int nosbpd_bonds_build(nosbpd_bonds *b, const double *x0, const double *volume, int n,
                       double delta, double dx, nosbpd_influence kind)
{
    if (solid_bonds_build(b, x0, volume, n, delta, dx) != 0)
        return -1;
    /* Coincident points (len 0) would make 'inverse' infinite: such a bond gets no
     * weight (and the geometry check should not let it happen). */
    for (int64_t k = 0; k < b->n_bonds; k++)
        b->weight[k] = b->length[k] > 0.0
                           ? nosbpd_influence_value(kind, b->length[k], delta) * b->weight[k]
                           : 0.0;
    return 0;
}

nosbpd_full_family nosbpd_full_family_of_lattice(double delta, double dx, nosbpd_influence kind)
{
    nosbpd_full_family f = {0, 0.0, 0.0};
    const double vol = pow(dx, FSI_DIM);
    fsi_lattice_ball ball;
    double len;
    fsi_lattice_ball_begin(&ball, delta + SOLID_BONDS_TOLERANCE * dx, dx);
    while (fsi_lattice_ball_next(&ball, &len)) {
        f.count++;
        f.sum_volume_over_length += vol / len;
        f.sum_weight += nosbpd_influence_value(kind, len, delta) * vol;
    }
    return f;
}
