/* Perfectly plastic Drucker-Prager model with non-associated flow: elastic
 * predictor, then a closed-form return to the smooth part of the cone or to its
 * apex (de Souza Neto, Peric & Owen 2008, Sec. 8.3; Simo & Hughes 1998, Ch. 3 for
 * the predictor/corrector frame). Tension positive.
 *
 *   yield     f = alpha I1 + sqrt(J2) - k          (alpha, k, beta: material_derive)
 *   potential g = beta  I1 + sqrt(J2)
 *   flow      deps_p = dlambda dg/dsigma = dlambda (beta I + s / (2 sqrt(J2)))
 *
 * Linear isotropic elasticity makes the return along D : dg/dsigma change p and
 * sqrt(J2) independently, so the backward-Euler (closest-point for beta = alpha)
 * return is one scalar equation with an explicit root; no iteration, and the
 * result is on f = 0 to round-off. The derivation is in docs/materials.md. The
 * increment deps is the rotation-free strain increment of 000 Eq. 41; this file
 * generalises 000 Eq. 43 (dsigma = D : deps) to dsigma = D : (deps - deps_p). */
#include <math.h>

#include "material_models.h"

/* f_trial below this fraction of the stress scale counts as on the surface, not
 * beyond it: a point that already sits on the cone and takes a purely tangential
 * (or zero) increment must not be reported as yielding because of the last bit. */
#define DP_YIELD_TOL 1e-13

static void record(material_state *st, const double dp[6])
{
    if (!st)
        return;
    double n2 = 0.0;
    for (int i = 0; i < 3; i++) {
        st->plastic_strain[i] += dp[i];
        n2 += dp[i] * dp[i];
    }
    for (int i = 3; i < 6; i++) {
        st->plastic_strain[i] += dp[i];
        n2 += 2.0 * dp[i] * dp[i];     /* tensor shear: xy and yx both count */
    }
    st->equivalent_plastic_strain += sqrt(2.0 / 3.0 * n2);
    st->yielding = 1;
}

void material_drucker_prager_update(const material *m, double deps[6], double stress[6],
                                    material_state *st)
{
    /* Plane stress is rejected by material_from_case: the deps_zz that keeps
     * sigma_zz = 0 would depend on the plastic flow (a local iteration); deps is
     * used as given, i.e. plane strain with deps[2] = 0 from the kinematics. */
    const double K = m->bulk_modulus, G = m->shear_modulus;
    const double alpha = m->dp_alpha, beta = m->dp_beta, k = m->dp_k;

    /* Elastic predictor: the trial stress of 000 Eq. 43. */
    double trial[6];
    material_hooke(m, deps, trial);
    for (int i = 0; i < 6; i++)
        trial[i] += stress[i];

    double p_tr = (trial[0] + trial[1] + trial[2]) / 3.0;
    double s_tr[6];
    for (int i = 0; i < 6; i++)
        s_tr[i] = trial[i] - (i < 3 ? p_tr : 0.0);
    double q_tr = sqrt(material_j2(trial));      /* sqrt(J2) of the trial state */
    double f_tr = 3.0 * alpha * p_tr + q_tr - k;
    double scale = k + 3.0 * alpha * fabs(p_tr) + q_tr;

    if (!(f_tr > DP_YIELD_TOL * scale)) {
        for (int i = 0; i < 6; i++)
            stress[i] = trial[i];
        if (st)
            st->yielding = 0;
        return;
    }

    /* Return to the smooth cone. With dsigma_p = -dlambda D : dg/dsigma =
     * -dlambda (3 K beta I + G s / sqrt(J2)), the new state has the trial deviator's
     * direction and p = p_tr - 3 K beta dlambda, sqrt(J2) = q_tr - G dlambda, so
     * f = f_tr - dlambda (G + 9 K alpha beta) = 0 gives dlambda in closed form. The
     * cone return is valid only if the new sqrt(J2) is not negative; otherwise the
     * return would overshoot the apex. */
    double dp[6];
    double dl = f_tr / (G + 9.0 * K * alpha * beta);
    double q_new = q_tr - G * dl;
    if (q_tr > 0.0 && q_new >= 0.0) {
        double p_new = p_tr - 3.0 * K * beta * dl;
        double ratio = q_new / q_tr;
        for (int i = 0; i < 6; i++) {
            stress[i] = ratio * s_tr[i] + (i < 3 ? p_new : 0.0);
            dp[i] = dl * (0.5 * s_tr[i] / q_tr + (i < 3 ? beta : 0.0));
        }
    } else {
        /* Apex return: sigma = p_apex I with f(p_apex) = 0, p_apex = k / (3 alpha).
         * alpha > 0 here, since with alpha = 0 the cone return always gives
         * q_new = k >= 0. The apex is a corner of the cone: dg/dsigma is not unique
         * there, and for a perfectly plastic material the stress is fixed, so the
         * plastic strain is whatever the elastic part cannot take,
         * deps_p = D^-1 : (trial - sigma_apex) = s_tr / (2 G) + (p_tr - p_apex) / (3 K) I
         * (de Souza Neto et al. 2008, Sec. 8.3, return to the apex with H = 0). This
         * keeps deps = D^-1 dsigma + deps_p exactly and is the tension cut-off a
         * cohesive soil reaches when pulled apart. */
        double p_apex = k / (3.0 * alpha);
        for (int i = 0; i < 6; i++) {
            stress[i] = i < 3 ? p_apex : 0.0;
            dp[i] = 0.5 * s_tr[i] / G + (i < 3 ? (p_tr - p_apex) / (3.0 * K) : 0.0);
        }
    }
    record(st, dp);
}
