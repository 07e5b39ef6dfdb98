/* Fluid leaking through walls: a fluid particle that passes through a [fluid.wall]
 * box from one side to the other stops the run (the walls of 000 §2.3 are meant to
 * hold the fluid; one it has crossed no longer does, and the water that fell through
 * the floor of F1 at a too low c0 went unnoticed). Which sides of the domain are walled
 * is not guessed: the check follows every fluid particle against every wall box and
 * every axis d that is not periodic. Walls of another shape (turned boxes, discs,
 * polygons: core/shape.h) have no slabs along the axes and are not followed.
 *
 * A particle is in the wall's shadow along d when its other, non-periodic coordinates
 * lie within the wall's extent (the box moved by its prescribed motion, fluid_motion.h);
 * there it is below the wall (x_d < min_d), in it, or above it (x_d > max_d). A particle
 * seen below the wall and then, without leaving the shadow, more than the tolerance
 * (one kernel support) above it has gone through it, and the other way round; leaving
 * the shadow forgets the side. So water that flows over the top of a wall, off the end
 * of a floor or round a wall's end (an open-topped tank, a dam break onto an open
 * floor, the gap under a gate) never counts, and neither does a particle that sinks
 * into a wall and comes back out on its own side. The check runs after every step, when
 * a particle has moved a fraction of a smoothing length. The same sides tell
 * fluid_leak_hold_and_check where to put back a particle that came into a wall, for a
 * scheme that asks for it (fluid_scheme_holds_at_walls). */
#ifndef FSI_FLUID_LEAK_H
#define FSI_FLUID_LEAK_H

#include <stddef.h>

#include "fluid_geometry.h"
#include "fluid_particles.h"
#include "periodic.h"
#include "state_store.h"

typedef struct {
    const fluid_geometry *geometry;     /* the walls (not owned) */
    int n_walls;
    int *wall;                  /* the walls' indices in geometry->boxes */
    double *box_lo, *box_hi;    /* where they are at the last check */
    double *box_v;              /* and their velocities */
    int periodic[FSI_DIM];
    double tolerance;           /* how far past a wall counts [m] */
    int n;                      /* particles the side table covers */
    unsigned char *side;        /* n * n_walls * FSI_DIM: 0 unknown, 1 below, 2 above */
} fluid_leak;

/* What fluid_leak_check found. */
typedef struct {
    int particle;               /* index of the particle, -1: nothing */
    int box;                    /* the wall's index in geometry->boxes */
    int axis;                   /* along which it crossed */
    int upward;                 /* 1: from below min to above max along axis */
    double face;                /* the face it ended up beyond [m] */
} fluid_leak_crossing;

/* Sets up the check for the first n particles of p (the case's fluid and walls) at
 * time t. Returns 0, or -1 when memory runs out. */
int fluid_leak_init(fluid_leak *l, const fluid_geometry *g, const fsi_periodic *per,
                    double tolerance, const fluid_particles *p, int n, double t);

/* Updates the sides of every fluid particle among the first n of p at time t and
 * returns 1 with the first crossing found, or 0. */
int fluid_leak_check(fluid_leak *l, const fluid_particles *p, double t,
                     fluid_leak_crossing *found);

/* The same pass, which first puts every fluid particle that lies inside a followed wall
 * box, having come in from a known side, back on the face it came through (of the axes
 * it came in along, the one of least depth), with its velocity into the wall set to the
 * wall's, and adds to *held how many it moved: a kinematic non-penetration constraint
 * for schemes whose forces do not hold every particle out (fluid_scheme_holds_at_walls).
 * A particle inside a wall since the start, or from an unknown side, stays. */
int fluid_leak_hold_and_check(fluid_leak *l, fluid_particles *p, double t, long *held,
                              fluid_leak_crossing *found);

/* The particles were permuted: the particle now at index k was at sorted[k]. Returns 0,
 * or -1 when memory runs out (nothing changed). */
int fluid_leak_reorder(fluid_leak *l, const int *sorted);

/* The sides of every particle against every wall under "<prefix>.side" (the walls'
 * boxes are computed at every check), and back. 0, or -1 (memory; restore: no such
 * state, or one for another number of particles or walls). */
int fluid_leak_save_state(const fluid_leak *l, fsi_state *st, const char *prefix);
int fluid_leak_restore_state(fluid_leak *l, const fsi_state *st, const char *prefix);

void fluid_leak_free(fluid_leak *l);

#endif
