/* The solid's material points, structure of arrays, owned by the solid main loop
 * (solid_main.c). Models read them and never reallocate them.
 * Vectors are particle-major: x[i * FSI_DIM + d]. */
#ifndef FSI_SOLID_PARTICLES_H
#define FSI_SOLID_PARTICLES_H

#include <stdint.h>

#include "dim.h"

enum {
    SOLID_CLAMPED = 1,      /* displacement held at zero (velocity and acceleration 0) */
    SOLID_LOADED = 2,       /* carries a prescribed external load from the case */
};

typedef struct {
    int n;
    double spacing;         /* lattice spacing dx [m] */
    int32_t *id;            /* stable particle id (index at creation) */
    double *x0;             /* reference position [m] */
    double *x;              /* current position [m] */
    double *v;              /* velocity [m/s] */
    double *a;              /* acceleration [m/s^2] */
    double *volume;         /* reference volume dx^FSI_DIM [m^DIM] (2D: per unit thickness) */
    double *density;        /* reference density rho0 [kg/m^DIM] */
    uint8_t *flags;         /* SOLID_* bits */
    int32_t *block;         /* index of the block the point came from */
} solid_particles;

#endif
