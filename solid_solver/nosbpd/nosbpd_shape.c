/* Shape tensor K of a family (000 Eq. 34), its inverse, the moment matrix of the
 * quadratic fit (gradient_order = 2) and the damage of the point (000 Eq. 49),
 * recomputed whenever one of the point's bonds breaks. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "nosbpd_internal.h"

/* A^-1 of the quadratic fit of point i, or K^-1 padded with zeros (and the flag
 * NOSBPD_POINT_LINEAR_FIT) when the family cannot carry one or has a broken bond. */
static void quadratic_fit_inverse(solid_model *m, int i, const double *k_inv, double *a_inv)
{
    const nosbpd_bonds *b = &m->bonds;
    const int nb = m->n_basis;
    const double inv_delta = 1.0 / m->delta;
    double a[NOSBPD_MAX_BASIS * NOSBPD_MAX_BASIS] = {0};
    int count = 0;
    for (int64_t q = b->offset[i]; q < b->offset[i + 1]; q++) {
        if (!b->intact[q])
            continue;
        double v[NOSBPD_MAX_BASIS];
        solid_fit_basis(b->xi + q * FSI_DIM, inv_delta, nb, v);
        for (int r = 0; r < nb; r++)
            for (int c = 0; c <= r; c++)
                a[r * nb + c] += b->weight[q] * v[r] * v[c];
        count++;
    }
    for (int r = 0; r < nb; r++)
        for (int c = r + 1; c < nb; c++)
            a[r * nb + c] = a[c * nb + r];
    /* A family cut by a crack is one-sided across it: a quadratic fit there
     * extrapolates the crack faces' motion and amplifies it (the notched plate goes
     * unstable once the crack branches). Damaged points keep the linear fit. */
    const int damaged = count < b->offset[i + 1] - b->offset[i];
    if (!damaged && count >= nb &&
        solid_fit_inverse(a, nb, a_inv, NOSBPD_MAX_CONDITION_FIT) == 0) {
        m->flags[i] &= (uint8_t)~NOSBPD_POINT_LINEAR_FIT;
        return;
    }
    m->flags[i] |= NOSBPD_POINT_LINEAR_FIT;
    memset(a_inv, 0, sizeof(double) * (size_t)(nb * nb));
    for (int r = 0; r < FSI_DIM; r++)
        for (int c = 0; c < FSI_DIM; c++)
            a_inv[r * nb + c] = FSI_MAT(k_inv, r, c);
}

int nosbpd_shape_tensor(solid_model *m, const solid_particles *p, int i)
{
    const nosbpd_bonds *b = &m->bonds;
    double k[FSI_MAT_SIZE];
    fsi_mat_zero(k);
    double intact_volume = 0.0;
    int count = 0;
    for (int64_t q = b->offset[i]; q < b->offset[i + 1]; q++) {
        if (!b->intact[q])
            continue;
        const double *xi = b->xi + q * FSI_DIM;
        fsi_mat_add_outer(k, b->weight[q], xi, xi);
        intact_volume += p->volume[b->neighbour[q]];
        count++;
    }
    /* Exactly symmetric (the sums of w xi_a xi_b and w xi_b xi_a round differently);
     * the adjugate inverse of a symmetric matrix is then exactly symmetric too. */
    for (int r = 0; r < FSI_DIM; r++)
        for (int c = r + 1; c < FSI_DIM; c++)
            FSI_MAT(k, r, c) = FSI_MAT(k, c, r) = 0.5 * (FSI_MAT(k, r, c) + FSI_MAT(k, c, r));
    m->intact_count[i] = count;
    const double family = m->family_volume[i];
    m->damage[i] = family > 0.0 ? 1.0 - intact_volume / family : 0.0;
    if (m->damage[i] < 0.0)
        m->damage[i] = 0.0; /* round-off when nothing is broken */
    double *k_inv = m->k_inv + (int64_t)i * FSI_MAT_SIZE;
    const int nb = m->n_basis;
    double *a_inv = m->moment_inv + (int64_t)i * nb * nb;
    if (count < FSI_DIM + 1 || fsi_mat_inverse(k, k_inv, NOSBPD_MAX_CONDITION_K) != 0) {
        fsi_mat_zero(k_inv);
        memset(a_inv, 0, sizeof(double) * (size_t)(nb * nb));
        return -1;
    }
    if (nb == FSI_DIM)
        fsi_mat_copy(k_inv, a_inv);
    else
        quadratic_fit_inverse(m, i, k_inv, a_inv);
    return 0;
}

void nosbpd_warn_point(solid_model *m, const solid_particles *p, int i, const char *what,
                       double t)
{
    if (m->flags[i] & NOSBPD_POINT_WARNED)
        return;
    m->flags[i] |= NOSBPD_POINT_WARNED;
    m->n_warnings++;
    if (m->n_warnings > NOSBPD_MAX_WARNINGS)
        return;
    char at[128];
    int len = snprintf(at, sizeof at, "(");
    for (int d = 0; d < FSI_DIM && len > 0 && (size_t)len < sizeof at; d++)
        len += snprintf(at + len, sizeof at - (size_t)len, "%s%.6g", d ? ", " : "",
                        p->x0[(int64_t)i * FSI_DIM + d]);
    if (len > 0 && (size_t)len < sizeof at)
        snprintf(at + len, sizeof at - (size_t)len, ")");
    fprintf(stderr, "nosbpd: warning: point id %d at reference position %s, t = %.9g s: %s "
            "(%d intact bonds)%s\n", p->id ? p->id[i] : i, at, t, what, m->intact_count[i],
            m->n_warnings == NOSBPD_MAX_WARNINGS ? "; further warnings of this kind are only "
            "counted" : "");
}
