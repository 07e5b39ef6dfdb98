/* Pass 2 of pseudo_spring_force.c: the quantities of each pair (i, j) that both of its
 * ends need, evaluated once per pair in the current configuration and stored at both
 * of its slots (link q = i -> j and reverse[q] = j -> i):
 *   - F(r) of grad_i W_ij = F(r) x_ij (Wendland C2, 004 Eq. 5): in the correction
 *     B_i (Eq. 20) of pass 3 and in the momentum gather (Eq. 15) of pass 4;
 *   - P^a_ij = (R_i + R_j) (W(r) / W(dx))^n, the artificial stress of Eq. 16, only
 *     where it is on (gamma > 0: link_art not NULL) and acts (R_i + R_j > 0).
 * The kernel depends on r^2 only and x_j - x_i = -(x_i - x_j) exactly in floating
 * point, as is R_i + R_j = R_j + R_i, so each end gets the bits it would have
 * computed itself. Point i writes the slots of its pairs with j > i only: every slot
 * is written by exactly one point, so the pass runs in parallel over points without
 * shared writes and its result does not depend on the number of threads. A pair
 * counts when either slot is intact (rows break both slots in the same pass 1, but
 * a reader never finds a stale value either way). */
#include <math.h>

#include "pseudo_spring_internal.h"

void ps_pair_quantities(solid_model *m, const solid_particles *p, int i)
{
    const solid_bonds *l = &m->links;
    const double *restrict x = p->x;
    for (int64_t q = l->offset[i]; q < l->offset[i + 1]; q++) {
        const int j = l->neighbour[q];
        const int64_t s = m->reverse[q];
        if (j < i || !(l->intact[q] || l->intact[s]))
            continue;
        double r2 = 0.0, w, f;
        for (int d = 0; d < FSI_DIM; d++) {
            const double r = x[(int64_t)i * FSI_DIM + d] - x[(int64_t)j * FSI_DIM + d];
            r2 += r * r;
        }
        wendland_c2_eval2(&m->kernel, r2, &w, &f);
        m->link_f[q] = m->link_f[s] = f;
        if (m->link_art) {
            const double rsum = m->art_r[i] + m->art_r[j];
            m->link_art[q] = m->link_art[s] =
                rsum > 0.0 ? rsum * pow(w / m->w_dx, m->art_exponent) : 0.0;
        }
    }
}
