/* The NOSB-PD model's state, shared by the files of this folder only. */
#ifndef NOSBPD_INTERNAL_H
#define NOSBPD_INTERNAL_H

#include <stdint.h>

#include "material.h"
#include "nosbpd.h"
#include "nosbpd_bonds.h"
#include "small_tensor.h"
#include "solid_fit.h"
#include "solid_model.h"

/* Largest Frobenius condition number |K| |K^-1| of a usable shape tensor: beyond,
 * the family is (nearly) collinear (coplanar in 3D) and K^-1 amplifies round-off
 * into the force state. A regular-lattice family, even a corner's or that of a
 * strip two points thick, stays below 100. */
#define NOSBPD_MAX_CONDITION_K 1e6

/* The same bound for the moment matrix of the quadratic fit (order 2). A family
 * confined to two lattice rows (a strip edge seen from a two-point-thick strip)
 * cannot tell xi_y^2 from xi_y and is singular; such points use the linear fit. */
#define NOSBPD_MAX_CONDITION_FIT 1e6

/* Below this many bonds the point loops run on one thread: a fork and a barrier
 * cost more than the work (the results are the same either way). */
#define NOSBPD_PARALLEL_MIN_BONDS 4096

/* Lines of per-point warnings on stderr before only a count is given. */
#define NOSBPD_MAX_WARNINGS 20

/* The deformation is fitted over each family in the basis b(xi) of solid_fit.h:
 * the bond vector xi (gradient_order = 1, 000 Eqs. 34, 36) or xi and its quadratic
 * monomials divided by delta (gradient_order = 2). */
#define NOSBPD_MAX_BASIS SOLID_FIT_MAX_BASIS

struct solid_model {
    material mat;
    int n;
    double dx;                      /* lattice spacing [m] */
    double delta;                   /* horizon [m] */
    nosbpd_influence influence;
    int gradient_order;             /* 1 or 2 (key gradient_order) */
    int n_basis;                    /* nb: FSI_DIM, or NOSBPD_MAX_BASIS for order 2 */
    int gather_stride;              /* FSI_DIM * nb + 1 */
    double zero_energy_coefficient; /* G */
    double stab_modulus;            /* G C_w [Pa / m^(DIM+2)... see nosbpd_stabilisation.h] */
    int failure;
    double critical_stretch;        /* s0, 0 when failure is off */
    nosbpd_full_family full;
    double stable_dt;               /* [s], before the main loop's safety factor */

    nosbpd_bonds bonds;

    /* Per point. */
    double *k_inv;                  /* K^-1, FSI_MAT_SIZE each (000 Eq. 34) */
    /* A^-1 of the moment matrix A = sum_J omega V_J b (x) b, nb * nb each: K^-1 for
     * order 1; for order 2 the quadratic fit's, or K^-1 padded with zeros where the
     * family cannot carry a quadratic fit (NOSBPD_POINT_LINEAR_FIT). */
    double *moment_inv;
    /* C = [F | H / 2 scaled] = (sum_J omega V_J y (x) b) A^-1 at the last call,
     * FSI_DIM * nb each; F its first FSI_DIM columns (Eq. 36 for order 1). */
    double *fit;
    double *defgrad;                /* F at the last call, FSI_MAT_SIZE each (Eq. 36) */
    /* Per point for the force gather, gather_stride each: D = P G - s C (FSI_DIM x nb,
     * G the first FSI_DIM rows of A^-1) and s (G C_w, 0 without force state). */
    double *gather;
    double *stress;                 /* Cauchy stress, 6 each */
    material_state *mstate;
    double *work;                   /* stress work per reference volume [J/m^DIM...];
                                     * hyperelastic: W(F) of the last call */
    double *thickness_stretch;      /* lambda_z (2D plane stress), else 1 */
    double *family_volume;          /* sum of V_J over the whole family (Eq. 49) */
    double *damage;                 /* Eq. 49 */
    int32_t *intact_count;
    uint8_t *flags;                 /* NOSBPD_POINT_* */
    int n_without_force_state;
    int64_t n_broken;               /* directed bonds */
    int n_warnings;

    /* Scratch for output and energy sums (allocated once). */
    double *scratch;                /* n * FSI_MAT_SIZE */
    int32_t *iscratch;              /* n */
};

/* K of point i over its intact bonds (000 Eq. 34: K = sum_J omega V_J xi (x) xi),
 * its inverse, the moment matrix inverse of the fit (order 2: falls back to the
 * linear fit, flag NOSBPD_POINT_LINEAR_FIT, when the family cannot carry a
 * quadratic one), intact count and damage (Eq. 49). Returns 0, or -1 when K is not
 * usable (fewer than FSI_DIM + 1 intact bonds, singular or ill-conditioned): then
 * k_inv[i] and moment_inv[i] are zero. */
int nosbpd_shape_tensor(solid_model *m, const solid_particles *p, int i);

/* Prints "nosbpd: warning: ..." about point i once (flag NOSBPD_POINT_WARNED),
 * up to NOSBPD_MAX_WARNINGS lines per model. */
void nosbpd_warn_point(solid_model *m, const solid_particles *p, int i, const char *what,
                       double t);

#endif
