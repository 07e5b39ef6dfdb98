/* Shapes of the fluid's blocks and walls and of the solid's blocks, shared by both
 * solvers: the axis-aligned box (the default), the box turned about its centre, the
 * disc or annulus and the simple polygon (the last three in 2D builds). One place
 * reads a shape from its case section, checks it, tells whether a point lies in it
 * and fills it with the lattice of the block's spacing:
 *
 *   box      min + (i + 1/2) dx along each axis, as before (core/lattice_box.h);
 *            with an angle the same points turned about the centre (min + max) / 2,
 *            so the lattice is aligned with the box, its edges are clean and it holds
 *            exactly as many points as the box unturned;
 *   disc     the points (i + 1/2) dx, i whole, of the lattice anchored at the origin
 *            (the lattice of every box whose corners lie on multiples of dx, so a
 *            disc meets such boxes without gaps) within radius of the centre and,
 *            for an annulus, beyond inner_radius;
 *   polygon  the points of that same lattice inside the polygon (any orientation).
 *
 * A point on the edge (within the tolerance the caller gives) counts as inside. */
#ifndef FSI_SHAPE_H
#define FSI_SHAPE_H

#include "case_check.h"
#include "dim.h"

typedef enum { FSI_SHAPE_BOX, FSI_SHAPE_DISC, FSI_SHAPE_POLYGON } fsi_shape_kind;

/* The keys of a shape, spliced into a block's key table after its min and max:
 * SHAPE_TEXT says what the shape is filled with (one sentence). */
#define FSI_SHAPE_KEYS(SHAPE_TEXT)                                                          \
    {"shape", FSI_KEY_CHOICE, "-", "box", 0, 0, 0, "box|disc|polygon",                     \
     "box: the box min .. max, turned by angle; disc: centre, radius (an annulus with "     \
     "inner_radius); polygon: points. Disc and polygon are filled with the lattice "        \
     "(i + 1/2) spacing anchored at the origin, a turned box with its own lattice turned "  \
     "with it (2D builds only; core/shape.h). " SHAPE_TEXT},                               \
    {"angle", FSI_KEY_REAL, "deg", "0", FSI_BOUND_MIN | FSI_BOUND_MAX, -360, 360, NULL,    \
     "shape = box: the box drawn by min and max and its lattice are turned "               \
     "counter-clockwise by this angle about the box's centre (min + max) / 2."},           \
    {"centre", FSI_KEY_VECTOR, "m", "", 0, 0, 0, NULL,                                     \
     "shape = disc: the centre (required)."},                                              \
    {"radius", FSI_KEY_REAL, "m", "0", FSI_BOUND_MIN, 0, 0, NULL,                          \
     "shape = disc: the radius, > 0 (required)."},                                         \
    {"inner_radius", FSI_KEY_REAL, "m", "0", FSI_BOUND_MIN, 0, 0, NULL,                    \
     "shape = disc: an annulus, without the points within this radius of the centre "      \
     "(0: a full disc); below radius."},                                                   \
    {"points", FSI_KEY_STRING, "m", "", 0, 0, 0, NULL,                                     \
     "shape = polygon: the corners x1,y1 x2,y2 x3,y3 ... of a simple polygon (at least "    \
     "three, either orientation, edges not crossing), the last joined to the first."}

/* Most polygon corners. */
#define FSI_SHAPE_MAX_POINTS 256

typedef struct {
    fsi_shape_kind kind;
    /* box: the box as drawn (before turning) and its lattice points per axis */
    double min[FSI_DIM], max[FSI_DIM];
    long count[FSI_DIM];
    double angle, cos_a, sin_a;     /* box: turn [rad] about its centre; 0: none */
    double centre[FSI_DIM];         /* box: (min + max) / 2; disc: the centre */
    double radius, inner_radius;    /* disc */
    int n_points;                   /* polygon: corners (x, y) in points */
    double points[2 * FSI_SHAPE_MAX_POINTS];
    char points_problem[160];       /* polygon: why 'points' did not read, or "" */
    double lo[FSI_DIM], hi[FSI_DIM];/* bounding box of the shape (turned) */
    double n_lattice;               /* lattice points that fill it (a double: no overflow) */
} fsi_shape;

/* Reads the shape keys of a block section (an unvalidated or bad value reads as 0 or
 * as no points; fsi_shape_check reports it) and counts its lattice points. */
void fsi_shape_read(fsi_shape *s, const fsi_case *c, const char *section, double spacing);

/* Reports what single-key validation cannot see (shape keys of another shape, a
 * missing centre, radius <= 0, inner_radius >= radius, fewer than 3 corners, crossing
 * edges, no area, no lattice point, a turned box or a non-box shape in a 3D build),
 * each naming the section and key. The size checks of a box (whole numbers of
 * spacings) stay with the solvers. Returns the number of problems. */
int fsi_shape_check(fsi_case_checker *k, const fsi_shape *s, const char *section,
                    double spacing);

/* Lattice points that fill the shape (a box's from its counts, as a double). */
double fsi_shape_points(const fsi_shape *s);

/* 1 when the shape is the plain axis-aligned box of the lattice_box.h code paths. */
int fsi_shape_is_plain_box(const fsi_shape *s);

/* 1 when x lies in the shape grown by tol (tol < 0: shrunk, so that points on an edge
 * shared with a neighbour are not inside). */
int fsi_shape_contains(const fsi_shape *s, double tol, const double *x);

/* The largest x . u over the shape (u a unit vector): how far it reaches along u. */
double fsi_shape_reach(const fsi_shape *s, const double *u);

/* The lattice points of a shape, in a fixed order (a box's as fsi_lattice_point
 * numbers them, the others row by row, axis 0 fastest):
 *
 *   fsi_shape_walk w;
 *   fsi_shape_walk_begin(&w, &shape, dx);
 *   while (fsi_shape_walk_next(&w, x)) ... */
typedef struct {
    const fsi_shape *s;
    double dx;
    long j, n;                  /* box: next point and count; others: next candidate */
    long first[FSI_DIM], span[FSI_DIM];
} fsi_shape_walk;

void fsi_shape_walk_begin(fsi_shape_walk *w, const fsi_shape *s, double spacing);
int fsi_shape_walk_next(fsi_shape_walk *w, double *x);

/* 1 when two shapes share a volume: a lattice point of one lies strictly inside the
 * other (by more than 1e-6 spacings), or for two plain boxes an overlap wider than
 * that. Shapes that only touch do not overlap. */
int fsi_shapes_overlap(const fsi_shape *a, const fsi_shape *b, double spacing);

/* The area of a polygon from its corners (shoelace formula, either orientation). */
double fsi_polygon_area(const double *points, int n_points);

#endif
