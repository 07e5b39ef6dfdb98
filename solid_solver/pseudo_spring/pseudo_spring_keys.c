/* Keys of the pseudo-spring SPH solid (docs/cases.md is generated from this table;
 * the model and its equations are in docs/pseudo_spring.md). The material keys are
 * material_keys (materials/), the keys every solid model has fsi_solid_common_keys. */
#include "pseudo_spring_keys.h"

static const fsi_key_spec keys[] = {
    {"smoothing_length_factor", FSI_KEY_REAL, "-", "1.5", FSI_BOUND_MIN | FSI_BOUND_MAX, 1, 3,
     NULL,
     "Smoothing length h of the Wendland C2 kernel (004 Eq. 5, support 2 h) as a multiple "
     "of the lattice spacing (004 §5.2: h / dp = 1.5). The interactions are the immediate "
     "lattice neighbours whatever h is (004 §3.2); h only sets their weights, and at least "
     "1 keeps the diagonal neighbours well inside the support."},
    {"artificial_viscosity_alpha", FSI_KEY_REAL, "-", "1", FSI_BOUND_MIN | FSI_BOUND_MAX, 0, 10,
     NULL,
     "Linear coefficient beta_1 of Monaghan's artificial viscosity (004 Eqs. 8-9 and 15) "
     "between approaching linked points; 004 gives no value for the solid, 1 is Monaghan's "
     "usual one."},
    {"artificial_viscosity_beta", FSI_KEY_REAL, "-", "1", FSI_BOUND_MIN | FSI_BOUND_MAX, 0, 10,
     NULL, "Quadratic coefficient beta_2 of the artificial viscosity (004 Eq. 8)."},
    {"artificial_stress", FSI_KEY_REAL, "-", "0", FSI_BOUND_MIN | FSI_BOUND_MAX, 0, 1, NULL,
     "Coefficient gamma of Monaghan's (2000) artificial stress against the tensile "
     "instability (004 Eq. 16; 004 §5.2 uses 0.3, 004's scheme as printed); 0, the "
     "default, switches it off: with the hourglass control the strip in tension stays "
     "smooth without it, and it lengthens S3's period by 1.6 % (docs/pseudo_spring.md)."},
    {"artificial_stress_exponent", FSI_KEY_REAL, "-", "0", FSI_BOUND_MIN | FSI_BOUND_MAX, 0, 10,
     NULL,
     "Exponent n of (W(d) / W(dp))^n in the artificial stress (004 Eq. 16); 0 means "
     "W(0) / W(dp) as 004 §3 defines it (2.17 for h = 1.5 dp)."},
    {"failure", FSI_KEY_BOOL, "-", "false", 0, 0, 0, NULL,
     "Whether links (pseudo-springs, 004 §3.3) break, for good, when their strain "
     "|x_ij| / |X_ij| - 1 exceeds failure_strain; a broken link no longer interacts "
     "(f_ij = 0)."},
    {"failure_strain", FSI_KEY_REAL, "-", "0.05", FSI_BOUND_MIN_OPEN | FSI_BOUND_MAX, 0, 10,
     NULL, "Tensile link strain at which a link breaks when failure = true (004 §5.5: 0.05)."},
    {"courant_number", FSI_KEY_REAL, "-", "0.4", FSI_BOUND_MIN_OPEN | FSI_BOUND_MAX, 0, 1,
     NULL,
     "C of the stable step C h / (c + |v|max), c = sqrt((K + 4 G / 3) / rho) the P-wave "
     "speed, and never above the lattice bound dx / c (both before the main loop's "
     "time_step_safety)."},
    {"hourglass_control", FSI_KEY_REAL, "-", "1", FSI_BOUND_MIN | FSI_BOUND_MAX, 0, 10, NULL,
     "Energy of the non-affine part of each point's neighbourhood motion (the zero-energy "
     "modes of the immediate-neighbour stencil, docs/pseudo_spring.md), in units of the "
     "material's own price 2 G for a strain of that size: 1 prices it as a deviatoric "
     "strain, 0 switches the control off (004's scheme as printed)."},
};

const fsi_key_table fsi_pseudo_spring_keys = {
    "pseudo_spring",
    "Pseudo-spring SPH solid (004 §3, Chakraborty & Shaw 2013): updated-Lagrangian SPH "
    "over the immediate lattice neighbours with the corrected kernel gradient, Jaumann "
    "stress rate, artificial viscosity and stress, and link failure "
    "(docs/pseudo_spring.md).",
    keys, (int)(sizeof keys / sizeof keys[0])};
