/* The NOSB-PD model's state, shared by the files of this folder only. */
#ifndef NOSBPD_INTERNAL_H
#define NOSBPD_INTERNAL_H

#include <stdint.h>

#include "material.h"
#include "nosbpd.h"
#include "nosbpd_bonds.h"
#include "small_tensor.h"
#include "solid_model.h"

/* Largest Frobenius condition number |K| |K^-1| of a usable shape tensor: beyond,
 * the family is (nearly) collinear (coplanar in 3D) and K^-1 amplifies round-off
 * into the force state. A regular-lattice family, even a corner's or that of a
 * strip two points thick, stays below 100. */
#define NOSBPD_MAX_CONDITION_K 1e6

/* Below this many bonds the point loops run on one thread: a fork and a barrier
 * cost more than the work (the results are the same either way). */
#define NOSBPD_PARALLEL_MIN_BONDS 4096

/* Lines of per-point warnings on stderr before only a count is given. */
#define NOSBPD_MAX_WARNINGS 20

/* Per point, what the force gather needs of a neighbour: B = P K^-1 - G C_w F and
 * the stabilisation modulus s (G C_w, or 0 for a point without force state). */
#define NOSBPD_GATHER_STRIDE (FSI_MAT_SIZE + 1)

struct solid_model {
    material mat;
    int n;
    double dx;                      /* lattice spacing [m] */
    double delta;                   /* horizon [m] */
    nosbpd_influence influence;
    double zero_energy_coefficient; /* G */
    double stab_modulus;            /* G C_w [Pa / m^(DIM+2)... see nosbpd_stabilisation.h] */
    int failure;
    double critical_stretch;        /* s0, 0 when failure is off */
    nosbpd_full_family full;
    double stable_dt;               /* [s], before the main loop's safety factor */

    nosbpd_bonds bonds;

    /* Per point. */
    double *k_inv;                  /* K^-1, FSI_MAT_SIZE each (000 Eq. 34) */
    double *defgrad;                /* F at the last call, FSI_MAT_SIZE each (Eq. 36) */
    double *gather;                 /* B and s, NOSBPD_GATHER_STRIDE each */
    double *stress;                 /* Cauchy stress, 6 each */
    material_state *mstate;
    double *work;                   /* stress work per reference volume [J/m^DIM...] */
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
 * its inverse, intact count and damage (Eq. 49). Returns 0, or -1 when K is not
 * usable (fewer than FSI_DIM + 1 intact bonds, singular or ill-conditioned): then
 * k_inv[i] is zero. */
int nosbpd_shape_tensor(solid_model *m, const solid_particles *p, int i);

/* Prints "nosbpd: warning: ..." about point i once (flag NOSBPD_POINT_WARNED),
 * up to NOSBPD_MAX_WARNINGS lines per model. */
void nosbpd_warn_point(solid_model *m, const solid_particles *p, int i, const char *what,
                       double t);

#endif
