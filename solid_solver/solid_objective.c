/* Hughes-Winget rotation around the material update: see solid_objective.h. */
#include "solid_objective.h"

#include "small_tensor.h"

void solid_objective_update(const material *mat, const double *g, double volume_ratio_mid,
                            double stress[6], material_state *st, double *thickness_stretch,
                            double *work)
{
    const double a = 0.5;
    double deps[FSI_MAT_SIZE], w[FSI_MAT_SIZE];
    fsi_mat_sym(g, deps);         /* Eq. 41 */
    fsi_mat_skew(g, w);           /* Eq. 42 */

    /* Eq. 46: R = (I - a w)^-1 (I + (1 - a) w). det(I - a w) >= 1 for skew w, so the
     * inverse always exists (bound 1e300: no condition test needed). */
    double lhs[FSI_MAT_SIZE], rhs[FSI_MAT_SIZE], lhs_inv[FSI_MAT_SIZE], r[FSI_MAT_SIZE];
    fsi_mat_identity(lhs);
    fsi_mat_identity(rhs);
    fsi_mat_axpy(lhs, -a, w, lhs);
    fsi_mat_axpy(rhs, 1.0 - a, w, rhs);
    (void)fsi_mat_inverse(lhs, lhs_inv, 1e300);
    fsi_mat_mul(lhs_inv, rhs, r);

    /* Rotate the old state into the new frame, then the rotation-free increment
     * (Eq. 43, with the material's return mapping for plasticity). */
    fsi_sym6_rotate(r, stress);
    fsi_sym6_rotate(r, st->plastic_strain);
    double sigma_old[6], deps6[6] = {0, 0, 0, 0, 0, 0};
    for (int k = 0; k < 6; k++)
        sigma_old[k] = stress[k];
    fsi_mat_to_sym6(deps, deps6); /* 2D: deps_zz = 0 unless plane stress solves it */
    material_update(mat, deps6, stress, st);

    /* Stress work per reference volume, trapezoidal in sigma, with the volume ratio of
     * the mid-point configuration: dW = J_{n+a} sigma_{n+a} : deps. */
    const double lz_old = *thickness_stretch;
    double lz_mid = lz_old;
#if FSI_DIM == 2
    if (mat->plane == MATERIAL_PLANE_STRESS) {
        const double lz_new = lz_old * (1.0 + deps6[2]);
        lz_mid = (1.0 - a) * lz_old + a * lz_new;
        *thickness_stretch = lz_new;
    }
#endif
    double sigma_mid[6];
    for (int k = 0; k < 6; k++)
        sigma_mid[k] = (1.0 - a) * sigma_old[k] + a * stress[k];
    *work += volume_ratio_mid * lz_mid * fsi_sym6_ddot(sigma_mid, deps6);
}
