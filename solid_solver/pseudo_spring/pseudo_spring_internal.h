/* The pseudo-spring SPH model's state, shared by the files of this folder only. */
#ifndef PSEUDO_SPRING_INTERNAL_H
#define PSEUDO_SPRING_INTERNAL_H

#include <stdint.h>

#include "material.h"
#include "pseudo_spring.h"
#include "small_tensor.h"
#include "solid_bonds.h"
#include "solid_model.h"
#include "solid_point_text.h"
#include "wendland_c2.h"

/* Largest Frobenius condition number |A| |A^-1| of a correction matrix inverted
 * exactly (004 Eq. 20). A lattice point's A, a corner's included, stays below 10;
 * beyond this the remaining links (after failure) nearly lie on a line and A^-1 would
 * amplify round-off into the stress: B is the regularised inverse instead
 * (pseudo_spring_gradient.c). */
#define PS_MAX_CONDITION_A 1e4

/* Tikhonov parameter of that regularised inverse, relative to |A|. */
#define PS_REGULARISATION 1e-2

/* Below this many links the point loops run on one thread (a fork and a barrier
 * cost more than the work; the results are the same either way). */
#define PS_PARALLEL_MIN_LINKS 4096

struct solid_model {
    material mat;
    int n;
    double dx;                  /* lattice spacing [m] */
    wendland_c2_kernel kernel;  /* h = smoothing_length_factor dx */
    double w_dx;                /* W(dx), the artificial stress's reference */
    double visc_alpha, visc_beta;       /* beta_1, beta_2 of 004 Eq. 8 */
    double art_stress, art_exponent;    /* gamma and n of 004 Eq. 16 */
    double hg_coefficient;      /* hourglass_control: E_i in units of G V0 eps_na^2 */
    int failure;
    double failure_strain;      /* 0 when failure is off */
    double courant;
    double sound_speed;         /* sqrt(M / rho0), the largest over the points [m/s] */
    int full_count;             /* links of a point deep inside the lattice */

    solid_bonds links;          /* immediate neighbours; weight = w_iJ of the hourglass control */
    int64_t *reverse;           /* per link I -> J: the slot of J -> I (solid_bonds_reverse) */
    /* Per link, the pair's quantities in the current configuration of this step
     * (pseudo_spring_pairs.c), evaluated once per pair and stored at both of its
     * slots: F(r) of grad_i W_ij = F(r) x_ij, and P^a_ij = (R_i + R_j) (W(r) / W(dx))^n
     * of 004 Eq. 16 (NULL when the artificial stress is off). */
    double *link_f;
    double *link_art;

    /* Per point. */
    double *mass;               /* rho0 V0 [kg/m^(3-DIM)...] */
    double *density;            /* current rho (004 Eq. 14) */
    double *density_next;       /* written by pass 1, swapped in after it */
    double *stress;             /* Cauchy stress, 6 each */
    material_state *mstate;
    double *work;               /* stress work per reference volume [J/m^3] */
    double *thickness_stretch;  /* lambda_z (2D plane stress), else 1 */
    /* Per point, for the force gather: D = lambda_z sigma B (FSI_DIM x FSI_DIM, B the
     * correction of the current configuration). */
    double *gather;             /* FSI_MAT_SIZE each */
    /* Per point, R = gamma |P_r| / rho^2 of 004 Eq. 16 (pass 1; NULL when off). */
    double *art_r;
    /* Per point, for the hourglass control (pseudo_spring_hourglass.c): the affine
     * fit F_i of the neighbourhood on the reference lattice and kappa_i (0: none). */
    double *hourglass;          /* PS_HOURGLASS_STRIDE each */
    double *damage;             /* D_i = broken / initial links */
    int32_t *initial_count, *intact_count;
    uint8_t *flags;             /* PS_POINT_* */
    int64_t n_broken;           /* directed links */
    int n_warnings;

    double *scratch;            /* n * FSI_MAT_SIZE, output */
};

#define PS_HOURGLASS_STRIDE (FSI_MAT_SIZE + 1)

/* Position of point j in the configuration of a pass: the current one (x_prev NULL)
 * or the mid-point one (x + x_prev) / 2. */
static inline void ps_position(const double *x, const double *x_prev, int64_t j, double *y)
{
    for (int d = 0; d < FSI_DIM; d++)
        y[d] = x_prev ? 0.5 * (x[j * FSI_DIM + d] + x_prev[j * FSI_DIM + d])
                      : x[j * FSI_DIM + d];
}

/* Correction matrix B_i = A_i^-1 (004 Eq. 20) over point i's intact links in the
 * configuration (x, x_prev) (ps_position), with volumes m_J / rho_J; link_f, when not
 * NULL, holds F(r) of that configuration per link (m->link_f of the current one),
 * else the kernel is evaluated. Returns 0 (exact inverse), PS_POINT_REGULARISED (A_i
 * ill-conditioned: the regularised inverse) or PS_POINT_DETACHED (no intact link:
 * B = 0). */
int ps_correction(const solid_model *m, const double *x, const double *x_prev,
                  const double *density, const double *link_f, int i, double *b);

/* G_i = sum_J V_J (du_J - du_i) (x) B_i grad W_iJ on the mid-point configuration: the
 * gradient of the displacement increment du = x - x_prev (004 Eq. 19 times dt, with
 * the corrected gradient). Returns ps_correction's outcome. */
int ps_increment_gradient(const solid_model *m, const solid_particles *p, const double *x_prev,
                          int i, double *g);

/* Breaks point i's intact links whose strain |x_iJ| / |X_iJ| - 1 exceeds the failure
 * strain (none when failure is off, or an end lies in a no_failure zone). Returns how
 * many it broke and updates intact_count and damage. */
int ps_break_links(solid_model *m, const solid_particles *p, int i);

/* Damage and intact count of point i from its row. */
void ps_count_links(solid_model *m, int i);

/* Pass 1 for point i (pseudo_spring_stress.c): breaks its overstrained links, then
 * updates its density (into density_next), stress from G and R_i (art_r). Returns a
 * PS_STEP_* outcome and the number of links it broke. */
enum { PS_STEP_OK = 0, PS_STEP_NOT_FINITE = 1, PS_STEP_CRUSHED = 2 };
int ps_update_point(solid_model *m, const solid_particles *p, const double *x_prev, int i,
                    int *broke);

/* Pass 2 (pseudo_spring_pairs.c), after pass 1 (final links, densities, R): the
 * kernel quantities of point i's pairs with every j > i into link_f and link_art,
 * at both slots of the pair. */
void ps_pair_quantities(solid_model *m, const solid_particles *p, int i);

/* Pass 3 for point i, after pass 2: D_i into gather. */
void ps_gather_factors(solid_model *m, const solid_particles *p, int i);

/* Hourglass control (pseudo_spring_hourglass.c): F_i and kappa_i of the current
 * positions into m->hourglass (pass 3); adds the control's force on point k to f
 * (pass 4, after every point's factors); point i's stored energy E_i at the current
 * positions. */
void ps_hourglass_weights(solid_model *m, const solid_particles *p);   /* at creation */
void ps_hourglass_factors(solid_model *m, const solid_particles *p, int i);
void ps_hourglass_force(const solid_model *m, const solid_particles *p, int k, double *f);
double ps_hourglass_energy(const solid_model *m, const solid_particles *p, int i);

/* Prints "pseudo_spring: warning: ..." about point i once (flag PS_POINT_WARNED), up
 * to PS_MAX_WARNINGS lines per model. */
#define PS_MAX_WARNINGS 20
void ps_warn_point(solid_model *m, const solid_particles *p, int i, const char *what, double t);

#endif
