/* Candidate neighbour lists with a skin (Verlet lists), shared by the fluid schemes.
 *
 * A scheme needs, at every evaluation of the rates (two per step of the
 * predictor-corrector), every pair closer than the support delta. Searching the cell grid for them each time
 * visits 3^DIM cells, about 2.9 times the support's area in 2D, and the search was
 * half of a step's cost. A Verlet list keeps, per particle, the candidates within
 * delta + skin at its last build; while no particle has moved more than skin / 2
 * since, every pair now within delta is among them (|x_IJ| now <= |x_IJ| then +
 * |d_I| + |d_J|), so the scheme filters the candidates instead of searching the
 * grid and the exact same neighbours within the support are found. The list is
 * rebuilt when a particle has moved half the skin (or the particle count changed):
 * about every skin / (2 v dt) steps.
 *
 * Idle walls. A wall particle with no fluid particle among its candidates has no fluid
 * particle within delta until the next build; nothing reads its own family then (a
 * fluid particle reads a wall through its own row, and in ULPH the wall's M^-1, but
 * only walls within its support, which have the fluid particle in theirs; 000 Eq. 52
 * of an idle wall sums over no fluid). With prune_idle_walls its row is left empty and it is
 * marked idle (ULPH then skips its M). In F1 most of the long floor is idle
 * for most of the run.
 *
 * Rows are in the grid's query order (by cell, then by index) at the build, built in
 * parallel with each particle writing only its own row: the same on any number of
 * threads. */
#ifndef FSI_VERLET_LIST_H
#define FSI_VERLET_LIST_H

#include <stdint.h>

#include "fluid_particles.h"
#include "neighbour_grid.h"
#include "state_store.h"

/* Default skin as a fraction of the support ([fluid.ulph] neighbour_skin). With h = 1.2 dx,
 * delta = 3 h, a skin of 0.1 delta holds 1.21 times the pairs within the support and
 * lasts 0.18 dx of travel of the fastest particle: about 20 steps of F1 at
 * cfl_acoustic = 0.1 and 2 m/s, against a build that costs about three evaluations'
 * filtering. */
#define FLUID_VERLET_SKIN 0.1

typedef struct {
    int n;                      /* particles of the last build */
    double radius;              /* delta + skin of the last build [m] */
    double support, skin;       /* delta and skin of the last update [m] */
    int64_t *offset;            /* n + 1: I's candidates are offset[I] .. offset[I+1]-1 */
    int32_t *candidate;         /* J, J != I, |x_IJ| <= radius at the build */
    uint8_t *idle;              /* 1: an idle wall (above), empty row */
    double *x_built;            /* positions at the build */
    long builds;                /* builds since the last invalidation */
    fsi_neighbour_grid grid;    /* of the positions at the build */
    fsi_periodic periodic;      /* the periodic axes of the grid of the last build */
    int point_capacity;         /* allocated sizes */
    int64_t pair_capacity;
} fluid_verlet;

/* Empty lists (no allocation). */
void fluid_verlet_init(fluid_verlet *v);
void fluid_verlet_free(fluid_verlet *v);

/* Candidates within radius of every particle of p from grid (built from p->x, any
 * cell size), idle walls pruned when asked. Returns 0, or -1 when the grid does not
 * hold p->n points or memory runs out. */
int fluid_verlet_build(fluid_verlet *v, const fsi_neighbour_grid *grid, const fluid_particles *p,
                      double radius, int prune_idle_walls);

/* Forgets the lists: the next fluid_verlet_update rebuilds them (the particles were
 * permuted). */
void fluid_verlet_invalidate(fluid_verlet *v);

/* Keeps the lists when every particle is within skin / 2 of its position at the last
 * build with the same support and count, else rebuilds them (grid included) with
 * radius support + skin, idle walls pruned. Returns 1 when rebuilt, 0 when kept, -1
 * when a position is not finite or memory runs out. */
int fluid_verlet_update(fluid_verlet *v, const fluid_particles *p, double support, double skin);

/* The lists as state (fluid_scheme_save_state): the candidates, idle flags, positions at
 * the build and the build's radius, support and skin under "<prefix>.*". Saved rather
 * than marked stale: a list rebuilt at another step than the first attempt's lists the
 * same pairs in another order, and the sums over them then differ in the last bits.
 * The grid is not state (a rebuild makes it anew). 0, or -1 when memory runs out. */
int fluid_verlet_save(const fluid_verlet *v, fsi_state *st, const char *prefix);

/* The lists saved under prefix back, exactly. 0, or -1 (no such state, or memory). */
int fluid_verlet_restore(fluid_verlet *v, const fsi_state *st, const char *prefix);

#endif
