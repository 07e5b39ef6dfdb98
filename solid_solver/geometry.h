/* The solid's geometry from the case: blocks filled with a regular lattice, regions
 * that clamp, load, remove or keep from breaking points, probe points; and the
 * particles built from them (solid_particles.h).
 *
 * Lattice: a block [min, max] holds the points min + (i + 1/2) dx, i = 0 .. n_d - 1
 * along each axis d, with n_d = (max_d - min_d) / dx (a whole number, checked by
 * solid_geometry_check), so a block of size L holds L / dx points and its points
 * carry exactly its volume (each dx^FSI_DIM). Touching blocks continue each other's
 * lattice when their corners lie on a common grid. Turned boxes, discs and polygons
 * are filled as core/shape.h says (fsi_shape_walk).
 *
 * Cracks (2D): a segment; bonds of a bond-based model whose reference segment
 * crosses it are broken from the start (a pre-crack or notch of zero width).
 *
 * Regions: a point belongs to a region when it lies in the closed box
 * [min - tol, max + tol], tol = 1e-6 dx (so a box drawn on the lattice's faces
 * selects the points inside it, immune to round-off). Points in a 'remove' region are
 * never created; 'clamp', 'load' and 'no_failure' regions then select among the
 * points that exist.
 *
 * Ownership: a solid_geometry points into the case (section names) and owns its
 * arrays (solid_geometry_free); solid_particles arrays are owned by whoever built
 * them (solid_particles_free). */
#ifndef FSI_SOLID_GEOMETRY_H
#define FSI_SOLID_GEOMETRY_H

#include <stddef.h>
#include <stdint.h>

#include "case_file.h"
#include "dim.h"
#include "shape.h"
#include "solid_particles.h"

/* Relative tolerance (in spacings) of region boxes and of "a whole number of
 * spacings". */
#define SOLID_GEOMETRY_TOL 1e-6

typedef enum {
    SOLID_REGION_CLAMP,
    SOLID_REGION_LOAD,
    SOLID_REGION_REMOVE,
    SOLID_REGION_NO_FAILURE
} solid_region_action;

typedef struct {
    const char *section;        /* "solid.block NAME" (owned by the case) */
    fsi_shape shape;            /* a box (min, max, count) or another shape (core/shape.h) */
} solid_block;

typedef struct {
    const char *section;        /* "solid.region NAME" */
    solid_region_action action;
    double min[FSI_DIM], max[FSI_DIM];
    double force[FSI_DIM];      /* load: total force [N, per unit thickness in 2D] */
    double ramp_time;           /* load: linear ramp from 0 over this time [s] */
    /* clamp: the face of the box the body touches, as axis * 2 + (0 for min, 1 for
     * max), or -1 for none (the points stay at x0) */
    int clamp_face;
} solid_region;

typedef struct {
    const char *section;        /* "solid.probe NAME" */
    double point[FSI_DIM];
} solid_probe_point;

typedef struct {
    const char *section;        /* "solid.crack NAME" */
    double from[FSI_DIM], to[FSI_DIM];
} solid_crack;

typedef struct {
    double spacing;
    int n_blocks, n_regions, n_probes, n_cracks;
    solid_block *blocks;
    solid_region *regions;
    solid_probe_point *probes;
    solid_crack *cracks;
} solid_geometry;

/* Reads [role] spacing and the role's block, region, probe and crack sections of a
 * validated case (values missing in an unvalidated case read as 0). Returns 0, or
 * -1 with a message when memory runs out. */
int solid_geometry_read(solid_geometry *g, const fsi_case *c, const char *role, char *msg,
                        size_t msg_size);
void solid_geometry_free(solid_geometry *g);

/* 1 when the segment p-q crosses the crack a-b (2D; always 0 in 3D). A segment that
 * only touches the crack's line at p or q does not cross it: points on the line
 * keep their bonds on both sides. A crack that ends on the segment does. */
int solid_crack_cuts(const double *p, const double *q, const double *a, const double *b);

/* (max - min) / spacing along 'axis': a box block's length in spacings, not rounded. */
double solid_block_spacings(const solid_block *b, double spacing, int axis);
/* Number of lattice points of the block. */
long solid_block_points(const solid_block *b);

/* True when x lies in the region's closed box, within SOLID_GEOMETRY_TOL spacings. */
int solid_region_contains(const solid_region *r, double spacing, const double *x);
/* True when a 'remove' region of g contains x. */
int solid_geometry_removed(const solid_geometry *g, const double *x);

/* 1 when two blocks share a volume, 0 when they are apart or only touch
 * (fsi_shapes_overlap). */
int solid_blocks_overlap(const solid_block *a, const solid_block *b, double spacing);

/* Most lattice points the blocks may hold (before removal): particle ids are int32. */
#define SOLID_MAX_LATTICE 2147483647.0

/* Lattice points of all blocks before removal, as a double (no overflow). */
double solid_geometry_lattice_size(const solid_geometry *g);

/* Creates the particles: every lattice point of every block outside the remove
 * regions, id = index, x = x0, v = a = 0, volume dx^FSI_DIM, the given reference
 * density, block index, and flags SOLID_CLAMPED / SOLID_LOADED from the clamp and
 * load regions. A point of a clamp region with a clamp_face whose mirror image across
 * that face is an unclamped particle becomes SOLID_MIRRORED with p->mirror set; one
 * without such an image stays an ordinary clamped point (*n_unmirrored counts them
 * when the pointer is not NULL). Returns 0, or -1 with a message (no points, more
 * than SOLID_MAX_LATTICE, out of memory). */
int solid_geometry_build(const solid_geometry *g, double density, solid_particles *p,
                         int *n_unmirrored, char *msg, size_t msg_size);

/* The words of clamp_face in the order of solid_region.clamp_face (x_min, x_max,
 * y_min, ...); index -1 is "none". Returns the index, or -2 for an unknown word. */
int solid_clamp_face_parse(const char *word);
void solid_particles_free(solid_particles *p);

/* Indices of the particles in region r (in index order) into 'index' when it is
 * not NULL; returns how many. */
int solid_region_select(const solid_geometry *g, int r, const solid_particles *p,
                        int32_t *index);

/* Index of the particle whose reference position x0 is nearest to 'point' (the
 * lowest index among equals), its distance in *distance; -1 when p is empty. */
int solid_nearest_particle(const solid_particles *p, const double *point, double *distance);

#endif
