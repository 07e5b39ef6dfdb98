/* Hughes-Winget objective stress update and the first Piola-Kirchhoff stress:
 * see nosbpd_stress_update.h. */
#include "nosbpd_stress_update.h"

#include "small_tensor.h"

/* Largest condition number accepted for F (a deformation gradient with principal
 * stretches more than 1e8 apart is no continuum any more). */
#define MAX_CONDITION_F 1e8

int nosbpd_hughes_winget(const material *mat, const double *f_prev, const double *f_next,
                         double stress[6], material_state *st, double *thickness_stretch,
                         double *work)
{
    const double a = NOSBPD_HW_ALPHA;
    double f_mid[FSI_MAT_SIZE], c[FSI_MAT_SIZE], f_mid_inv[FSI_MAT_SIZE];
    for (int k = 0; k < FSI_MAT_SIZE; k++) {
        f_mid[k] = (1.0 - a) * f_prev[k] + a * f_next[k]; /* Eqs. 37-38 */
        c[k] = f_next[k] - f_prev[k];                     /* Eq. 39 */
    }
    if (fsi_mat_inverse(f_mid, f_mid_inv, MAX_CONDITION_F) != 0)
        return -1;
    double g[FSI_MAT_SIZE], deps[FSI_MAT_SIZE], w[FSI_MAT_SIZE];
    fsi_mat_mul(c, f_mid_inv, g); /* Eq. 40 */
    fsi_mat_sym(g, deps);         /* Eq. 41 */
    fsi_mat_skew(g, w);           /* Eq. 42 */

    /* Eq. 46: R = (I - a w)^-1 (I + (1 - a) w). det(I - a w) >= 1 for skew w. */
    double lhs[FSI_MAT_SIZE], rhs[FSI_MAT_SIZE], lhs_inv[FSI_MAT_SIZE], r[FSI_MAT_SIZE];
    fsi_mat_identity(lhs);
    fsi_mat_identity(rhs);
    fsi_mat_axpy(lhs, -a, w, lhs);
    fsi_mat_axpy(rhs, 1.0 - a, w, rhs);
    if (fsi_mat_inverse(lhs, lhs_inv, 1e300) != 0)
        return -1;
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
    *work += fsi_mat_det(f_mid) * lz_mid * fsi_sym6_ddot(sigma_mid, deps6);
    return 0;
}

int nosbpd_first_piola(const double stress[6], const double *f, double thickness_stretch,
                       double *p)
{
    double f_inv[FSI_MAT_SIZE], sigma[FSI_MAT_SIZE];
    const double det = fsi_mat_det(f);
    if (!(det > 0.0) || fsi_mat_inverse(f, f_inv, MAX_CONDITION_F) != 0)
        return -1;
    fsi_sym6_to_mat(stress, sigma);
    fsi_mat_mul_transpose(sigma, f_inv, p); /* sigma F^-T */
    fsi_mat_scale(p, det * thickness_stretch);
    return 0;
}
