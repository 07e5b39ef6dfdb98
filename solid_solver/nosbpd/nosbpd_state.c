/* The NOSB-PD model's state (solid_model_save_state / solid_model_restore_state).
 *
 * Saved, as committed by the internal-force calls: which bonds are intact (failure
 * is permanent), the Cauchy stress and the material state (Drucker-Prager's plastic
 * strain), the stress work, the thickness stretch, F and the fit C of the last call
 * (output and the stabilisation's energy), the point flags (no force state, linear
 * fit, warned) and the counts of broken bonds, points without force state and
 * warnings. Derived from the intact bonds and recomputed on restore, for the points
 * whose bonds differ from the model's: K^-1, the fit's A^-1, the intact count and
 * the damage (nosbpd_shape_tensor, the same function every bond failure calls, so
 * the same bits). Not saved: the gather factors D, rewritten for every point by every
 * call before they are read. */
#include <string.h>

#include "nosbpd_internal.h"
#include "state_store.h"

enum { N_FIELDS = 11 };

static int state_fields(const solid_model *m, fsi_state_field *f)
{
    const size_t n = (size_t)m->n, d = sizeof(double);
    int k = 0;
    f[k++] = (fsi_state_field){"nosbpd.intact", m->bonds.intact, (size_t)m->bonds.n_bonds};
    f[k++] = (fsi_state_field){"nosbpd.stress", m->stress, n * 6 * d};
    f[k++] = (fsi_state_field){"nosbpd.material_state", m->mstate,
                                 n * sizeof *m->mstate};
    f[k++] = (fsi_state_field){"nosbpd.work", m->work, n * d};
    f[k++] = (fsi_state_field){"nosbpd.thickness_stretch", m->thickness_stretch, n * d};
    f[k++] = (fsi_state_field){"nosbpd.defgrad", m->defgrad, n * FSI_MAT_SIZE * d};
    f[k++] = (fsi_state_field){"nosbpd.fit", m->fit, n * FSI_DIM * (size_t)m->n_basis * d};
    f[k++] = (fsi_state_field){"nosbpd.flags", m->flags, n};
    f[k++] = (fsi_state_field){"nosbpd.broken", (void *)&m->n_broken, sizeof m->n_broken};
    f[k++] = (fsi_state_field){"nosbpd.without_force_state", (void *)&m->n_without_force_state,
                                 sizeof m->n_without_force_state};
    f[k++] = (fsi_state_field){"nosbpd.warnings", (void *)&m->n_warnings,
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
    fsi_state_field f[N_FIELDS];
    const int count = state_fields(m, f);
    if (!fsi_state_fields_match(st, f, count))
        return -1;
    /* The points whose bonds differ from the saved ones (iscratch: 1). */
    const uint8_t *intact = fsi_state_data(st, "nosbpd.intact", NULL);
    const int64_t *offset = m->bonds.offset;
    int changed = 0;
    for (int i = 0; i < m->n; i++) {
        const size_t len = (size_t)(offset[i + 1] - offset[i]);
        m->iscratch[i] = len > 0 && memcmp(intact + offset[i], m->bonds.intact + offset[i], len) != 0;
        changed += m->iscratch[i];
    }
    if (fsi_state_get_fields(st, f, count) != 0)
        return -1;
    /* The restored flags already hold what these calls set (NOSBPD_POINT_LINEAR_FIT). */
    for (int i = 0; changed > 0 && i < m->n; i++)
        if (m->iscratch[i])
            (void)nosbpd_shape_tensor(m, p, i);
    return 0;
}
