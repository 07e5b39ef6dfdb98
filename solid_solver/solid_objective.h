/* The objective incremental stress update every solid model shares: the rotation
 * part of the Hughes-Winget algorithm (Hughes & Winget 1980, IJNME 15, 1862-1867;
 * 000 §2.2.1 Eqs. 41-46 with alpha = 1/2), around the shared material's
 * rotation-free update (material_update, materials/).
 *
 * Input: G, the gradient of the displacement increment du = x_{n+1} - x_n with
 * respect to the mid-point configuration x_{n+1/2} = (x_n + x_{n+1}) / 2 (NOSB-PD:
 * G = (F_{n+1} - F_n) F_{n+1/2}^-1, 000 Eq. 40; pseudo-spring SPH: the corrected
 * kernel gradient of du on x_{n+1/2}, docs/pseudo_spring.md). Then
 *   deps = (G + G^T) / 2,  w = (G - G^T) / 2            (Eqs. 41, 42; 004 Eq. 18 times dt)
 *   R    = (I - w / 2)^-1 (I + w / 2)                    (Eq. 46)
 *   sigma_{n+1} = R sigma_n R^T + dsigma(deps)           (Eqs. 43-45; the material)
 * R sigma R^T is the Jaumann rate's rotation (004 Eq. 17: S w^T + w S) integrated
 * over the step with the mid-point spin, second-order accurate and exactly a
 * rotation. With alpha = 1/2 a rigid rotation gives deps = 0 exactly (G is the Cayley
 * transform of the rotation increment, a skew tensor). Why the old stress is rotated
 * (and not sigma_n + dsigma, as 000 Eqs. 44-45 print): nosbpd_stress_update.h.
 *
 * The plastic strain tensor is rotated with the stress. In 2D the z axis is fixed:
 * deps_zz = 0 (plane strain) or solved by the material (plane stress). */
#ifndef FSI_SOLID_OBJECTIVE_H
#define FSI_SOLID_OBJECTIVE_H

#include "dim.h"
#include "material.h"

/* One point's update. stress (6 components, Cauchy), st, *thickness_stretch (2D
 * plane stress: lambda_z, the thickness ratio; 1 otherwise) and *work are updated:
 * work += volume_ratio_mid lambda_z,mid sigma_{n+1/2} : deps (the stress work per
 * reference volume over the step, trapezoidal in sigma), volume_ratio_mid the
 * in-plane volume ratio of the mid-point configuration to the reference one. */
void solid_objective_update(const material *mat, const double *g, double volume_ratio_mid,
                            double stress[6], material_state *st, double *thickness_stretch,
                            double *work);

#endif
