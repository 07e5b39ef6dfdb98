/* Internal force of the NOSB-PD correspondence model (000 §2.2), two gather passes
 * over the CSR bonds, each parallel over points with no shared writes (so the
 * result does not depend on the number of threads, bit for bit).
 *
 * The deformation of a family is fitted in the basis b(xi) (nosbpd_internal.h):
 *     C = N A^-1,  N = sum_J omega V_J y (x) b(xi),  A = sum_J omega V_J b (x) b,
 * F the first FSI_DIM columns of C. With b = xi (gradient_order = 1) A = K and this
 * is 000 Eqs. 34 and 36. With the quadratic monomials added (order 2) F is exact for
 * quadratic motions at every point, also where the family is cut by a surface,
 * which a linear fit gets wrong by the curvature times the offset of the family's
 * centroid (docs/nosbpd.md, "Second-order deformation gradient"). In both cases
 * F = sum_J omega V_J y (x) g_J with g = G b(xi), G the first FSI_DIM rows of A^-1,
 * so the force state of the strain energy V W(F) is T<xi> = omega P G b(xi)
 * (000 Eq. 33 for order 1, where G b = K^-1 xi).
 *
 * Pass 1, per point I:
 *   - bond failure (Eq. 47): an intact bond with stretch
 *     s = (|y| - |xi|) / |xi| > s0 breaks for ever (tested without a square root as
 *     |y|^2 > (1 + s0)^2 |xi|^2). Both halves of a pair compute the same numbers,
 *     so they break together;
 *   - N_{n+1} and N_n (at x_prev) over the intact bonds; if a bond broke, K, A^-1
 *     and the damage are recomputed (Eqs. 34, 49);
 *   - C = N_{n+1} A^-1, F_{n+1} and F_n (Eqs. 36, 38);
 *   - Hughes-Winget update of the Cauchy stress (Eqs. 37-46, nosbpd_stress_update.h)
 *     and P = J sigma F^-T (Eq. 35); for a hyperelastic material instead P, sigma and
 *     W from F_{n+1} alone (material_total_stress, point_stress below);
 *   - D_I = P G - s C.
 * Pass 2, per point I, the gather form of Eq. 32 with T_I<xi> = omega P_I G_I b(xi),
 * T_J<-xi> = omega P_J G_J b(-xi), plus the stabilisation
 * T_s,I<xi> = s omega (y - C_I b(xi)) (nosbpd_stabilisation.h):
 *   f_I = V_I sum_J omega V_J [D_I b(xi) - D_J b(-xi) + (s_I + s_J) y]
 * [N, per unit thickness in 2D], with s = G C_w (0 for a point without force state).
 * b(-xi) differs from b(xi) only in the sign of its linear part.
 *
 * A point without force state (singular K, or inverted F with failure on) has
 * D = 0 and s = 0: it still feels its neighbours' force states through its bonds,
 * exerts none of its own, and its stress is zero. */
#include <stdio.h>
#include <string.h>

#include "nosbpd_internal.h"
#include "nosbpd_stress_update.h"
#include "solid_point_text.h"

#define NO_FORCE_STATE NOSBPD_NO_FORCE_STATE

/* Pass-1 outcome of a point. */
enum { POINT_OK = 0, POINT_BECAME_SINGULAR = 1, POINT_INVERTED = 2, POINT_NOT_FINITE = 3 };

static void clear_point(solid_model *m, int i)
{
    double *g = m->gather + (int64_t)i * m->gather_stride;
    for (int k = 0; k < m->gather_stride; k++)
        g[k] = 0.0;
    for (int k = 0; k < 6; k++)
        m->stress[(int64_t)i * 6 + k] = 0.0;
}

static int all_finite(const double *a, int count)
{
    for (int k = 0; k < count; k++)
        if (!isfinite(a[k]))
            return 0;
    return 1;
}

/* P (pk1) and the Cauchy stress of point i at F_{n+1} = f1. A hyperelastic material
 * is a function of F: P, sigma and W per reference volume (into work, which
 * solid_model_strain_energy sums) come from f1 alone (materials/hyperelastic.c), with no
 * rate, no rotation and no integration error in W. The others integrate their rate
 * from F_n = f0: Hughes-Winget (Eqs. 37-46), then P = J sigma F^-T (Eq. 35). Returns 0,
 * or -1 (F inverted, singular or ill-conditioned). */
static int point_stress(solid_model *m, int i, const double *f0, const double *f1,
                        double *stress, double *pk1)
{
    if (material_is_hyperelastic(&m->mat))
        return material_total_stress(&m->mat, f1, pk1, stress, &m->work[i],
                                     &m->thickness_stretch[i]);
    if (nosbpd_hughes_winget(&m->mat, f0, f1, stress, &m->mstate[i], &m->thickness_stretch[i],
                             &m->work[i]) != 0)
        return -1;
    return nosbpd_first_piola(stress, f1, m->thickness_stretch[i], pk1);
}

/* Pass 1 for point i; returns a POINT_* outcome and the number of bonds it broke. */
static int update_point(solid_model *m, const solid_particles *p, const double *x_prev, int i,
                        int *broke)
{
    const nosbpd_bonds *b = &m->bonds;
    const double *restrict x = p->x;
    const double *restrict xi_all = b->xi;
    const double *restrict weight = b->weight;
    const int32_t *restrict nb_index = b->neighbour;
    uint8_t *restrict intact = b->intact;
    /* A point of a no_failure region keeps all its bonds; others keep those to one. */
    const int failure = m->failure && !(p->flags[i] & SOLID_UNBREAKABLE);
    const double crit2 = (1.0 + m->critical_stretch) * (1.0 + m->critical_stretch);

    const int nb = m->n_basis;
    const double inv_delta = 1.0 / m->delta;
    double n1[FSI_DIM * NOSBPD_MAX_BASIS] = {0}, n0[FSI_DIM * NOSBPD_MAX_BASIS] = {0};
    const double *xi_pos = x + (int64_t)i * FSI_DIM, *xp_pos = x_prev + (int64_t)i * FSI_DIM;
    int broken_here = 0;
    for (int64_t q = b->offset[i]; q < b->offset[i + 1]; q++) {
        if (!intact[q])
            continue;
        const int j = nb_index[q];
        double y1[FSI_DIM], y0[FSI_DIM];
        for (int d = 0; d < FSI_DIM; d++) {
            y1[d] = x[(int64_t)j * FSI_DIM + d] - xi_pos[d];
            y0[d] = x_prev[(int64_t)j * FSI_DIM + d] - xp_pos[d];
        }
        if (failure && !(p->flags[j] & SOLID_UNBREAKABLE)) {
            /* Eq. 47, s = (|y| - |xi|) / |xi| > s0, as |y|^2 > (1 + s0)^2 |xi|^2. */
            const double len = b->length[q];
            if (fsi_vec_dot(y1, y1) > crit2 * (len * len)) {
                intact[q] = 0;
                broken_here++;
                continue;
            }
        }
        double basis[NOSBPD_MAX_BASIS];
        solid_fit_basis(xi_all + q * FSI_DIM, inv_delta, nb, basis);
        const double w = weight[q];
        for (int r = 0; r < FSI_DIM; r++) {
            const double a1 = w * y1[r], a0 = w * y0[r];
            for (int c = 0; c < nb; c++) {
                n1[r * nb + c] += a1 * basis[c];
                n0[r * nb + c] += a0 * basis[c];
            }
        }
    }
    *broke = broken_here;

    const uint8_t had = m->flags[i];
    int outcome = POINT_OK;
    if (broken_here && !(had & NO_FORCE_STATE) && nosbpd_shape_tensor(m, p, i) != 0) {
        m->flags[i] |= NOSBPD_POINT_SINGULAR_SHAPE;
        outcome = POINT_BECAME_SINGULAR;
    } else if (broken_here && (had & NO_FORCE_STATE)) {
        (void)nosbpd_shape_tensor(m, p, i); /* damage and intact count only */
    }
    if (m->flags[i] & NO_FORCE_STATE) {
        clear_point(m, i);
        return outcome;
    }

    /* C = N A^-1 (A^-1 symmetric); F = its first FSI_DIM columns (Eq. 36). */
    const double *a_inv = m->moment_inv + (int64_t)i * nb * nb;
    double *fit = m->fit + (int64_t)i * FSI_DIM * nb;
    double *f1 = m->defgrad + (int64_t)i * FSI_MAT_SIZE;
    double f0[FSI_MAT_SIZE], f1_new[FSI_MAT_SIZE], fit_new[FSI_DIM * NOSBPD_MAX_BASIS];
    for (int r = 0; r < FSI_DIM; r++)
        for (int c = 0; c < nb; c++) {
            double t1 = 0.0, t0 = 0.0;
            for (int k = 0; k < nb; k++) {
                t1 += n1[r * nb + k] * a_inv[k * nb + c];
                t0 += n0[r * nb + k] * a_inv[k * nb + c];
            }
            fit_new[r * nb + c] = t1;
            if (c < FSI_DIM) {
                FSI_MAT(f1_new, r, c) = t1;
                FSI_MAT(f0, r, c) = t0;
            }
        }
    if (!all_finite(fit_new, FSI_DIM * nb) || !all_finite(f0, FSI_MAT_SIZE)) {
        fsi_mat_copy(f1_new, f1);
        return POINT_NOT_FINITE;
    }

    double *stress = m->stress + (int64_t)i * 6;
    double pk1[FSI_MAT_SIZE];
    if (fsi_mat_det(f1_new) <= 0.0 || point_stress(m, i, f0, f1_new, stress, pk1) != 0) {
        fsi_mat_copy(f1_new, f1);
        return POINT_INVERTED;
    }
    fsi_mat_copy(f1_new, f1);
    memcpy(fit, fit_new, sizeof(double) * (size_t)(FSI_DIM * nb));

    /* D = P G - s C, G = rows 0 .. FSI_DIM-1 of A^-1. */
    double *g = m->gather + (int64_t)i * m->gather_stride;
    const double s = m->stab_modulus;
    for (int r = 0; r < FSI_DIM; r++)
        for (int c = 0; c < nb; c++) {
            double t = -s * fit[r * nb + c];
            for (int k = 0; k < FSI_DIM; k++)
                t += FSI_MAT(pk1, r, k) * a_inv[k * nb + c];
            g[r * nb + c] = t;
        }
    g[FSI_DIM * nb] = s;
    return POINT_OK;
}

/* Pass 2 for point i: the gather of Eq. 32. */
static void gather_force(const solid_model *m, const solid_particles *p, int i, double *force)
{
    const nosbpd_bonds *b = &m->bonds;
    const double *restrict x = p->x;
    const double *restrict xi_all = b->xi;
    const double *restrict weight = b->weight;
    const int32_t *restrict nb_index = b->neighbour;
    const uint8_t *restrict intact = b->intact;
    const double *restrict gather = m->gather;
    const int nb = m->n_basis, stride = m->gather_stride;
    const double inv_delta = 1.0 / m->delta;

    const double *di = gather + (int64_t)i * stride;
    const double si = di[FSI_DIM * nb];
    const double *xi_pos = x + (int64_t)i * FSI_DIM;
    double f[FSI_DIM];
    for (int d = 0; d < FSI_DIM; d++)
        f[d] = 0.0;
    for (int64_t q = b->offset[i]; q < b->offset[i + 1]; q++) {
        if (!intact[q])
            continue;
        const int j = nb_index[q];
        const double *dj = gather + (int64_t)j * stride;
        double basis[NOSBPD_MAX_BASIS];
        solid_fit_basis(xi_all + q * FSI_DIM, inv_delta, nb, basis);
        const double s = si + dj[FSI_DIM * nb];
        const double w = weight[q];
        for (int r = 0; r < FSI_DIM; r++) {
            const double *dir = di + r * nb, *djr = dj + r * nb;
            double t = s * (x[(int64_t)j * FSI_DIM + r] - xi_pos[r]);
            for (int c = 0; c < FSI_DIM; c++)
                t += (dir[c] + djr[c]) * basis[c];     /* linear part: b(-xi) = -xi */
            for (int c = FSI_DIM; c < nb; c++)
                t += (dir[c] - djr[c]) * basis[c];     /* quadratic part: even */
            f[r] += w * t;
        }
    }
    const double vi = p->volume[i];
    for (int d = 0; d < FSI_DIM; d++)
        force[(int64_t)i * FSI_DIM + d] = vi * f[d];
}

int solid_model_internal_force(solid_model *m, const solid_particles *p, const double *x_prev,
                               double dt, double t, double *force, char *msg, size_t msg_size)
{
    (void)dt; /* the update is incremental in positions; dt is not needed */
    const int n = m->n;
    int first_bad = n, new_flags = 0;
    int64_t broken = 0;

    const int parallel = m->bonds.n_bonds >= NOSBPD_PARALLEL_MIN_BONDS;
#pragma omp parallel for schedule(static) if (parallel) reduction(min : first_bad) \
    reduction(+ : new_flags, broken)
    for (int i = 0; i < n; i++) {
        int broke = 0;
        const int outcome = update_point(m, p, x_prev, i, &broke);
        broken += broke;
        if (outcome == POINT_NOT_FINITE || (outcome == POINT_INVERTED && !m->failure)) {
            if (i < first_bad)
                first_bad = i;
        } else if (outcome == POINT_INVERTED) {
            m->flags[i] |= NOSBPD_POINT_INVERTED;
            clear_point(m, i);
            new_flags++;
        } else if (outcome == POINT_BECAME_SINGULAR) {
            new_flags++;
        }
    }
    m->n_broken += broken;

    if (first_bad < n) {
        char at[256];
        solid_describe_point(p, first_bad, at, sizeof at);
        const double *f = m->defgrad + (int64_t)first_bad * FSI_MAT_SIZE;
        const double det = fsi_mat_det(f);
        if (!isfinite(det))
            snprintf(msg, msg_size, "nosbpd: the deformation gradient of %s is not finite at "
                     "t = %.9g s (positions not finite?)", at, t);
        else
            snprintf(msg, msg_size, "nosbpd: the deformation gradient of %s is inverted or "
                     "singular (det F = %.6g) at t = %.9g s: the body is crushed or the step "
                     "is unstable (with failure = true such a point would be taken out)", at,
                     det, t);
        return -1;
    }
    if (new_flags) {
        int count = 0;
        for (int i = 0; i < n; i++) {
            if (!(m->flags[i] & (NOSBPD_POINT_SINGULAR_SHAPE | NOSBPD_POINT_INVERTED)))
                continue;
            count++;
            if (!(m->flags[i] & NOSBPD_POINT_WARNED))
                nosbpd_warn_point(m, p, i,
                                  (m->flags[i] & NOSBPD_POINT_INVERTED)
                                      ? "its deformation gradient inverted: it carries no "
                                        "force state from now on"
                                      : "after bond failure its family is too poor for a "
                                        "shape tensor: it carries no force state from now on",
                                  t);
        }
        m->n_without_force_state = count;
    }

#pragma omp parallel for schedule(static) if (parallel)
    for (int i = 0; i < n; i++)
        gather_force(m, p, i, force);
    return 0;
}
