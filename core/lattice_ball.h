/* The lengths of the offsets of a regular lattice (spacing dx) that lie within a radius
 * r of a lattice point, the point itself left out: the full neighbourhood an interior
 * point has. The solid uses it for the family every interior point shares (the model's
 * normalising sums) and for the interface band (points with fewer neighbours than this
 * are near a surface). Callers add a small tolerance to r, so lattice distances equal
 * to the radius up to round-off count as inside.
 *
 *   fsi_lattice_ball ball;
 *   double len;
 *   fsi_lattice_ball_begin(&ball, r, dx);
 *   while (fsi_lattice_ball_next(&ball, &len))
 *       ... one offset, of length len ...
 */
#ifndef FSI_LATTICE_BALL_H
#define FSI_LATTICE_BALL_H

#include <math.h>

#include "dim.h"

typedef struct {
    double dx, r2;
    int m;                      /* index range -m..m per axis */
    int idx[FSI_DIM];           /* the next offset to look at, in spacings */
    int done;
} fsi_lattice_ball;

static inline void fsi_lattice_ball_begin(fsi_lattice_ball *b, double r, double dx)
{
    b->dx = dx;
    b->r2 = r * r;
    b->m = (int)ceil(r / dx);
    for (int d = 0; d < FSI_DIM; d++)
        b->idx[d] = -b->m;
    b->done = !(r > 0.0 && dx > 0.0);
}

/* Moves to the next offset within the radius; 0 when there is none left. */
static inline int fsi_lattice_ball_next(fsi_lattice_ball *b, double *length)
{
    while (!b->done) {
        double len2 = 0.0;
        int origin = 1;
        for (int d = 0; d < FSI_DIM; d++) {
            const double e = b->idx[d] * b->dx;
            len2 += e * e;
            origin &= b->idx[d] == 0;
        }
        int d = 0;
        while (d < FSI_DIM && ++b->idx[d] > b->m)
            b->idx[d++] = -b->m;
        b->done = d == FSI_DIM;
        if (!origin && len2 <= b->r2) {
            *length = sqrt(len2);
            return 1;
        }
    }
    return 0;
}

#endif
