/* Isotropic linear elasticity in the incremental objective update: the stress
 * increment from the rotation-free strain increment, 000 Eq. 43, with Hooke's D
 * (the caller does the rotation, 000 Eqs. 44-46). Tensors are 6-component,
 * order xx, yy, zz, xy, yz, zx, TENSOR shear components (material.h), so
 * D : deps = lambda tr(deps) I + 2 mu deps holds component-wise with no factor 2
 * on the shear terms. */
#include "dim.h"
#include "material_models.h"

void material_hooke(const material *m, const double deps[6], double dsigma[6])
{
    double lam = m->lame_lambda, two_mu = 2.0 * m->shear_modulus;
    double lt = lam * (deps[0] + deps[1] + deps[2]);
    for (int i = 0; i < 3; i++)
        dsigma[i] = lt + two_mu * deps[i];
    for (int i = 3; i < 6; i++)
        dsigma[i] = two_mu * deps[i];
}

/* D^-1 split into volume and shape: deps = tr(dsigma) / (9 K) I + dev(dsigma) / (2 mu).
 * (The E/nu form would lose the exact split the plastic tests compare against.) */
void material_compliance(const material *m, const double dsigma[6], double deps[6])
{
    double p = (dsigma[0] + dsigma[1] + dsigma[2]) / 3.0;
    double vol = p / (3.0 * m->bulk_modulus), inv_2mu = 0.5 / m->shear_modulus;
    for (int i = 0; i < 3; i++)
        deps[i] = vol + (dsigma[i] - p) * inv_2mu;
    for (int i = 3; i < 6; i++)
        deps[i] = dsigma[i] * inv_2mu;
}

void material_linear_elastic_update(const material *m, double deps[6], double stress[6],
                                    material_state *st)
{
#if FSI_DIM == 2
    if (m->plane == MATERIAL_PLANE_STRESS) {
        /* Thin plate: sigma_zz = 0 after the step. From sigma_zz + lambda (deps_xx +
         * deps_yy + deps_zz) + 2 mu deps_zz = 0 the thickness strain is
         * deps_zz = -(sigma_zz + lambda (deps_xx + deps_yy)) / (lambda + 2 mu); with
         * sigma_zz = 0 on entry this is the textbook -nu/(1-nu) (deps_xx + deps_yy),
         * and any round-off left in sigma_zz is taken out instead of carried along.
         * The in-plane result is then sigma_xx += E/(1-nu^2) (deps_xx + nu deps_yy). */
        double lam = m->lame_lambda, two_mu = 2.0 * m->shear_modulus;
        deps[2] = -(stress[2] + lam * (deps[0] + deps[1])) / (lam + two_mu);
    }
#endif
    double ds[6];
    material_hooke(m, deps, ds);
    for (int i = 0; i < 6; i++)
        stress[i] += ds[i];
#if FSI_DIM == 2
    if (m->plane == MATERIAL_PLANE_STRESS)
        stress[2] = 0.0;        /* exactly, not up to the round-off of the sum above */
#endif
    if (st)
        st->yielding = 0;
}
