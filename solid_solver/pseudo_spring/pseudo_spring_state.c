/* The pseudo-spring SPH model's state (solid_model_save_state /
 * solid_model_restore_state).
 *
 * Saved, as committed by the internal-force calls: which links are intact (failure
 * is permanent), the current density (004 Eq. 14, integrated), the Cauchy stress and
 * the material state (Drucker-Prager's plastic strain), the stress work, the thickness
 * stretch, the point flags (regularised, detached, warned) and the counts of broken
 * links and warnings. Derived from the intact links and recomputed on restore: the
 * intact counts and the damage (ps_count_links). Not saved, because every call
 * rewrites them for every point or pair before reading them: the next density, the
 * pairs' kernel values and artificial stress, R_i, the gather factors and the
 * hourglass fits. */
#include "pseudo_spring_internal.h"
#include "state_store.h"

enum { N_FIELDS = 9 };

static int state_fields(const solid_model *m, fsi_state_field *f)
{
    const size_t n = (size_t)m->n, d = sizeof(double);
    int k = 0;
    f[k++] = (fsi_state_field){"pseudo_spring.intact", m->links.intact,
                                 (size_t)m->links.n_bonds};
    f[k++] = (fsi_state_field){"pseudo_spring.density", m->density, n * d};
    f[k++] = (fsi_state_field){"pseudo_spring.stress", m->stress, n * 6 * d};
    f[k++] = (fsi_state_field){"pseudo_spring.material_state", m->mstate,
                                 n * sizeof *m->mstate};
    f[k++] = (fsi_state_field){"pseudo_spring.work", m->work, n * d};
    f[k++] = (fsi_state_field){"pseudo_spring.thickness_stretch", m->thickness_stretch,
                                 n * d};
    f[k++] = (fsi_state_field){"pseudo_spring.flags", m->flags, n};
    f[k++] = (fsi_state_field){"pseudo_spring.broken", (void *)&m->n_broken,
                                 sizeof m->n_broken};
    f[k++] = (fsi_state_field){"pseudo_spring.warnings", (void *)&m->n_warnings,
                                 sizeof m->n_warnings};
    return k;
}

int solid_model_save_state(const solid_model *m, const solid_particles *p, fsi_state *st)
{
    (void)p;
    fsi_state_field f[N_FIELDS];
    return fsi_state_put_fields(st, f, state_fields(m, f));
}

int solid_model_restore_state(solid_model *m, solid_particles *p, const fsi_state *st)
{
    (void)p;
    fsi_state_field f[N_FIELDS];
    if (fsi_state_get_fields(st, f, state_fields(m, f)) != 0)
        return -1;
    for (int i = 0; i < m->n; i++)
        ps_count_links(m, i);
    return 0;
}
