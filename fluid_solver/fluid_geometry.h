/* The fluid's geometry from the case: boxes of water ([fluid.block NAME]) and of fixed
 * wall particles ([fluid.wall NAME]), both filled with the lattice min + (i + 1/2) dx
 * along each axis (n_d = (max_d - min_d) / dx points, a whole number checked by
 * fluid_geometry_check), or turned boxes, discs and polygons filled as core/shape.h
 * says (a wall's shape is filled with wall particles like a block's with water), and
 * probe points. A solid_geometry's counterpart for the
 * fluid; the two share nothing but the lattice convention, so that a wall box drawn
 * on the faces of a solid block lines up with it. */
#ifndef FSI_FLUID_GEOMETRY_H
#define FSI_FLUID_GEOMETRY_H

#include <stddef.h>

#include "case_file.h"
#include "dim.h"
#include "fluid_motion.h"
#include "fluid_particles.h"
#include "shape.h"

/* Relative tolerance (in spacings) of "a whole number of spacings" and of boxes. */
#define FLUID_GEOMETRY_TOL 1e-6

/* Most particles: ids are int32. */
#define FLUID_MAX_LATTICE 2147483647.0

typedef struct {
    const char *section;        /* "fluid.block NAME" or "fluid.wall NAME" (the case's) */
    fsi_shape shape;            /* a box (min, max, count) or another shape (core/shape.h) */
    int is_wall, free_slip;
    fluid_motion motion;        /* a wall's prescribed motion (kind NONE: fixed) */
} fluid_box;

typedef struct {
    const char *section;        /* "fluid.probe NAME" */
    double point[FSI_DIM];
    int elevation;              /* quantity = elevation (else pressure) */
    const char *follow;         /* the wall NAME the point moves with, or NULL */
    int follow_box;             /* its index in boxes, -1 (none, or no such wall) */
} fluid_probe_point;

typedef struct {
    double spacing;
    int n_boxes, n_probes;      /* boxes: the blocks in file order, then the walls */
    fluid_box *boxes;
    fluid_probe_point *probes;
} fluid_geometry;

/* Reads [role] spacing and the block, wall and probe sections of a case. Returns 0,
 * or -1 with a message when memory runs out. */
int fluid_geometry_read(fluid_geometry *g, const fsi_case *c, const char *role, char *msg,
                        size_t msg_size);
void fluid_geometry_free(fluid_geometry *g);

/* (max - min) / spacing along 'axis', not rounded. */
double fluid_box_spacings(const fluid_box *b, double spacing, int axis);
/* Lattice points of every box, as a double (no overflow). */
double fluid_geometry_lattice_size(const fluid_geometry *g);
/* Particles of one box (its shape's lattice points). */
double fluid_box_points(const fluid_box *b);
/* 1 when two boxes share a volume (fsi_shapes_overlap). */
int fluid_boxes_overlap(const fluid_box *a, const fluid_box *b, double spacing);
/* True when x lies in the closed shape, within FLUID_GEOMETRY_TOL spacings. */
int fluid_box_contains(const fluid_box *b, double spacing, const double *x);

/* Creates the particles: fluid particles (FLUID_PARTICLE_FLUID) of every block, then
 * wall particles (FLUID_PARTICLE_WALL) of every wall; id = index, v = 0, volume
 * dx^DIM, mass rho0 dx^DIM, density rho0, pressure 0. free_slip[i] (allocated here,
 * n entries) is 1 for the particles of a free-slip wall. Returns 0, or -1 with a
 * message. */
int fluid_geometry_build(const fluid_geometry *g, double density, fluid_particles *p,
                         unsigned char **free_slip, char *msg, size_t msg_size);

#endif
