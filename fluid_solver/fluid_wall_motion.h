/* Walls that move with a prescribed rigid motion (fluid_motion.h): before every
 * evaluation of the rates the main loop puts each moving wall particle at
 * x0 + X(t) with velocity X'(t) and acceleration X''(t), the a_S of 000 Eq. 52
 * (p->boundary_acceleration). Several walls with the same law move as
 * one tank. */
#ifndef FSI_FLUID_WALL_MOTION_H
#define FSI_FLUID_WALL_MOTION_H

#include <stddef.h>

#include "fluid_geometry.h"
#include "fluid_particles.h"
#include "state_store.h"

typedef struct {
    int n_moving;               /* moving wall particles */
    int *particle;              /* their indices */
    const fluid_motion **law;   /* their motion (the box's) */
    double *x_start;            /* their position in the case, n_moving * FSI_DIM */
    const fluid_motion *tank;   /* the one law every moving wall follows, or NULL when
                                 * none moves or laws differ */
} fluid_wall_motion;

/* From the boxes of g, in the particle order of fluid_geometry_build. Returns 0, or -1
 * with a message. */
int fluid_wall_motion_init(fluid_wall_motion *w, const fluid_geometry *g,
                           const fluid_particles *p, char *msg, size_t msg_size);

/* The particles were permuted: the particle at index i is now at new_index[i]. */
void fluid_wall_motion_renumber(fluid_wall_motion *w, const int *new_index);

/* Moving wall particles to their position, velocity and acceleration
 * (p->boundary_acceleration) at time t. */
void fluid_wall_motion_apply(fluid_wall_motion *w, double t, fluid_particles *p);

/* Widens the box [box_min, box_max] by the reach of every moving wall along each axis,
 * so that a box around the initial particles still holds the walls at any time. */
void fluid_wall_motion_widen(const fluid_wall_motion *w, double *box_min, double *box_max);

/* Power the walls give the fluid at time t, from the fluid's rates dv_dt: with one
 * rigid motion V(t) of every moving wall the force the walls exert on the fluid is
 * sum_f m_f (a_f - g) (fluid pairs cancel: the ULPH forces conserve momentum), and its
 * power is that force . V(t). 0 when nothing moves, NAN when the walls follow different
 * laws (then the power is not known from the fluid's rates alone). */
double fluid_wall_motion_power(const fluid_wall_motion *w, double t, const fluid_particles *p,
                               const double *dv_dt, const double *gravity);

/* The moving wall particles' indices (they follow the particle order) under
 * "<prefix>.particle", and back. 0, or -1 (memory; restore: no such state). */
int fluid_wall_motion_save_state(const fluid_wall_motion *w, fsi_state *st, const char *prefix);
int fluid_wall_motion_restore_state(fluid_wall_motion *w, const fsi_state *st,
                                    const char *prefix);

void fluid_wall_motion_free(fluid_wall_motion *w);

#endif
