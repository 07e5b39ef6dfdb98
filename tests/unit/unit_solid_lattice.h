/* A regular lattice of solid particles for the tests (test_nosbpd_*.c, the solid
 * contract): points at (i + 1/2) dx, reference volume dx^DIM, no flags. */
#ifndef FSI_UNIT_SOLID_LATTICE_H
#define FSI_UNIT_SOLID_LATTICE_H

#include <math.h>
#include <stdlib.h>

#include "geometry.h"
#include "solid_particles.h"

/* nx x ny (x nz) lattice of spacing dx, points at (i + 1/2) dx, density rho. */
static inline solid_particles *test_lattice(int nx, int ny, int nz, double dx, double rho)
{
    solid_particles *p = calloc(1, sizeof *p);
    const int n = FSI_DIM == 2 ? nx * ny : nx * ny * nz;
    p->n = n;
    p->spacing = dx;
    p->id = calloc((size_t)n, sizeof *p->id);
    p->x0 = calloc((size_t)n * FSI_DIM, sizeof *p->x0);
    p->x = calloc((size_t)n * FSI_DIM, sizeof *p->x);
    p->v = calloc((size_t)n * FSI_DIM, sizeof *p->v);
    p->a = calloc((size_t)n * FSI_DIM, sizeof *p->a);
    p->volume = calloc((size_t)n, sizeof *p->volume);
    p->density = calloc((size_t)n, sizeof *p->density);
    p->flags = calloc((size_t)n, sizeof *p->flags);
    p->block = calloc((size_t)n, sizeof *p->block);
    int k = 0;
    for (int c = 0; c < (FSI_DIM == 2 ? 1 : nz); c++)
        for (int b = 0; b < ny; b++)
            for (int a = 0; a < nx; a++) {
                const int idx[3] = {a, b, c};
                for (int d = 0; d < FSI_DIM; d++)
                    p->x0[k * FSI_DIM + d] = p->x[k * FSI_DIM + d] = (idx[d] + 0.5) * dx;
                p->id[k] = k;
                p->volume[k] = pow(dx, FSI_DIM);
                p->density[k] = rho;
                k++;
            }
    return p;
}

static inline void test_lattice_free(solid_particles *p)
{
    solid_particles_free(p);
    free(p);
}

#endif
