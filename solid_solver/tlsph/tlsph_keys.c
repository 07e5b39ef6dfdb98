/* Keys of the total-Lagrangian SPH solid (docs/cases.md is generated from this table;
 * the model and its equations are in docs/tlsph.md). The material keys are
 * material_keys (materials/), the keys every solid model has fsi_solid_common_keys. */
#include "tlsph_keys.h"

static const fsi_key_spec keys[] = {
    {"kernel", FSI_KEY_CHOICE, "-", "cubic_spline", 0, 0, 0, "cubic_spline|wendland_c2",
     "Kernel of the reference-configuration gradients: cubic_spline (the cubic B-spline of "
     "003 §2.1) or wendland_c2 (004 Eq. 5); both have support 2 h."},
    {"smoothing_length_factor", FSI_KEY_REAL, "-", "1.2", FSI_BOUND_MIN | FSI_BOUND_MAX, 1,
     3, NULL,
     "Smoothing length h as a multiple of the lattice spacing (003 §2.1: h = 1.2 dx); every "
     "point within 2 h in the reference configuration is a neighbour for good."},
    {"gradient_order", FSI_KEY_INT, "-", "2", FSI_BOUND_MIN | FSI_BOUND_MAX, 1, 2, NULL,
     "1: the corrected gradient of 003 Eq. 35 (exact for linear fields; first order where a "
     "family is one-sided, at every surface); 2: the weighted least-squares quadratic fit of "
     "each family (exact gradients of quadratic fields everywhere; the default: S2's period "
     "+1.4 % instead of +4.4 % at T/dx = 10, docs/tlsph.md)."},
    {"courant_number", FSI_KEY_REAL, "-", "0.5", FSI_BOUND_MIN_OPEN | FSI_BOUND_MAX, 0, 1,
     NULL,
     "C of the stable step C h / (c + |v|max), c = sqrt((K + 4 G / 3) / rho) the P-wave "
     "speed, and never above the lattice bound dx / c (both before the main loop's "
     "time_step_safety)."},
    {"hourglass_control", FSI_KEY_REAL, "-", "0", FSI_BOUND_MIN | FSI_BOUND_MAX, 0, 100,
     NULL,
     "Coefficient alpha of Ganzenmueller's (2015) hourglass control: a pair force "
     "proportional to E times the mismatch between each pair's current vector and the one "
     "the points' deformation gradients predict; 0 (the default, 003's scheme) switches it "
     "off (docs/tlsph.md has the measurements)."},
};

const fsi_key_table fsi_tlsph_keys = {
    "tlsph",
    "Total-Lagrangian SPH solid (003 §2.2, Lin et al. 2015): kernel gradients of the "
    "reference configuration with the shape-matrix correction, the deformation gradient, "
    "first Piola-Kirchhoff stress, optional hourglass control (docs/tlsph.md).",
    keys, (int)(sizeof keys / sizeof keys[0])};
