/* The corrected kernel gradient (004 Eq. 20, Chen et al. 1999) over a point's intact
 * links, and the gradient of the displacement increment (004 Eq. 19).
 *
 * With x_ij = x_i - x_j and grad_i W_ij = F(r) x_ij (F = (dW/dr) / r of the Wendland
 * C2 kernel, core/wendland_c2.h),
 *     A_i = sum_J V_J grad_i W_iJ (x) (x_J - x_i),   B_i = A_i^-1,
 *     W^_iJ = B_i grad_i W_iJ,
 * so that sum_J V_J (x_J - x_i) (x) W^_iJ = I: the gradient of any linear field is
 * exact at every point, an edge's or a corner's too (004 §3.2, C1 consistency), which
 * the uncorrected sum over 8 immediate neighbours is far from (A = 0.65 I inside the
 * lattice for h = 1.5 dx). 004 Eq. 20 writes A with -x_ij = x_j - x_i; the order of
 * the factors makes B A = I with W^ = B grad W as the velocity gradient uses it.
 *
 * A is summed over the intact links only (f_ij = 1): a broken link is no part of the
 * point's neighbourhood any more, and a correction over the reference links would
 * make the gradient of a point next to a crack inconsistent (the sum over its
 * remaining links would no longer reproduce a linear field). When the remaining
 * links nearly lie on a line (condition number above PS_MAX_CONDITION_A), A^-1 would
 * amplify round-off: B is then the Tikhonov-regularised inverse
 *     B = (A^T A + lambda^2 I)^-1 A^T,   lambda = PS_REGULARISATION |A|,
 * which acts as A^-1 on the directions the links span well and damps the others to
 * zero (the pseudo-inverse's behaviour, without its jump when a singular value
 * crosses zero). With no intact link B = 0: the point is detached. */
#include "pseudo_spring_internal.h"

int ps_correction(const solid_model *m, const double *x, const double *x_prev,
                  const double *density, const double *link_f, int i, double *b)
{
    const solid_bonds *l = &m->links;
    double a[FSI_MAT_SIZE] = {0}, yi[FSI_DIM];
    ps_position(x, x_prev, i, yi);
    int count = 0;
    for (int64_t q = l->offset[i]; q < l->offset[i + 1]; q++) {
        if (!l->intact[q])
            continue;
        const int j = l->neighbour[q];
        double yj[FSI_DIM], r[FSI_DIM], r2 = 0.0, w, f;
        ps_position(x, x_prev, j, yj);
        for (int d = 0; d < FSI_DIM; d++) {
            r[d] = yi[d] - yj[d];
            r2 += r[d] * r[d];
        }
        if (link_f)
            f = link_f[q];      /* evaluated once per pair (pseudo_spring_pairs.c) */
        else
            wendland_c2_eval2(&m->kernel, r2, &w, &f);
        /* grad W (x) (x_J - x_i) = -F x_ij (x) x_ij */
        fsi_mat_add_outer(a, -f * m->mass[j] / density[j], r, r);
        count++;
    }
    if (count == 0) {
        fsi_mat_zero(b);
        return PS_POINT_DETACHED;
    }
    if (fsi_mat_inverse(a, b, PS_MAX_CONDITION_A) == 0)
        return 0;
    const double lambda = PS_REGULARISATION * fsi_mat_norm(a);
    double ata[FSI_MAT_SIZE], ata_inv[FSI_MAT_SIZE];
    fsi_mat_transpose_mul(a, a, ata);
    for (int d = 0; d < FSI_DIM; d++)
        FSI_MAT(ata, d, d) += lambda * lambda;
    if (fsi_mat_inverse(ata, ata_inv, 1e300) != 0) {
        fsi_mat_zero(b);        /* |A| = 0: links of zero weight only (beyond the support) */
        return PS_POINT_REGULARISED;
    }
    fsi_mat_mul_transpose(ata_inv, a, b);      /* (A^T A + l^2 I)^-1 A^T */
    return PS_POINT_REGULARISED;
}

int ps_increment_gradient(const solid_model *m, const solid_particles *p, const double *x_prev,
                          int i, double *g)
{
    const solid_bonds *l = &m->links;
    double b[FSI_MAT_SIZE];
    const int outcome = ps_correction(m, p->x, x_prev, m->density, NULL, i, b);
    /* M = sum_J V_J (du_J - du_i) (x) grad W_iJ on the mid-point configuration; then
     * G = M B^T, i.e. G_ab = sum_J V_J (du_J - du_i)_a W^_iJ,b. */
    double mm[FSI_MAT_SIZE] = {0}, yi[FSI_DIM], dui[FSI_DIM];
    const double *x = p->x;
    ps_position(x, x_prev, i, yi);
    for (int d = 0; d < FSI_DIM; d++)
        dui[d] = x[(int64_t)i * FSI_DIM + d] - x_prev[(int64_t)i * FSI_DIM + d];
    for (int64_t q = l->offset[i]; q < l->offset[i + 1]; q++) {
        if (!l->intact[q])
            continue;
        const int j = l->neighbour[q];
        double yj[FSI_DIM], r[FSI_DIM], du[FSI_DIM], r2 = 0.0, w, f;
        ps_position(x, x_prev, j, yj);
        for (int d = 0; d < FSI_DIM; d++) {
            r[d] = yi[d] - yj[d];
            r2 += r[d] * r[d];
            du[d] = x[(int64_t)j * FSI_DIM + d] - x_prev[(int64_t)j * FSI_DIM + d] - dui[d];
        }
        wendland_c2_eval2(&m->kernel, r2, &w, &f);
        fsi_mat_add_outer(mm, f * m->mass[j] / m->density[j], du, r);
    }
    fsi_mat_mul_transpose(mm, b, g);
    return outcome;
}
