/* A prescribed rigid motion of a wall ([fluid.wall NAME] motion keys): the law X(t) and
 * its derivatives. Displacements are counted from the wall's position in the case, so a
 * wall starts where it is drawn whatever the phase:
 *   harmonic  X(t) = A e (sin(w t + phi) - sin(phi)),  w = 2 pi / T
 *             X'(t) = A w e cos(w t + phi),  X''(t) = -A w^2 e sin(w t + phi)
 * with amplitude A [m], period T [s], phase phi (read in degrees) and the unit
 * direction e. phi = 90 deg gives the sloshing tank of 000 Eq. 60 and Faltinsen et al.
 * 2000: velocity -(2 pi A / T) sin(2 pi t / T), acceleration -A w^2 cos(w t). */
#ifndef FSI_FLUID_MOTION_H
#define FSI_FLUID_MOTION_H

#include "case_file.h"
#include "dim.h"

typedef enum { FLUID_MOTION_NONE = 0, FLUID_MOTION_HARMONIC } fluid_motion_kind;

typedef struct {
    fluid_motion_kind kind;
    double amplitude, period, phase;    /* m, s, rad */
    double direction[FSI_DIM];          /* unit vector (zero when not given) */
} fluid_motion;

/* The motion keys of a [fluid.wall] section (defaults of fluid_keys.c). */
void fluid_motion_read(fluid_motion *m, const fsi_case *c, const char *section);

/* Displacement from the start, velocity and acceleration at time t (any may be NULL). */
void fluid_motion_at(const fluid_motion *m, double t, double *displacement, double *velocity,
                     double *acceleration);

/* Largest |displacement| along axis d over all times. */
double fluid_motion_reach(const fluid_motion *m, int d);

/* True when a and b are the same law (one rigid tank made of several walls). */
int fluid_motion_same(const fluid_motion *a, const fluid_motion *b);

#endif
