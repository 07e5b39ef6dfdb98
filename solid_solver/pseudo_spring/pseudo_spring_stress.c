/* One point's state over a step (pass 1 of pseudo_spring_force.c): link failure,
 * density (004 Eq. 14), the objective stress update (004 Eqs. 17-19) and R_i of the
 * artificial stress (004 Eq. 16); and, once every pair's kernel is evaluated (pass 2),
 * the point's factor D_i for the force gather (with the corrected gradient of the
 * current configuration, pass 3).
 *
 * Strain increment. 004 integrates the rates with a predictor-corrector scheme, the
 * velocity gradient l = sum_J (v_J - v_i) (x) W^_iJ V_J (Eq. 19 with W^ of Eq. 20)
 * taken from the velocities. The main loop here is velocity Verlet and gives the
 * model the positions x_{n+1} reached from x_n over dt; in Verlet
 * (x_{n+1} - x_n) / dt is exactly the half-step velocity v_{n+1/2} it moved with
 * (solid_verlet_drift), so the gradient G of du = x_{n+1} - x_n on the mid-point
 * configuration (x_n + x_{n+1}) / 2 is l dt evaluated at t_{n+1/2}: the mid-point rule
 * for the stress rate, second-order in dt like 004's predictor-corrector, and a
 * function of positions only (what solid_model.h promises; a caller that moves
 * points without setting v, as the contract tests do, gets the same stress).
 * Taking G on the mid-point configuration (not on x_{n+1}) makes a rigid rotation
 * give deps = 0 exactly (solid_objective.h), so the Jaumann update is objective to
 * round-off for any step.
 *
 * Stress. solid_objective_update rotates the stress with the mid-point spin and adds
 * the shared material's increment for deps (Hooke's law, or Drucker-Prager's return
 * mapping): sigma = S - p I with S by the Jaumann rate of Eq. 17 and the pressure
 * increment K tr(deps), i.e. p = -K ln(V / V0) = K (rho / rho0 - 1) + O(eps^2), the
 * linear equation of state of 004 §3.1 to first order in the volume strain (and
 * plane stress, plasticity and the energy bookkeeping for free).
 *
 * Density. Eq. 14 with the corrected gradient is d rho / dt = -rho tr(l); over the
 * step by the mid-point rule, rho_{n+1} = rho_n (2 - tr G) / (2 + tr G). It sets the
 * current volumes m / rho of the sums and the densities of Eqs. 8 and 16. */
#include <math.h>

#include "pseudo_spring_internal.h"
#include "solid_objective.h"

/* Largest principal value of a symmetric stress (6 components), in 2D of its in-plane
 * part (the artificial stress acts on the pair forces of the plane). */
static double largest_principal(const double s[6])
{
#if FSI_DIM == 2
    const double mean = 0.5 * (s[0] + s[1]), half = 0.5 * (s[0] - s[1]);
    return mean + sqrt(half * half + s[3] * s[3]);
#else
    /* Eigenvalues of a symmetric 3 x 3 matrix by the trigonometric form (Smith 1961). */
    const double q = (s[0] + s[1] + s[2]) / 3.0;
    const double off = s[3] * s[3] + s[4] * s[4] + s[5] * s[5];
    const double a = s[0] - q, b = s[1] - q, c = s[2] - q;
    const double p2 = (a * a + b * b + c * c + 2.0 * off) / 6.0;
    if (!(p2 > 0.0))
        return q;
    const double pp = sqrt(p2);
    /* det((S - q I) / pp) / 2 */
    const double det = a * (b * c - s[4] * s[4]) - s[3] * (s[3] * c - s[4] * s[5]) +
                       s[5] * (s[3] * s[4] - b * s[5]);
    double r = det / (2.0 * pp * pp * pp);
    r = r < -1.0 ? -1.0 : r > 1.0 ? 1.0 : r;
    return q + 2.0 * pp * cos(acos(r) / 3.0);
#endif
}

/* 004 Eq. 16: R_i = gamma |P_r,i| / rho_i^2 with |P_r| the largest principal stress
 * where it is tensile (the tensile instability is what the term is for, Monaghan
 * 2000), 0 otherwise; rho_i the new density. */
static void art_stress_factor(solid_model *m, int i, double rho)
{
    const double tension = fmax(largest_principal(m->stress + (int64_t)i * 6), 0.0);
    m->art_r[i] = m->art_stress * tension / (rho * rho);
}

int ps_update_point(solid_model *m, const solid_particles *p, const double *x_prev, int i,
                    int *broke)
{
    /* R_i stays 0 where the point carries no stress (detached, mirrored). */
    if (m->art_r)
        m->art_r[i] = 0.0;
    *broke = ps_break_links(m, p, i);
    double g[FSI_MAT_SIZE];
    const int outcome = ps_increment_gradient(m, p, x_prev, i, g);
    double *stress = m->stress + (int64_t)i * 6;
    m->flags[i] = (uint8_t)((m->flags[i] & ~(PS_POINT_REGULARISED | PS_POINT_DETACHED)) |
                            outcome);
    const double rho = m->density[i];
    if (outcome == PS_POINT_DETACHED) {
        /* Nothing left to interact with: the stress and its stored energy go. */
        for (int k = 0; k < 6; k++)
            stress[k] = 0.0;
        m->work[i] = 0.0;
        m->density_next[i] = rho;
        return PS_STEP_OK;
    }
    for (int k = 0; k < FSI_MAT_SIZE; k++)
        if (!isfinite(g[k]))
            return PS_STEP_NOT_FINITE;
    const double tr = fsi_mat_trace(g);
    const double rho_next = rho * (2.0 - tr) / (2.0 + tr);
    if (!(2.0 + tr > 0.0) || !(rho_next > 0.0) || !isfinite(rho_next))
        return PS_STEP_CRUSHED;
    m->density_next[i] = rho_next;
    /* A mirrored clamp point is an image, not material: its density (its volume in
     * the neighbours' sums) follows, it carries no stress and stores nothing. */
    if (m->flags[i] & PS_POINT_GHOST)
        return PS_STEP_OK;
    const double rho0 = p->density[i];
    solid_objective_update(&m->mat, g, rho0 / (0.5 * (rho + rho_next)), stress, &m->mstate[i],
                           &m->thickness_stretch[i], &m->work[i]);
    if (m->art_r)
        art_stress_factor(m, i, rho_next);
    return PS_STEP_OK;
}

void ps_gather_factors(solid_model *m, const solid_particles *p, int i)
{
    double *gth = m->gather + (int64_t)i * FSI_MAT_SIZE;
    double b[FSI_MAT_SIZE], sigma[FSI_MAT_SIZE];
    (void)ps_correction(m, p->x, NULL, m->density, m->link_f, i, b);
    fsi_sym6_to_mat(m->stress + (int64_t)i * 6, sigma);
    /* D = lambda_z sigma B: lambda_z (plane stress) turns the in-plane volume into
     * the volume per unit reference thickness, as in the stress work. A mirrored
     * point has no stress of its own, so D = 0. */
    fsi_mat_mul(sigma, b, gth);
    fsi_mat_scale(gth, m->thickness_stretch[i]);
}
