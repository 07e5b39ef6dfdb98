/* Internal force of the TLSPH solid (003 §2.2), two passes over the reference
 * families, each parallel over points with no shared writes (the result does not
 * depend on the number of threads, bit for bit):
 *   1. per point: F_i = sum_J V_J (x_J - x_i) (x) g_iJ (003 Eq. 36, g the corrected
 *      reference gradient of tlsph_model.c), and P_i, its first Piola-Kirchhoff stress
 *      from the material (P = J sigma F^-T for 003's Hooke law on the Almansi strain,
 *      Eqs. 34 and 37-40 as corrected in docs/tlsph.md; P = dW/dF for the hyperelastic
 *      ones);
 *   2. per point, the gather of the momentum equation (003 Eq. 42 times m_i):
 *        f_i = V_i sum_J V_J (P_i g_iJ - P_J g_Ji) = V_i (P_i s_i - sum_J V_J P_J g_Ji),
 *      s_i = sum_J V_J g_iJ fixed at creation,
 *      plus the hourglass control (tlsph_hourglass.c) when it is on.
 *
 * Eq. 42 is the exact derivative of the discrete energy sum_i V_i W(F_i): with
 * dF_i/dx_J = V_J I (x) g_iJ and dF_i/dx_i = -sum_J V_J I (x) g_iJ,
 *   -dE/dx_k = V_k sum_J V_J P_k g_kJ - sum_{i: k in N(i)} V_i V_k P_i g_ik,
 * which is the gather above (families are symmetric), and g_Ji = -K_J^-T grad_0 W_iJ
 * turns it into Eq. 42's sum of P_a K_a^-1 grad W_ab + P_b K_b^-1 grad W_ab. So the
 * energy check closes, the pair terms are equal and opposite (linear momentum) and
 * the force has no net moment when P F^T is symmetric (angular momentum). Mirrored
 * clamp points are images: their F is not material and their P is 0; the force they
 * receive belongs to their partners (the main loop's chain rule). */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "solid_point_text.h"
#include "tlsph_internal.h"

void tlsph_deformation_gradient(const solid_model *m, const double *x, int i, double *f)
{
    const solid_bonds *b = &m->family;
    fsi_mat_zero(f);
    const double *xi = x + (int64_t)i * FSI_DIM;
    for (int64_t q = b->offset[i]; q < b->offset[i + 1]; q++) {
        const double *xj = x + (int64_t)b->neighbour[q] * FSI_DIM;
        double u[FSI_DIM];
        for (int d = 0; d < FSI_DIM; d++)
            u[d] = xj[d] - xi[d];
        fsi_mat_add_outer(f, b->weight[q], u, m->grad + q * FSI_DIM);
    }
}

int tlsph_point_response(const solid_model *m, const double *x, int i, double *energy,
                         double sigma6[6])
{
    double f[FSI_MAT_SIZE], pk1[FSI_MAT_SIZE];
    tlsph_deformation_gradient(m, x, i, f);
    return material_total_stress(&m->mat, f, pk1, sigma6, energy, NULL);
}

enum { POINT_OK = 0, POINT_INVERTED = 1 };

/* Pass 1 for point i: F_i and P_i (0 for an image). */
static int stress_point(solid_model *m, const solid_particles *p, int i)
{
    double *f = m->defgrad + (int64_t)i * FSI_MAT_SIZE;
    double *pk1 = m->pk1 + (int64_t)i * FSI_MAT_SIZE;
    tlsph_deformation_gradient(m, p->x, i, f);
    if (m->ghost[i]) {
        fsi_mat_zero(pk1);
        return POINT_OK;
    }
    return material_total_stress(&m->mat, f, pk1, NULL, NULL, NULL) == 0 ? POINT_OK
                                                                          : POINT_INVERTED;
}

int tlsph_stress_pass(solid_model *m, const solid_particles *p, double t, char *msg,
                      size_t msg_size)
{
    const int n = m->n;
    int bad = n;
#pragma omp parallel for schedule(static) reduction(min : bad) \
    if (m->family.n_bonds >= TLSPH_PARALLEL_MIN_BONDS)
    for (int i = 0; i < n; i++)
        if (stress_point(m, p, i) != POINT_OK && i < bad)
            bad = i;
    if (bad < n) {
        char where[160];
        solid_describe_point(p, bad, where, sizeof where);
        const double *f = m->defgrad + (int64_t)bad * FSI_MAT_SIZE;
        snprintf(msg, msg_size, "tlsph: the deformation gradient of %s is inverted or not "
                 "finite (det F = %.6g) at t = %.9g s: the body is crushed or the step is "
                 "unstable", where, fsi_mat_det(f), t);
        return -1;
    }
    return 0;
}

/* Pass 2 for point i: f_i = V_i (P_i s_i - sum_J V_J P_J g_Ji). */
static void gather_force(const solid_model *m, const solid_particles *p, int i, double *force)
{
    const solid_bonds *b = &m->family;
    double own[FSI_DIM], other[FSI_DIM] = {0};
    fsi_mat_vec(m->pk1 + (int64_t)i * FSI_MAT_SIZE, m->grad_sum + (int64_t)i * FSI_DIM, own);
    for (int64_t q = b->offset[i]; q < b->offset[i + 1]; q++) {
        const double vj = b->weight[q];
        const double *gji = m->grad + m->reverse[q] * FSI_DIM;
        const double *pj = m->pk1 + (int64_t)b->neighbour[q] * FSI_MAT_SIZE;
        for (int r = 0; r < FSI_DIM; r++)
            for (int s = 0; s < FSI_DIM; s++)
                other[r] += vj * FSI_MAT(pj, r, s) * gji[s];
    }
    for (int d = 0; d < FSI_DIM; d++)
        force[(int64_t)i * FSI_DIM + d] = p->volume[i] * (own[d] - other[d]);
    if (m->hg_alpha > 0.0)
        tlsph_hourglass_force(m, p, i, force + (int64_t)i * FSI_DIM);
}

int solid_model_internal_force(solid_model *m, const solid_particles *p, const double *x_prev,
                               double dt, double t, double *force, char *msg, size_t msg_size)
{
    (void)x_prev;   /* total Lagrangian: the force is a function of x alone */
    (void)dt;
    if (tlsph_stress_pass(m, p, t, msg, msg_size) != 0)
        return -1;
    const int n = m->n;
#pragma omp parallel for schedule(static) if (m->family.n_bonds >= TLSPH_PARALLEL_MIN_BONDS)
    for (int i = 0; i < n; i++)
        gather_force(m, p, i, force);
    return 0;
}
