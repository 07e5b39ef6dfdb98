/* Hourglass control of the TLSPH solid (Ganzenmueller 2015, CMAME 286, "An hourglass
 * control algorithm for Lagrangian Smooth Particle Hydrodynamics"). F_i, the
 * corrected-gradient fit of a point's family, cannot see a displacement field that
 * alternates from point to point (the zero-energy modes of the collocated scheme).
 * Each pair compares its current vector x_ij = x_j - x_i with the ones the two ends'
 * deformation gradients predict from the reference vector X_ij:
 *     delta_i = (F_i X_ij - x_ij) . e_ij,   delta_j = (F_j X_ij - x_ij) . e_ij,
 * (e_ij = x_ij / |x_ij|; delta < 0 when the pair is longer than its ends' F predict)
 * and a central pair force of the material's own stiffness restores the prediction:
 *     f_i += -alpha/2 E V_i V_j W_ij (delta_i + delta_j) / |X_ij|^2 e_ij,
 * equal and opposite on j (both momenta conserved). It is zero for every affine field
 * (F_i = F_j = F, x_ij = F X_ij). Images (mirrored clamp points) are not material and
 * take no part. The force is not the derivative of an energy and can feed energy into
 * a body near its clamps (docs/tlsph.md, "Hourglass control"): it is off by default. */
#include <math.h>

#include "tlsph_internal.h"

static double predicted_mismatch(const double *f, const double *xref, const double *x,
                                 const double *e)
{
    double fx[FSI_DIM], s = 0.0;
    fsi_mat_vec(f, xref, fx);
    for (int d = 0; d < FSI_DIM; d++)
        s += (fx[d] - x[d]) * e[d];
    return s;
}

void tlsph_hourglass_force(const solid_model *m, const solid_particles *p, int i, double *f)
{
    const solid_bonds *b = &m->family;
    const double *fi = m->defgrad + (int64_t)i * FSI_MAT_SIZE;
    const double scale = -0.5 * m->hg_alpha * m->mat.youngs_modulus * p->volume[i];
    for (int64_t q = b->offset[i]; q < b->offset[i + 1]; q++) {
        const int j = b->neighbour[q];
        if (m->ghost[i] || m->ghost[j])
            continue;
        const double *xref = b->xi + q * FSI_DIM;
        double x[FSI_DIM], e[FSI_DIM], r2 = 0.0;
        for (int d = 0; d < FSI_DIM; d++) {
            x[d] = p->x[(int64_t)j * FSI_DIM + d] - p->x[(int64_t)i * FSI_DIM + d];
            r2 += x[d] * x[d];
        }
        if (!(r2 > 0.0))
            continue;
        const double r = sqrt(r2);
        for (int d = 0; d < FSI_DIM; d++)
            e[d] = x[d] / r;
        const double *fj = m->defgrad + (int64_t)j * FSI_MAT_SIZE;
        const double sum =
            predicted_mismatch(fi, xref, x, e) + predicted_mismatch(fj, xref, x, e);
        const double s = scale * b->weight[q] * m->kernel_w[q] * sum /
                         (b->length[q] * b->length[q]);
        for (int d = 0; d < FSI_DIM; d++)
            f[d] += s * e[d];
    }
}
