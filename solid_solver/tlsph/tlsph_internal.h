/* The TLSPH model's state, shared by the files of this folder only. */
#ifndef TLSPH_INTERNAL_H
#define TLSPH_INTERNAL_H

#include <stdint.h>

#include "material.h"
#include "small_tensor.h"
#include "solid_bonds.h"
#include "solid_fit.h"
#include "solid_model.h"
#include "tlsph.h"

/* Largest Frobenius condition number |K| |K^-1| of a shape matrix (003 Eq. 35)
 * accepted at creation. A lattice point's K, a corner's included, stays below 10
 * with h = 1.2 dx; a larger one means a family that nearly lies on a line (a body
 * one point thick), whose corrected gradient would amplify round-off. */
#define TLSPH_MAX_CONDITION_K 1e3

/* Largest condition number of the quadratic fit's moment matrix (gradient_order =
 * 2) before a point keeps the linear fit (NOSB-PD's bound, nosbpd_internal.h). */
#define TLSPH_MAX_CONDITION_FIT 1e6

/* Below this many family members the point loops run on one thread (a fork and a
 * barrier cost more than the work; the results are the same either way). */
#define TLSPH_PARALLEL_MIN_BONDS 4096

struct solid_model {
    material mat;
    int n;
    double dx;                  /* lattice spacing [m] */
    double h;                   /* smoothing length [m] */
    double courant;
    double hg_alpha;            /* hourglass_control: Ganzenmueller's alpha */
    int gradient_order;         /* 1: 003 Eq. 35's linear correction; 2: quadratic fit */
    int linear_fit_points;      /* points whose family cannot carry the quadratic fit */
    double sound_speed;         /* sqrt(M / rho0), the largest over the points [m/s] */
    int full_count;             /* family members of a point deep inside the lattice */

    /* Reference families within 2 h (weight = V_J), fixed for good. */
    solid_bonds family;
    int64_t *reverse;           /* per bond I -> J: the slot of J -> I */
    /* Per bond I -> J: the corrected reference gradient g_IJ (FSI_DIM each: K_I^-T
     * grad_0 W_IJ of Eqs. 35-36, or the quadratic fit's, tlsph_model.c) and the
     * kernel value W_IJ (hourglass control). */
    double *grad;
    double *kernel_w;

    /* Per point. */
    uint8_t *ghost;             /* 1 for mirrored clamp points (images, not material) */
    double *pk1;                /* first Piola-Kirchhoff stress of the last evaluation */
    double *defgrad;            /* F of the last evaluation (hourglass control, output) */
    /* sum_J V_J g_IJ (FSI_DIM each, fixed): the gather's own term is P_I times it, so
     * the pair loop carries only the neighbours' stresses (zero inside the lattice). */
    double *grad_sum;
};

/* P_i and F_i of every point at positions x (pass 1); -1 with msg naming the first
 * point whose F is inverted or not finite. */
int tlsph_stress_pass(solid_model *m, const solid_particles *p, double t, char *msg,
                      size_t msg_size);

/* Ganzenmueller's hourglass force on point i at positions x (pass 2, after pass 1's
 * F of every point), added to f. */
void tlsph_hourglass_force(const solid_model *m, const solid_particles *p, int i, double *f);

/* The strain energy density W(F_i) [J/m^3 of reference volume] of point i at x, and
 * its Cauchy stress into sigma6 (may be NULL); -1 when F_i is inverted. */
int tlsph_point_response(const solid_model *m, const double *x, int i, double *energy,
                         double sigma6[6]);

#endif
