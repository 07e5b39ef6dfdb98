/* Case keys of the constitutive models (material.h), shared by every solid model.
 * docs/cases.md is generated from this table, so each description is one sentence
 * a user reads; the models and equations are in docs/materials.md.
 *
 * Only single-key rules live here (type, unit, bounds); what depends on several
 * keys (Drucker-Prager with plane stress, dilation above friction, which keys a
 * model needs) is material_case_check() in material_case.c. This file needs no
 * other part of the library, so a registry can link the table alone. */
#include "material.h"

#include "dim.h"

const fsi_key_spec material_keys[] = {
    {"constitutive", FSI_KEY_CHOICE, "-", "linear_elastic", 0, 0, 0,
     "linear_elastic|drucker_prager|saint_venant_kirchhoff|neo_hookean",
     "Constitutive model: linear_elastic (isotropic Hooke's law in the incremental "
     "objective update of 000 Eq. 43), drucker_prager (perfectly plastic Drucker-Prager "
     "cone matched to Mohr-Coulomb in plane strain), saint_venant_kirchhoff (hyperelastic, "
     "Hooke's law of the Green-Lagrange strain, as the Turek-Hron CSM tests define it) or "
     "neo_hookean (compressible neo-Hookean hyperelasticity for rubber-like large "
     "strains); the hyperelastic two need a model with a deformation gradient (NOSB-PD, "
     "TLSPH; not pseudo_spring), docs/materials.md."},
    /* From aerogels (1 kg/m^3) with room to spare to four times the densest element
     * (osmium, 22590 kg/m^3): a range of physics; the step it gives is checked apart
     * (solid_check.c). */
    {"density", FSI_KEY_REAL, "kg/m^3", NULL, FSI_BOUND_MIN | FSI_BOUND_MAX, 1e-3, 1e5, NULL,
     "Mass density rho0 of the solid in its reference configuration."},
    {"youngs_modulus", FSI_KEY_REAL, "Pa", NULL, FSI_BOUND_MIN_OPEN, 0, 0, NULL,
     "Young's modulus E of the isotropic elastic response."},
    {"poisson_ratio", FSI_KEY_REAL, "-", NULL, FSI_BOUND_MIN | FSI_BOUND_MAX, 0,
     MATERIAL_MAX_POISSON, NULL,
     "Poisson ratio nu of the isotropic elastic response, 0 <= nu <= 0.499 (closer to 0.5 "
     "the bulk modulus would dwarf the shear modulus and set a vanishing explicit step)."},
#if FSI_DIM == 2
    {"plane", FSI_KEY_CHOICE, "-", "strain", 0, 0, 0, "strain|stress",
     "2D idealisation: strain (eps_zz = 0, thick bodies; the only one drucker_prager "
     "supports) or stress (sigma_zz = 0, thin plates; the model solves for eps_zz)."},
#endif
    {"cohesion", FSI_KEY_REAL, "Pa", "0", FSI_BOUND_MIN, 0, 0, NULL,
     "Cohesion c of the Mohr-Coulomb envelope the Drucker-Prager cone is matched to; "
     "required with constitutive = drucker_prager, not taken otherwise."},
    {"friction_angle", FSI_KEY_REAL, "deg", "0", FSI_BOUND_MIN | FSI_BOUND_MAX, 0, 89, NULL,
     "Internal friction angle phi of the Mohr-Coulomb envelope (degrees); required with "
     "constitutive = drucker_prager, not taken otherwise."},
    {"dilation_angle", FSI_KEY_REAL, "deg", "0", FSI_BOUND_MIN | FSI_BOUND_MAX, 0, 89, NULL,
     "Dilation angle psi <= friction_angle of the plastic potential (degrees): 0 gives "
     "plastic flow without volume change (000 Table 4), psi = phi associated flow; "
     "drucker_prager only."},
};

const int material_n_keys = (int)(sizeof material_keys / sizeof material_keys[0]);

const fsi_key_table material_key_table = {
    "materials",
    "Constitutive model and material constants of the solid, shared by every solid model "
    "(docs/materials.md).",
    material_keys, (int)(sizeof material_keys / sizeof material_keys[0])};
