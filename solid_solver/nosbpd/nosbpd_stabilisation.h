/* Zero-energy (hourglass) mode control after Silling 2017 ("Stability of
 * peridynamic correspondence material models and their particle discretizations",
 * CMAME 322, 42-57): a term added to the strain energy density that resists the
 * non-uniform part of the deformation of each family,
 *     z<xi> = Y<xi> - F xi                     (Y<xi> = x_J - x_I, the deformed bond)
 *     W_s   = (1/2) G C_w sum_J omega V_J |z|^2
 *     T_s<xi> = dW_s / dY<xi> = G C_w omega z<xi>      (force state per V_J).
 * Because K and F are sums over the same bonds with the same weight omega,
 * sum_J omega V_J z (x) xi = 0: the dependence of z on Y through F drops out of
 * dW_s/dY, a uniform deformation (z = 0) feels nothing (the stress and the patch
 * test are untouched), and sum_J T_s (x) Y = G C_w sum omega z (x) z is symmetric
 * (angular momentum is kept). Smooth quadratic fields are not resisted in the
 * interior either: z_I<xi> and z_J<-xi> cancel in the pair force.
 *
 * G is the key zero_energy_coefficient (dimensionless, 0 switches the term off).
 * C_w scales it like Silling's bond micromodulus: G = 1 gives the family the same
 * total bond stiffness against z as a bond-based (PMB) material of the same bulk
 * modulus has against bond stretch,
 *     C_w sum_J omega V_J = c sum_J V_J / |xi|   over a complete lattice family,
 *     c = 18 K / (pi delta^4)   (3D),   c = 12 kappa / (pi delta^3)   (2D)
 * with K = M - 4 mu / 3 the bulk modulus and kappa = M - mu the in-plane (2D) bulk
 * modulus (lambda + mu in plane strain, E / (2 (1 - nu)) in plane stress), M the
 * P-wave modulus (material_wave_modulus). With the inverse influence function
 * (omega = delta / |xi|) this is exactly T_s = G c z / |xi|, the unprojected form
 * of a PMB bond force. */
#ifndef NOSBPD_STABILISATION_H
#define NOSBPD_STABILISATION_H

#include "material.h"
#include "nosbpd_bonds.h"

/* The bond-based micromodulus c of the material for horizon delta. */
double nosbpd_micromodulus(const material *mat, double delta);

/* G C_w: T_s = (this) omega z. */
double nosbpd_stabilisation_modulus(const material *mat, double coefficient, double delta,
                                    const nosbpd_full_family *full);

#endif
