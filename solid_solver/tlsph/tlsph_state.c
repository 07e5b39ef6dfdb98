/* The TLSPH model's state (solid_model_save_state / solid_model_restore_state).
 *
 * TLSPH commits nothing (solid_model_stateless): its force, stress and energy are
 * functions of the positions, which the main loop saves. Saved is F of the last
 * evaluation, which the output fields (stress, jacobian) are computed from; not
 * saved, the first Piola-Kirchhoff stress of the last evaluation, which every call
 * rewrites for every point before its gather reads it. */
#include "state_store.h"
#include "tlsph_internal.h"

int solid_model_save_state(const solid_model *m, const solid_particles *p, fsi_state *st)
{
    (void)p;
    const fsi_state_field f = {"tlsph.defgrad", m->defgrad,
                                 (size_t)m->n * FSI_MAT_SIZE * sizeof(double)};
    return fsi_state_put_fields(st, &f, 1);
}

int solid_model_restore_state(solid_model *m, solid_particles *p, const fsi_state *st)
{
    (void)p;
    const fsi_state_field f = {"tlsph.defgrad", m->defgrad,
                                 (size_t)m->n * FSI_MAT_SIZE * sizeof(double)};
    return fsi_state_get_fields(st, &f, 1);
}
