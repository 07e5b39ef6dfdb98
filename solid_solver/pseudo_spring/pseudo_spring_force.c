/* Internal force of the pseudo-spring SPH solid (004 §3), four passes over the
 * links, each parallel over points with no shared writes (so the result does not
 * depend on the number of threads, bit for bit):
 *   1. per point (pseudo_spring_stress.c): link failure, the increment gradient G
 *      on the mid-point configuration, density (Eq. 14), stress (Eqs. 17-19),
 *      R_i = gamma |P_r,i| / rho_i^2 (Eq. 16);
 *   2. per pair, once every link, density and R is final (pseudo_spring_pairs.c):
 *      the kernel F(r) and the artificial stress P^a = (R_i + R_J) (W(r) / W(dx))^n
 *      (Eq. 16) of the current configuration, evaluated once and stored at both
 *      slots of the pair (point i writes its pairs with j > i);
 *   3. per point: B_i of the current configuration (Eq. 20, with pass 2's F),
 *      D_i = lambda_z sigma_i B_i, and the hourglass fit;
 *   4. per point, the gather of the momentum equation (Eq. 15) over its intact
 *      links (f_ij = 1), with x_ij = x_i - x_j, grad_i W_ij = F(r) x_ij, V = m / rho:
 *        f_i = sum_J [ V_i V_J (D_i + D_J) grad_i W_iJ
 *                      - m_i m_J (Pi_iJ + P^a_iJ) grad_i W_iJ ]
 *      Pi the artificial viscosity (Eqs. 8-9, on the mid-point configuration with
 *      the increment velocity du / dt), F and P^a from pass 2 (the pair's, so each
 *      end uses the same bits it would have computed itself).
 *
 * The stress term is 004 Eq. 15's sigma_i / rho_i^2 + sigma_J / rho_J^2 with
 * m_i m_J / rho^2 read as V_i V_J and each stress taking its own point's corrected
 * gradient (B_i for sigma_i, B_J for sigma_J). That is the force whose power is
 * minus the stress power sum_i V_i sigma_i : l_i of Eq. 19's velocity gradient (so
 * the energy check closes), it is antisymmetric pair by pair (linear momentum), and
 * since sum_J V_J x_Ji (x) grad W_iJ = A_i and D_i A_i = lambda_z sigma_i is
 * symmetric, it has no net moment (angular momentum; Bonet & Lok 1999), except at
 * points whose B is regularised. The viscosity and the artificial stress are
 * stabilisation terms: they act along x_ij with the plain kernel gradient, central
 * pair forces that conserve both momenta everywhere. */
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "pseudo_spring_internal.h"

static void gather_force(const solid_model *m, const solid_particles *p, const double *x_prev,
                         double dt, int i, double *force)
{
    const solid_bonds *l = &m->links;
    const double *restrict x = p->x;
    const double *di = m->gather + (int64_t)i * FSI_MAT_SIZE;
    const double h = m->kernel.h, c = m->sound_speed;
    const double inv_dt = dt > 0.0 ? 1.0 / dt : 0.0;
    const double vi = m->mass[i] / m->density[i];
    double f[FSI_DIM] = {0};
    for (int64_t q = l->offset[i]; q < l->offset[i + 1]; q++) {
        if (!l->intact[q])
            continue;
        const int j = l->neighbour[q];
        const double *dj = m->gather + (int64_t)j * FSI_MAT_SIZE;
        double r[FSI_DIM], rm2 = 0.0, vr = 0.0;
        for (int d = 0; d < FSI_DIM; d++) {
            const int64_t ki = (int64_t)i * FSI_DIM + d, kj = (int64_t)j * FSI_DIM + d;
            r[d] = x[ki] - x[kj];
            const double rm = 0.5 * (r[d] + x_prev[ki] - x_prev[kj]);
            rm2 += rm * rm;
            vr += (x[ki] - x_prev[ki] - x[kj] + x_prev[kj]) * inv_dt * rm;
        }
        const double fr = m->link_f[q];
        /* Eqs. 8-9: only between approaching points. */
        double pi = 0.0;
        if (vr < 0.0) {
            const double mu = h * vr / (rm2 + 0.01 * h * h);
            pi = (-m->visc_alpha * c * mu + m->visc_beta * mu * mu) /
                 (0.5 * (m->density[i] + m->density[j]));
        }
        /* Eq. 16, 0 where off (gamma = 0: no pow at all) or where neither end is in
         * tension. */
        const double pa = m->link_art ? m->link_art[q] : 0.0;
        const double vv = vi * m->mass[j] / m->density[j];
        const double central = m->mass[i] * m->mass[j] * (pi + pa);
        for (int a = 0; a < FSI_DIM; a++) {
            double t = 0.0;
            for (int b = 0; b < FSI_DIM; b++)
                t += (di[a * FSI_DIM + b] + dj[a * FSI_DIM + b]) * r[b];
            f[a] += fr * (vv * t - central * r[a]);
        }
    }
    ps_hourglass_force(m, p, i, f);
    for (int d = 0; d < FSI_DIM; d++)
        force[(int64_t)i * FSI_DIM + d] = f[d];
}

int solid_model_internal_force(solid_model *m, const solid_particles *p, const double *x_prev,
                               double dt, double t, double *force, char *msg, size_t msg_size)
{
    const int n = m->n;
    /* The first failing point and its outcome in one reduction: 4 i + outcome. */
    int64_t first_bad = INT64_MAX;
    int64_t broken = 0;
    const int parallel = m->links.n_bonds >= PS_PARALLEL_MIN_LINKS;
#pragma omp parallel for schedule(static) if (parallel) reduction(min : first_bad) \
    reduction(+ : broken)
    for (int i = 0; i < n; i++) {
        int broke = 0;
        const int outcome = ps_update_point(m, p, x_prev, i, &broke);
        broken += broke;
        if (outcome != PS_STEP_OK && 4 * (int64_t)i + outcome < first_bad)
            first_bad = 4 * (int64_t)i + outcome;
    }
    m->n_broken += broken;
    if (first_bad != INT64_MAX) {
        char at[256];
        solid_describe_point(p, (int)(first_bad / 4), at, sizeof at);
        if (first_bad % 4 == PS_STEP_NOT_FINITE)
            snprintf(msg, msg_size, "pseudo_spring: the velocity gradient of %s is not finite "
                     "at t = %.9g s (positions not finite?)", at, t);
        else
            snprintf(msg, msg_size, "pseudo_spring: the density of %s would not stay positive "
                     "at t = %.9g s (volume strain below -2 in one step): the body is crushed "
                     "or the step is unstable", at, t);
        return -1;
    }
    double *swap = m->density;
    m->density = m->density_next;
    m->density_next = swap;

#pragma omp parallel for schedule(static) if (parallel)
    for (int i = 0; i < n; i++)
        ps_pair_quantities(m, p, i);

    int warn = 0;
#pragma omp parallel for schedule(static) if (parallel) reduction(+ : warn)
    for (int i = 0; i < n; i++) {
        ps_gather_factors(m, p, i);
        ps_hourglass_factors(m, p, i);
        warn += (m->flags[i] & (PS_POINT_REGULARISED | PS_POINT_DETACHED)) &&
                !(m->flags[i] & PS_POINT_WARNED);
    }
    if (warn)
        for (int i = 0; i < n; i++)
            if ((m->flags[i] & (PS_POINT_REGULARISED | PS_POINT_DETACHED)) &&
                !(m->flags[i] & PS_POINT_WARNED))
                ps_warn_point(m, p, i,
                              (m->flags[i] & PS_POINT_DETACHED)
                                  ? "all its links are broken: it interacts with nothing "
                                    "from now on"
                                  : "its remaining links nearly lie on a line: its corrected "
                                    "gradient is regularised",
                              t);

#pragma omp parallel for schedule(static) if (parallel)
    for (int i = 0; i < n; i++)
        gather_force(m, p, x_prev, dt, i, force);
    return 0;
}
