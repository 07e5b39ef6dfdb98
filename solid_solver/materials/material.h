/* Constitutive models shared by every solid model (NOSB-PD, pseudo-spring SPH,
 * TLSPH), in two forms:
 *  - incremental (material_update): given a strain increment, update the Cauchy
 *    stress and the plastic state (linear_elastic, drucker_prager);
 *  - total (material_total_stress): the stress and strain energy as functions of the
 *    deformation gradient (saint_venant_kirchhoff, neo_hookean, and linear_elastic's
 *    Almansi-Hooke form), for models that have F.
 * Stress and strain are always full 3D symmetric tensors in the order xx, yy, zz, xy,
 * yz, zx with TENSOR shear components (eps_xy, not gamma_xy), so 2D plane strain
 * (deps_zz = 0) and plane stress (sigma_zz = 0, the model solves for deps_zz) share
 * one code path.
 *
 * The rotation part of the objective update (000 Eqs. 44-46) is done by the caller;
 * a material only sees the rotation-free increment (000 Eq. 43, generalised to
 * plasticity by a return mapping). The total form needs no rotation: it is objective
 * by construction. docs/materials.md has the equations. */
#ifndef FSI_MATERIAL_H
#define FSI_MATERIAL_H

#include <stddef.h>
#include <stdio.h>

#include "case_file.h"

typedef enum {
    MATERIAL_LINEAR_ELASTIC,
    MATERIAL_DRUCKER_PRAGER,
    MATERIAL_SAINT_VENANT_KIRCHHOFF,    /* hyperelastic: total form only */
    MATERIAL_NEO_HOOKEAN                /* hyperelastic: total form only */
} material_kind;
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
 * 6-component tensors; in plane stress deps[2] is an output (the thickness strain).
 * The hyperelastic kinds have no incremental form: for them every component of
 * stress becomes NaN (deps untouched), so that a model which calls this instead of
 * material_total_stress stops at its first finiteness check instead of running
 * Hooke's law under another material's name. */
void material_update(const material *m, double deps[6], double stress[6], material_state *st);

/* 1 for materials whose stress is a function of the deformation gradient alone
 * (saint_venant_kirchhoff, neo_hookean): they need a model that has F. */
int material_is_hyperelastic(const material *m);

/* Total-form response at the deformation gradient f (FSI_MAT_SIZE entries, the
 * FSI_DIM x FSI_DIM matrix row-major, as core/small_tensor.h stores matrices).
 * Valid for every kind except MATERIAL_DRUCKER_PRAGER (which returns -1):
 *  - saint_venant_kirchhoff: E = (F^T F - I)/2, S = lambda tr(E) I + 2 mu E, P = F S,
 *    W = lambda/2 tr(E)^2 + mu E:E;
 *  - neo_hookean (compressible, Ciarlet / Bonet & Wood form):
 *    W = mu/2 (I1 - 3) - mu ln J + lambda/2 (ln J)^2, P = mu (F - F^-T) + lambda ln J F^-T;
 *  - linear_elastic: 003's TLSPH law (003 Eqs. 37-40 with Eq. 39 read as the Almansi
 *    strain e = F^-T E F^-1 = (I - F^-T F^-1)/2): sigma = lambda tr(e) I + 2 mu e
 *    (Hooke), P = J sigma F^-T; this is not hyperelastic, its W is the small-strain
 *    1/2 e : D : e times J, exact to second order in the strain (P = dW/dF only to
 *    first order in the strain, relative).
 * In 2D, plane strain has F_zz = 1; plane stress solves F_zz (the thickness stretch)
 * so that the zz stress vanishes (closed form for SVK and for the Almansi-Hooke law,
 * a guarded Newton iteration for neo_hookean) and uses the full 3D W with it.
 * Outputs: p (first Piola-Kirchhoff, FSI_MAT_SIZE, nominal: the force per reference
 * area, the divergence of which in X is the force density), sigma (Cauchy stress, 6
 * components in the order xx, yy, zz, xy, yz, zx as material.h stores tensors; may
 * be NULL), *energy (strain energy per REFERENCE volume [J/m^3]; may be NULL),
 * *thickness_stretch (F_zz; may be NULL; 1 in 3D and plane strain).
 * Returns 0, or -1 when det F <= 0 (or the 3D J including F_zz) or F is not finite;
 * also when F is numerically singular (condition number above 1e12, for the laws
 * that need F^-1) and in plane stress when no thickness stretch makes the zz stress
 * vanish (SVK once the in-plane tr E reaches (1 - nu) / (2 nu), the Almansi-Hooke law
 * once the in-plane tr e reaches -(1 - nu) / (2 nu): docs/materials.md); nothing is
 * written then. */
int material_total_stress(const material *m, const double *f, double *p, double sigma[6],
                          double *energy, double *thickness_stretch);

/* The constitutive key's word for a kind ("linear_elastic", ...). */
const char *material_kind_name(material_kind k);

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
