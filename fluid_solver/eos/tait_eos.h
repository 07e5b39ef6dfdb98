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

/* Every fluid particle's pressure (the equation above) and volume V = m / rho from its
 * density; without tension a density below rho0 is first raised to rho0 (p >= 0: a
 * stretched front keeps its stiffness instead of a density deficit that no pressure
 * restores and that lets it sink into a wall, docs/ulph.md "Tension"). The schemes'
 * step 1 of every evaluation of the rates. */
void tait_eos_update_fluid(const tait_eos *e, fluid_particles *p, int tension);

#endif
