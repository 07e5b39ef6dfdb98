/* The fluid's particles, structure of arrays, owned by the fluid main loop
 * (fluid_main.c). Schemes (ulph/, ...) read them and update the fields they
 * own (density, pressure, volume); they never reallocate them. The main loop may: the
 * solid's particles at the tail change in number between windows (fluid_boundary.h),
 * and the fixed part is sorted by cell now and then (its order is not stable; id is).
 * Vectors are particle-major: x[i * FSI_DIM + d].
 *
 * Three kinds of particle share the arrays (flags): fluid particles, fixed wall
 * (ghost) particles (000 §2.3) and moving boundary particles, the solid particles
 * received from the coupling (000 §3). All of them are neighbours in the non-local
 * operators; which ones are integrated in time is the main loop's business.
 *
 * Mass and volume are both kept: a fluid particle's mass is constant and its volume
 * follows its density, V = m / rho (000 Eq. 16), set by the scheme whenever it
 * changes the density; a wall or moving boundary particle has a fixed volume V0 (the
 * solid sends its own) and its mass follows its interpolated density, m = rho V0
 * (000 Eqs. 52-54). */
#ifndef FSI_FLUID_PARTICLES_H
#define FSI_FLUID_PARTICLES_H

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "dim.h"

/* Kind of a particle (exactly one of them is set in flags). */
enum {
    FLUID_PARTICLE_FLUID = 1,
    FLUID_PARTICLE_WALL = 2,            /* fixed boundary particle */
    FLUID_PARTICLE_MOVING_BOUNDARY = 4, /* solid particle seen by the fluid (coupling) */
};

#define FLUID_PARTICLE_KIND_MASK                                                         \
    (FLUID_PARTICLE_FLUID | FLUID_PARTICLE_WALL | FLUID_PARTICLE_MOVING_BOUNDARY)

typedef struct {
    int n;
    double spacing;         /* initial particle spacing dx [m] */
    int32_t *id;            /* stable particle id (index at creation; the solid's id for
                             * moving boundary particles) */
    double *x;              /* current position [m] */
    double *v;              /* velocity [m/s] */
    double *mass;           /* [kg] (2D: per unit thickness, kg/m) */
    double *volume;         /* V = m / rho [m^DIM] (2D: per unit thickness) */
    double *density;        /* rho [kg/m^3] */
    double *pressure;       /* p [Pa] */
    double *boundary_acceleration; /* a_S of a wall or moving boundary particle (000
                             * Eq. 52): its prescribed or received acceleration; 0 for
                             * fluid particles and fixed walls [m/s^2] */
    double *boundary_density; /* the density of the solid a moving boundary particle
                             * belongs to, as received [kg/m^3]; 0 for fluid and wall
                             * particles. Times volume it is the solid particle's mass
                             * (up to its volume ratio J where the solid's density changes,
                             * docs/protocol.md); density and mass above are the fluid's
                             * interpolated ones (000 Eqs. 52-54). */
    uint8_t *flags;         /* FLUID_PARTICLE_* */
} fluid_particles;

/* The spacing of a lattice whose cells have this volume, V^(1/DIM): the own spacing of
 * a wall or solid particle, whose volume is fixed (a solid may be finer than the fluid). */
static inline double fluid_particle_side(double volume)
{
#if FSI_DIM == 2
    return sqrt(volume);
#else
    return cbrt(volume);
#endif
}

/* Frees the arrays and leaves p empty (n = 0, pointers NULL). */
static inline void fluid_particles_free(fluid_particles *p)
{
    free(p->id);
    free(p->x);
    free(p->v);
    free(p->mass);
    free(p->volume);
    free(p->density);
    free(p->pressure);
    free(p->boundary_acceleration);
    free(p->boundary_density);
    free(p->flags);
    *p = (fluid_particles){0};
}

/* Allocates n particles, every field zero. Returns 0, or -1 (p left empty) when
 * memory runs out or n is negative. */
static inline int fluid_particles_alloc(fluid_particles *p, int n, double spacing)
{
    *p = (fluid_particles){0};
    if (n < 0)
        return -1;
    const size_t m = n > 0 ? (size_t)n : 1;
    p->n = n;
    p->spacing = spacing;
    p->id = calloc(m, sizeof *p->id);
    p->x = calloc(m * FSI_DIM, sizeof *p->x);
    p->v = calloc(m * FSI_DIM, sizeof *p->v);
    p->mass = calloc(m, sizeof *p->mass);
    p->volume = calloc(m, sizeof *p->volume);
    p->density = calloc(m, sizeof *p->density);
    p->pressure = calloc(m, sizeof *p->pressure);
    p->boundary_acceleration = calloc(m * FSI_DIM, sizeof *p->boundary_acceleration);
    p->boundary_density = calloc(m, sizeof *p->boundary_density);
    p->flags = calloc(m, sizeof *p->flags);
    if (!p->id || !p->x || !p->v || !p->mass || !p->volume || !p->density || !p->pressure ||
        !p->boundary_acceleration || !p->boundary_density || !p->flags) {
        fluid_particles_free(p);
        return -1;
    }
    return 0;
}

/* Grows or shrinks p to n particles, keeping the first min(n, p->n) and zeroing the
 * new ones. Returns 0, or -1 (p unchanged) when memory runs out or n is negative. (A
 * new field goes into fluid_particles_alloc, _free and _resize here, and into the saved
 * state: fluid_main.c's save_state and restore_state.) */
static inline int fluid_particles_resize(fluid_particles *p, int n)
{
    if (n < 0)
        return -1;
    if (n == p->n)
        return 0;
    fluid_particles q;
    if (fluid_particles_alloc(&q, n, p->spacing) != 0)
        return -1;
    const size_t keep = (size_t)(n < p->n ? n : p->n);
    memcpy(q.id, p->id, keep * sizeof *q.id);
    memcpy(q.x, p->x, keep * FSI_DIM * sizeof *q.x);
    memcpy(q.v, p->v, keep * FSI_DIM * sizeof *q.v);
    memcpy(q.mass, p->mass, keep * sizeof *q.mass);
    memcpy(q.volume, p->volume, keep * sizeof *q.volume);
    memcpy(q.density, p->density, keep * sizeof *q.density);
    memcpy(q.pressure, p->pressure, keep * sizeof *q.pressure);
    memcpy(q.boundary_acceleration, p->boundary_acceleration,
           keep * FSI_DIM * sizeof *q.boundary_acceleration);
    memcpy(q.boundary_density, p->boundary_density, keep * sizeof *q.boundary_density);
    memcpy(q.flags, p->flags, keep * sizeof *q.flags);
    fluid_particles_free(p);
    *p = q;
    return 0;
}

#endif