/* Keys of the NOSB-PD model (docs/cases.md is generated from this table; the model
 * and its equations are in docs/nosbpd.md). The material keys are material_keys
 * (materials/), the keys every solid model has are fsi_solid_common_keys. */
#include "nosbpd_keys.h"

static const fsi_key_spec keys[] = {
    {"horizon_factor", FSI_KEY_REAL, "-", "3", FSI_BOUND_MIN | FSI_BOUND_MAX, 1, 10, NULL,
     "Horizon delta as a multiple m of the lattice spacing (delta = m dx): each point "
     "interacts with every point within delta of it in the reference configuration."},
    {"influence_function", FSI_KEY_CHOICE, "-", NOSBPD_DEFAULT_INFLUENCE, 0, 0, 0,
     "one|inverse|gaussian",
     "Bond weight omega(|xi|) in the shape tensor, deformation gradient and force state: "
     "one (1), inverse (delta / |xi|) or gaussian (exp(-(2 |xi| / delta)^2))."},
    {"gradient_order", FSI_KEY_INT, "-", NOSBPD_DEFAULT_GRADIENT_ORDER_TEXT,
     FSI_BOUND_MIN | FSI_BOUND_MAX, 1, 2, NULL,
     "Order of the fit that gives the deformation gradient over a family: 1 is the "
     "linear fit of 000 Eqs. 34 and 36 (F = N K^-1); 2 adds the quadratic terms, so "
     "that F stays exact for bending-like (quadratic) motions where a surface cuts the "
     "family (docs/nosbpd.md). Points whose family cannot carry a quadratic fit use "
     "the linear one."},
    {"zero_energy_coefficient", FSI_KEY_REAL, "-", "0.3", FSI_BOUND_MIN | FSI_BOUND_MAX, 0, 10,
     NULL,
     "Coefficient G of Silling's 2017 zero-energy mode control, a bond force G C omega z "
     "against the part z of the deformed bond that the family's fit does not explain "
     "(z = Y - F xi for gradient_order = 1); 1 matches the stiffness of a bond-based "
     "material of the same bulk modulus, 0 switches the control off."},
    {"failure", FSI_KEY_BOOL, "-", "false", 0, 0, 0, NULL,
     "Whether bonds break (permanently) when their stretch exceeds the critical stretch "
     "(000 Eq. 47); needs critical_stretch or fracture_energy."},
    {"critical_stretch", FSI_KEY_REAL, "-", "0", FSI_BOUND_MIN, 0, 0, NULL,
     "Critical bond stretch s0 (000 Eq. 47); when > 0 it is used and fracture_energy is "
     "ignored, 0 means: derive s0 from fracture_energy."},
    {"fracture_energy", FSI_KEY_REAL, "J/m^2", "0", FSI_BOUND_MIN, 0, 0, NULL,
     "Energy release rate G0 giving s0 = sqrt(5 G0 / (9 K delta)) in 3D (000 Eq. 48), "
     "sqrt(4 pi G0 / (9 E delta)) in 2D plane stress, sqrt(5 pi G0 / (12 E delta)) in 2D "
     "plane strain; used when critical_stretch is 0."},
};

const fsi_key_table fsi_nosbpd_keys = {
    "nosbpd",
    "Non-ordinary state-based peridynamics (correspondence model, 000 §2.2): horizon, "
    "bond weights, zero-energy mode control and bond failure (docs/nosbpd.md).",
    keys, (int)(sizeof keys / sizeof keys[0])};
