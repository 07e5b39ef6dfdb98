/* The Tait equation of state (000 Eq. 6) and its inverse (the density of a given
 * pressure, 000 Eq. 53 for wall particles):
 *
 *     p = rho0 c0^2 / gamma ((rho / rho0)^gamma - 1)
 *     rho = rho0 (1 + gamma p / (rho0 c0^2))^(1 / gamma)
 *
 * 000 Eq. 53 prints the linearised inverse rho = p / c0^2 + rho0; the exact inverse is
 * used here so that a wall particle and a fluid particle at the same pressure have the
 * same density (the two agree to O((p / (rho0 c0^2))^2), 2.5e-5 at 0.5 % compression).
 * The inverse is clamped at a tension of -rho0 c0^2 / gamma, where the density would
 * reach zero. */
#ifndef FSI_TAIT_EOS_H
#define FSI_TAIT_EOS_H

#include <math.h>

#include "fluid_particles.h"

typedef struct {
    double rho0, c0, gamma;
} tait_eos;

/* r^gamma; gamma = 7 (000 Eq. 6, the default) by multiplications: pow() of every
 * particle at every evaluation cost as much as the walls. Equal to pow to round-off. */
static inline double tait_eos_power(double r, double gamma)
{
    if (gamma == 7.0) {
        const double r2 = r * r, r4 = r2 * r2;
        return r4 * r2 * r;
    }
    return pow(r, gamma);
}

static inline double tait_eos_pressure(const tait_eos *e, double rho)
{
    return e->rho0 * e->c0 * e->c0 / e->gamma * (tait_eos_power(rho / e->rho0, e->gamma) - 1.0);
}

static inline double tait_eos_density(const tait_eos *e, double p)
{
    if (p == 0.0)
        return e->rho0; /* exactly what the formula gives; every wall away from water */
    double base = 1.0 + e->gamma * p / (e->rho0 * e->c0 * e->c0);
    return e->rho0 * pow(base > 1e-6 ? base : 1e-6, 1.0 / e->gamma);
}

/* The energy stored per unit mass by compressing the fluid from rho0 to rho [J/kg]: the
 * work of the pressure, e = int_rho0^rho p / rho'^2 drho' (de = -p dv, v = 1 / rho),
 * which for the equation above is, with r = rho / rho0 and B = rho0 c0^2 / gamma,
 *
 *     e = B / rho0 ((r^(gamma - 1) - 1) / (gamma - 1) + 1 / r - 1)
 *
 * (c0^2 (r - 1)^2 / 2 for small r - 1; its limit ln r for the first term at gamma = 1,
 * the smallest exponent the keys allow). r < 1 gives e > 0 too: a fluid in tension
 * stores energy as well. */
static inline double tait_eos_energy(const tait_eos *e, double rho)
{
    const double r = rho / e->rho0, b = e->c0 * e->c0 / e->gamma;
    const double first = e->gamma == 1.0 ? log(r)
                                         : (tait_eos_power(r, e->gamma) / r - 1.0) /
                                               (e->gamma - 1.0);
    return b * (first + 1.0 / r - 1.0);
}

/* Every fluid particle's pressure (the equation above) and volume V = m / rho from its
 * density; without tension a density below rho0 is first raised to rho0 (p >= 0: a
 * stretched front keeps its stiffness instead of a density deficit that no pressure
 * restores and that lets it sink into a wall, docs/ulph.md "Tension"). The schemes'
 * step 1 of every evaluation of the rates. */
void tait_eos_update_fluid(const tait_eos *e, fluid_particles *p, int tension);

#endif
