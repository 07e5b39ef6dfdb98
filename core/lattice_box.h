/* Axis-aligned boxes filled with a regular lattice, shared by the solid's blocks and
 * regions and the fluid's blocks and walls: a box of size L along an axis holds
 * count = L / dx points at min + (i + 1/2) dx. Point j of a box is numbered with
 * the first axis varying fastest. */
#ifndef FSI_LATTICE_BOX_H
#define FSI_LATTICE_BOX_H

#include <math.h>

#include "dim.h"

/* Lattice points along one axis of a box from min to max: the nearest whole number
 * of spacings (the case checks refuse sizes that are not whole numbers; rounding
 * keeps an unchecked case from misbehaving), 0 for an empty or inverted box, capped
 * at 1e9 so that products of counts stay far from overflow. */
static inline long fsi_lattice_count(double min, double max, double spacing)
{
    const double n = spacing > 0.0 ? (max - min) / spacing : 0.0;
    return n > 0.5 ? lround(fmin(n, 1e9)) : 0;
}

/* Points of a box with 'count' points per axis, as a double (no overflow). */
static inline double fsi_lattice_points(const long *count)
{
    double n = 1.0;
    for (int d = 0; d < FSI_DIM; d++)
        n *= (double)count[d];
    return n;
}

/* Position of lattice point j of the box starting at 'min'. */
static inline void fsi_lattice_point(const double *min, const long *count, double spacing,
                                     long j, double *x)
{
    for (int d = 0; d < FSI_DIM; d++) {
        const long i = j % count[d];
        j /= count[d];
        x[d] = min[d] + ((double)i + 0.5) * spacing;
    }
}

/* True when x lies in the closed box [min, max] widened by tol on every side. */
static inline int fsi_box_contains(const double *min, const double *max, double tol,
                                   const double *x)
{
    for (int d = 0; d < FSI_DIM; d++)
        if (x[d] < min[d] - tol || x[d] > max[d] + tol)
            return 0;
    return 1;
}

/* Width of the overlap of boxes a and b, the minimum over axes: > 0 when they share
 * a volume, <= 0 when they only touch or are apart. */
static inline double fsi_boxes_overlap(const double *a_min, const double *a_max,
                                       const double *b_min, const double *b_max)
{
    double width = INFINITY;
    for (int d = 0; d < FSI_DIM; d++)
        width = fmin(width, fmin(a_max[d], b_max[d]) - fmax(a_min[d], b_min[d]));
    return width;
}

#endif
