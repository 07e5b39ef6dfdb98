/* The pseudo-springs (004 §3.3): link failure, link counts and damage, warnings.
 *
 * The links are the immediate lattice neighbours (004 §3.2: the points joined to i
 * by a straight line that meets no other point; on a regular lattice those within
 * sqrt(FSI_DIM) dx: 8 inside, 5 on an edge, 3 at a corner in 2D, 26 inside in 3D),
 * built once by solid_bonds_build in the reference configuration and never added
 * to. Each carries f_ij in {1, 0} (solid_bonds' intact byte), which multiplies every
 * kernel term of the pair. 004 does not say what strain breaks a link; we take the
 * tensile engineering strain of the link, eps_ij = |x_ij| / |X_ij| - 1 (004 §5.5's
 * "strain in the connecting pseudo-spring"), so that compression never breaks one. */
#include <stdio.h>

#include "pseudo_spring_internal.h"

int ps_break_links(solid_model *m, const solid_particles *p, int i)
{
    /* A point of a no_failure region keeps all its links; others keep those to one. */
    if (!m->failure || (p->flags[i] & SOLID_UNBREAKABLE))
        return 0;
    solid_bonds *b = &m->links;
    const double crit2 = (1.0 + m->failure_strain) * (1.0 + m->failure_strain);
    const double *xi_pos = p->x + (int64_t)i * FSI_DIM;
    int broke = 0;
    for (int64_t q = b->offset[i]; q < b->offset[i + 1]; q++) {
        const int j = b->neighbour[q];
        if (!b->intact[q] || (p->flags[j] & SOLID_UNBREAKABLE))
            continue;
        /* |x_ij| > (1 + eps_f) |X_ij| without a square root. Both ends compute the
         * same numbers (the differences only change sign), so a pair breaks in both
         * rows in the same call. */
        double r2 = 0.0;
        for (int d = 0; d < FSI_DIM; d++) {
            const double e = p->x[(int64_t)j * FSI_DIM + d] - xi_pos[d];
            r2 += e * e;
        }
        if (r2 > crit2 * b->length[q] * b->length[q]) {
            b->intact[q] = 0;
            broke++;
        }
    }
    if (broke)
        ps_count_links(m, i);
    return broke;
}

void ps_count_links(solid_model *m, int i)
{
    const solid_bonds *b = &m->links;
    int intact = 0;
    for (int64_t q = b->offset[i]; q < b->offset[i + 1]; q++)
        intact += b->intact[q];
    m->intact_count[i] = intact;
    const int initial = m->initial_count[i];
    /* 004 §3.3: D_i = failed links / initial links. */
    m->damage[i] = initial > 0 ? (double)(initial - intact) / initial : 0.0;
}

void ps_warn_point(solid_model *m, const solid_particles *p, int i, const char *what, double t)
{
    if (m->flags[i] & PS_POINT_WARNED)
        return;
    m->flags[i] |= PS_POINT_WARNED;
    m->n_warnings++;
    if (m->n_warnings > PS_MAX_WARNINGS)
        return;
    char at[256];
    solid_describe_point(p, i, at, sizeof at);
    fprintf(stderr, "pseudo_spring: warning: %s, t = %.9g s: %s (%d of %d links intact)%s\n",
            at, t, what, m->intact_count[i], m->initial_count[i],
            m->n_warnings == PS_MAX_WARNINGS ? "; further warnings of this kind are only "
                                               "counted" : "");
}
