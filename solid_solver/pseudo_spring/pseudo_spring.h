/* What the pseudo-spring SPH model offers beyond solid_model.h: read/write access to
 * its state for unit tests and figures for logs. Only code that links
 * fsi_solid_pseudo_spring on purpose (tests, bench) includes this; the main loop
 * knows the model only through solid_model.h. */
#ifndef PSEUDO_SPRING_H
#define PSEUDO_SPRING_H

#include <stdint.h>

#include "solid_bonds.h"
#include "solid_model.h"

/* Per-point state flags (solid_model::flags, pseudo_spring_internal.h). */
enum {
    /* A mirrored clamp point (SOLID_MIRRORED): an image, not material. Its
     * position (the odd reflection of its partner's) and volume enter its
     * neighbours' sums; it carries no stress, artificial stress or hourglass energy
     * and stores nothing (the main loop hands the force it receives to the
     * partner); never on the surface. */
    PS_POINT_GHOST = 1,
    /* A_i (004 Eq. 20) is ill-conditioned (the remaining links nearly on a line): B_i
     * is the regularised inverse (pseudo_spring_gradient.c). */
    PS_POINT_REGULARISED = 2,
    /* Every link of the point is broken (D_i = 1): it interacts with nothing, its
     * stress and stored energy are released. */
    PS_POINT_DETACHED = 4,
    PS_POINT_WARNED = 8,        /* a warning about it went to stderr */
};

const solid_bonds *pseudo_spring_links(const solid_model *m);
int64_t pseudo_spring_broken_links(const solid_model *m);   /* directed */
/* Links of a point deep inside the lattice (8 in 2D, 26 in 3D). */
int pseudo_spring_full_count(const solid_model *m);
/* Per point: Cauchy stress (6 components, xx yy zz xy yz zx), writable so that tests
 * can pre-stress a body; damage; intact and initial link counts. (The current density
 * is solid_model_density's.) */
double *pseudo_spring_stress(solid_model *m);
const double *pseudo_spring_damage(const solid_model *m);
const int32_t *pseudo_spring_intact_count(const solid_model *m);
const int32_t *pseudo_spring_initial_count(const solid_model *m);

#endif
