/* Objective incremental stress update of one material point under finite
 * deformation: the Hughes-Winget algorithm (Hughes & Winget 1980, IJNME 15,
 * 1862-1867) as 000 §2.2.1 Eqs. 37-46 use it, with alpha = 1/2.
 *
 * Given the nonlocal deformation gradients F_n (positions x_prev) and F_{n+1}
 * (positions x), both over the same intact bonds and K^-1 (000 Eqs. 36, 38):
 *   F_{n+a} = (1 - a) F_n + a F_{n+1}            (Eq. 38 on the configuration of Eq. 37,
 *                                                 x_{n+a} = (1 - a) x_n + a x_{n+1})
 *   C       = F_{n+1} - F_n                       (Eq. 39, gradient of du = x_{n+1} - x_n)
 *   G       = C F_{n+a}^-1                        (Eq. 40, gradient of du on x_{n+a})
 *   deps    = (G + G^T) / 2,  w = (G - G^T) / 2   (Eqs. 41, 42)
 *   R       = (I - a w)^-1 (I + (1 - a) w)        (Eq. 46)
 *   sigma_{n+1} = R sigma_n R^T + dsigma(deps)    (Eqs. 43-45, see below)
 * The printed Eqs. 44-45 read sigma~ = sigma_n + dsigma, sigma_{n+1} = R^T sigma~ R.
 * Hughes & Winget rotate the OLD stress, sigma_{n+1} = R sigma_n R^T + dsigma, with
 * R as in Eq. 46 (R = I + w + O(w^2), a rotation carrying the frame of step n into
 * that of step n+1, hence R sigma R^T and not R^T sigma R); the increment, computed
 * on the mid-point configuration, is already in the n+1 frame to second order. We
 * implement the Hughes-Winget form: it is also what a return mapping needs, since
 * the trial state of material_update() must be the rotated old stress plus the
 * elastic increment. Rotating (sigma_n + dsigma) instead differs by O(w dsigma).
 * With a = 1/2 a rigid rotation gives deps = 0 exactly (G is the Cayley transform
 * of the rotation increment, a skew tensor) and R equal to that increment.
 *
 * The plastic strain tensor of the material state is rotated with the stress. In
 * 2D the z axis is fixed: deps_zz = 0 (plane strain) or solved by the material
 * (plane stress); deps_yz = deps_zx = 0. The part from G on (Eqs. 41-46 and the
 * stress work) is shared with the other solid models: solid_objective.h. */
#ifndef NOSBPD_STRESS_UPDATE_H
#define NOSBPD_STRESS_UPDATE_H

#include "dim.h"
#include "material.h"

/* The mid-point parameter alpha of Eqs. 37-46. */
#define NOSBPD_HW_ALPHA 0.5 /* the same as solid_objective.c's */

/* One point's update. stress (6 components, Cauchy), st, *thickness_stretch (2D
 * plane stress: lambda_z, the thickness ratio; 1 otherwise) and *work (stress work
 * per reference volume, J sigma : deps summed with the trapezoidal rule) are
 * updated. Returns 0, or -1 when F_{n+a} is singular or ill-conditioned (nothing
 * is changed then). */
int nosbpd_hughes_winget(const material *mat, const double *f_prev, const double *f_next,
                         double stress[6], material_state *st, double *thickness_stretch,
                         double *work);

/* First Piola-Kirchhoff stress P = J sigma F^-T (000 Eq. 35) with J = det F times
 * the thickness stretch (2D plane stress). Returns 0, or -1 when det F <= 0 or F is
 * singular or ill-conditioned. */
int nosbpd_first_piola(const double stress[6], const double *f, double thickness_stretch,
                       double *p);

#endif
