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
    /* Also SOLID_CLAMPED: a clamp point that mirrors the body across the clamp face
     * (x - x0 = -(x_m - x0_m) for its partner m = mirror[i]). It is not material: no
     * mass, no strain energy, no force state; it only shows the body's families the
     * displacement field continued past the clamp (docs/nosbpd.md, "Clamps"). */
    SOLID_MIRRORED = 4,
    /* In a no_failure region: no bond with an end here breaks (docs/nosbpd.md,
     * "No-failure zones"). */
    SOLID_UNBREAKABLE = 8,
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
    int32_t *mirror;        /* partner of a SOLID_MIRRORED point, else -1; NULL if none */
} solid_particles;

#endif
