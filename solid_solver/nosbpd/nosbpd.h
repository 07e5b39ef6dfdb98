/* What the NOSB-PD model offers beyond solid_model.h: figures for logs and
 * benchmarks, and read/write access to its state for unit tests. Only code that
 * links fsi_solid_nosbpd on purpose (tests, bench) includes this; the main loop
 * knows the model only through solid_model.h. */
#ifndef NOSBPD_H
#define NOSBPD_H

#include <stdint.h>

#include "nosbpd_bonds.h"
#include "solid_model.h"

/* Per-point state flags (nosbpd_point_flags). */
enum {
    /* K is singular or ill-conditioned (fewer than FSI_DIM + 1 intact bonds, or all
     * of them nearly on a line / plane): the point has no force state of its own. */
    NOSBPD_POINT_SINGULAR_SHAPE = 1,
    /* det F <= 0 or F singular with failure on: the point has no force state. */
    NOSBPD_POINT_INVERTED = 2,
    NOSBPD_POINT_WARNED = 4,    /* a warning about it went to stderr */
    /* gradient_order = 2, but the family (a strip too thin, or after bond failure)
     * cannot carry a quadratic fit: F is the linear fit of 000 Eq. 36 there. */
    NOSBPD_POINT_LINEAR_FIT = 8,
    /* A mirrored clamp point (SOLID_MIRRORED): its position enters the families of
     * its neighbours, but it is not material and has no force state of its own. */
    NOSBPD_POINT_GHOST = 16,
};

/* The flags that leave a point without a force state of its own. */
#define NOSBPD_NO_FORCE_STATE                                                          \
    (NOSBPD_POINT_SINGULAR_SHAPE | NOSBPD_POINT_INVERTED | NOSBPD_POINT_GHOST)

/* Points without a force state of their own through failure or a poor family
 * (SINGULAR_SHAPE or INVERTED; mirrored clamp points are not counted). */
int nosbpd_points_without_force_state(const solid_model *m);

/* Directed bonds (each pair counts twice) in all, and broken ones. */
int64_t nosbpd_bond_count(const solid_model *m);
int64_t nosbpd_broken_bond_count(const solid_model *m);

double nosbpd_horizon(const solid_model *m);
double nosbpd_critical_stretch(const solid_model *m);   /* 0 when failure is off */
double nosbpd_stabilisation_modulus_of(const solid_model *m);   /* G C_w */
/* Bonds of a point deep inside the lattice (the surface test compares with it). */
int nosbpd_full_family_count(const solid_model *m);

const nosbpd_bonds *nosbpd_model_bonds(const solid_model *m);
/* Per point: Cauchy stress (6 components, xx yy zz xy yz zx), writable so that tests
 * can pre-stress a body; F and K^-1 (FSI_DIM^2, row-major) as of the last
 * internal-force call (F = I and K^-1 of the reference before it); damage; flags. */
double *nosbpd_stress(solid_model *m);
const double *nosbpd_deformation_gradient(const solid_model *m);
const double *nosbpd_shape_tensor_inverse(const solid_model *m);
const double *nosbpd_damage(const solid_model *m);
const uint8_t *nosbpd_point_flags(const solid_model *m);

#endif
