/* Hughes-Winget objective stress update and the first Piola-Kirchhoff stress:
 * see nosbpd_stress_update.h. */
#include "nosbpd_stress_update.h"

#include "small_tensor.h"
#include "solid_objective.h"

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
    double g[FSI_MAT_SIZE];
    fsi_mat_mul(c, f_mid_inv, g); /* Eq. 40 */
    /* Eqs. 41-46 and the stress work, shared with every solid model. */
    solid_objective_update(mat, g, fsi_mat_det(f_mid), stress, st, thickness_stretch, work);
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
