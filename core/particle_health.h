/* What the particle participants (solid and fluid main loops) share to check a run's
 * health and to say where a problem is: the "(x, y)" of a point, a generous box that
 * no particle of a sane run leaves, and the fastest particle. Vectors are
 * particle-major, x[i * FSI_DIM + d]. */
#ifndef FSI_PARTICLE_HEALTH_H
#define FSI_PARTICLE_HEALTH_H

#include <stddef.h>

#include "dim.h"

/* "(x, y)" (or "(x, y, z)") of the point x[0..FSI_DIM-1] into buf; returns buf. */
const char *fsi_point_text(const double *x, char *buf, size_t size);

/* The bounding box of the n points x, widened on every side by 'diagonals' times its
 * diagonal (at least min_size, so that a single point or a flat body still gets a
 * box): the region a particle may not leave. */
void fsi_escape_box(const double *x, int n, double diagonals, double min_size,
                    double *box_min, double *box_max);

/* Index of the first point outside the box, or -1. */
int fsi_outside_box(const double *x, int n, const double *box_min, const double *box_max);

/* Index of the fastest of the n velocities v (the first non-finite one if any; 0 when
 * n = 0) and its speed in *speed: where an instability is growing. */
int fsi_fastest(const double *v, int n, double *speed);

#endif
