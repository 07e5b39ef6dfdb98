/* Constitutive models shared by every solid model (NOSB-PD now; TLSPH and
 * pseudo-spring SPH later): given a strain increment, update the Cauchy stress and
 * the plastic state. Stress and strain are always full 3D symmetric tensors in the
 * order xx, yy, zz, xy, yz, zx with TENSOR shear components (eps_xy, not gamma_xy),
 * so 2D plane strain (deps_zz = 0) and plane stress (sigma_zz = 0, the model
 * solves for deps_zz) share one code path.
 *
 * The rotation part of the objective update (000 Eqs. 44-46) is done by the caller;
 * a material only sees the rotation-free increment (000 Eq. 43, generalised to
 * plasticity by a return mapping). */
#ifndef FSI_MATERIAL_H
#define FSI_MATERIAL_H

#include <stddef.h>
#include <stdio.h>

#include "case_file.h"

typedef enum { MATERIAL_LINEAR_ELASTIC, MATERIAL_DRUCKER_PRAGER } material_kind;
typedef enum { MATERIAL_PLANE_STRAIN, MATERIAL_PLANE_STRESS } material_plane;

typedef struct {
    material_kind kind;
    material_plane plane;       /* meaningful in 2D builds only */
    double density;             /* rho0 [kg/m^3] */
    double youngs_modulus;      /* E [Pa] */
    double poisson_ratio;       /* nu [-] */
    double bulk_modulus, shear_modulus, lame_lambda;   /* derived */
    /* Drucker-Prager (kind == MATERIAL_DRUCKER_PRAGER) */
    double cohesion;            /* c [Pa] */
    double friction_angle;      /* phi [rad] */
    double dilation_angle;      /* psi [rad] */
    double dp_alpha, dp_k, dp_beta;   /* yield f = alpha I1 + sqrt(J2) - k; potential beta I1 + sqrt(J2) */
} material;

/* Per-point plastic state. */
typedef struct {
    double plastic_strain[6];   /* accumulated plastic strain tensor */
    double equivalent_plastic_strain;   /* sqrt(2/3 e_p : e_p), accumulated */
    /* (e_p above is each step's plastic strain increment, full tensor, shear terms
     * counted twice: sum over steps of sqrt(2/3 de_p : de_p); docs/materials.md.) */
    int yielding;               /* 1 when the last update returned to the yield surface */
} material_state;

/* Reads [solid] material keys (see material_keys) from a validated case; returns
 * 0, or -1 with a message naming the key when the combination is invalid. */
int material_from_case(material *m, const fsi_case *c, const char *section, char *msg,
                       size_t msg_size);

/* Sets the derived constants (bulk, shear, Lame, Drucker-Prager alpha/k/beta). */
void material_derive(material *m);

/* sigma += D : deps, with plastic correction for Drucker-Prager. stress and deps are
 * 6-component tensors; in plane stress deps[2] is an output (the thickness strain). */
void material_update(const material *m, double deps[6], double stress[6], material_state *st);

/* P-wave modulus (lambda + 2 mu, or the plane-stress equivalent): the wave speed
 * sqrt(M / rho) sets the stable step. */
double material_wave_modulus(const material *m);

/* dx / sqrt(M / rho): the time a P wave takes to cross one lattice spacing, the
 * lattice bound of every explicit particle solid's stable step (NOSB-PD's
 * nosbpd_model.c, and the case check's estimate of it, solid_check.c). */
double material_wave_crossing_time(const material *m, double density, double dx);

/* Case keys shared by solid models: density, youngs_modulus, poisson_ratio, plane,
 * constitutive, cohesion, friction_angle (degrees), dilation_angle (degrees). */
extern const fsi_key_spec material_keys[];
extern const int material_n_keys;

/* ------------------------------------------------------------- additions */

/* material_update accepts st == NULL (nothing recorded); it never changes deps
 * except deps[2] in 2D plane stress. */

/* The same keys as a table for a solver spec's key_tables (solid_keys.h order:
 * common keys, this table, the model's keys). In 3D builds 'plane' is absent. */
extern const fsi_key_table material_key_table;

/* The cross-key checks of material_from_case for the launcher's validation (a
 * solver spec's check hook may call it): Drucker-Prager with plane stress, dilation
 * angle above friction angle, missing cohesion/friction_angle with drucker_prager,
 * Drucker-Prager keys given to linear_elastic, nu too close to 0.5, a cone without
 * strength. Writes each problem as "WHERE: [section] key: message" (WHERE as
 * fsi_case_origin, the section header for defaulted keys) and returns how many. */
int material_case_check(const fsi_case *c, const char *section, FILE *errors);

/* Largest accepted Poisson ratio (also the key's bound): beyond it the bulk modulus
 * exceeds 500 shear moduli and the explicit step is set by a nearly rigid volume. */
#define MATERIAL_MAX_POISSON 0.499

/* Isotropic Hooke's law on 6-component tensors (tensor shear components):
 * dsigma = lambda tr(deps) I + 2 mu deps, and its inverse (the compliance). Pure 3D:
 * no plane-stress handling here. */
void material_hooke(const material *m, const double deps[6], double dsigma[6]);
void material_compliance(const material *m, const double dsigma[6], double deps[6]);

/* Drucker-Prager yield function f = alpha I1 + sqrt(J2) - k [Pa] of a stress
 * (tension positive); f <= 0 is admissible. For linear_elastic (c = phi = 0) it is
 * simply sqrt(J2). */
double material_dp_yield(const material *m, const double stress[6]);

/* Invariants: I1 = tr(sigma) and J2 = s:s / 2 with s the deviator. */
double material_i1(const double stress[6]);
double material_j2(const double stress[6]);

#endif
