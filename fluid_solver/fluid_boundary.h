/* Moving boundary particles: the solid's particles as the fluid sees them (000 §3),
 * replaced from the coupling at every window (the boundary-particle set is dynamic:
 * its size may change from one window to the next, e.g. when the solid fractures).
 *
 * They sit at the tail of the particle arrays, after the fluid and wall particles of the
 * case, whose number never changes; every index below n_fixed keeps its meaning
 * (free-slip flags, probes, the static part of the output).
 *
 * Inside a window the fluid sub-cycles while the solid is known only at the window's
 * start t_k (the solid sends position, velocity and acceleration there), so the
 * boundary moves with that constant acceleration:
 *     x(t_k + tau) = x_k + v_k tau + a_k tau^2 / 2,     v(t_k + tau) = v_k + a_k tau,
 * exact for a rigid translation at constant acceleration and second order in the
 * window otherwise. */
#ifndef FSI_FLUID_BOUNDARY_H
#define FSI_FLUID_BOUNDARY_H

#include <stddef.h>

#include "fluid_particles.h"
#include "participant.h"

typedef struct {
    int n_fixed;                /* fluid and wall particles, before the tail */
    int n;                      /* moving boundary particles in the tail */
    int capacity;
    double *x_start, *v_start;  /* the solid's state at t_k, n * FSI_DIM */
    double *acceleration;       /* a_k, n * FSI_DIM */
    int acceleration_in_pressure;   /* a_k becomes p->boundary_acceleration (the a_S of
                                     * 000 Eq. 52); 0: zero there (the motion keeps a_k) */
} fluid_boundary;

/* An empty boundary behind n_fixed particles (no allocation). */
void fluid_boundary_init(fluid_boundary *b, int n_fixed);
void fluid_boundary_free(fluid_boundary *b);

/* Replaces the tail of p (p->n becomes n_fixed + solid->n) with the solid's particles:
 * id, position, velocity, acceleration, volume V0 and the solid's density
 * (p->boundary_density) from solid, kind FLUID_PARTICLE_MOVING_BOUNDARY, density rho0
 * and mass rho0 V0 until the scheme interpolates them (000 Eqs. 52-54). Returns 0, or
 * -1 with msg (a position, velocity or acceleration not finite, a volume or density
 * not positive, memory) with p and b unchanged. */
int fluid_boundary_set(fluid_boundary *b, fluid_particles *p, const fsi_interface *solid,
                       double rho0, char *msg, size_t msg_size);

/* Puts the tail at t_k + tau: positions, velocities and accelerations
 * (p->boundary_acceleration, the a_S of 000 Eq. 52, zero unless
 * acceleration_in_pressure). */
void fluid_boundary_move(const fluid_boundary *b, fluid_particles *p, double tau);

#endif
