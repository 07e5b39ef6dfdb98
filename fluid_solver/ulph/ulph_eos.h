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
#ifndef ULPH_EOS_H
#define ULPH_EOS_H

#include <math.h>

typedef struct {
    double rho0, c0, gamma;
} ulph_eos;

static inline double ulph_eos_pressure(const ulph_eos *e, double rho)
{
    return e->rho0 * e->c0 * e->c0 / e->gamma * (pow(rho / e->rho0, e->gamma) - 1.0);
}

static inline double ulph_eos_density(const ulph_eos *e, double p)
{
    double base = 1.0 + e->gamma * p / (e->rho0 * e->c0 * e->c0);
    return e->rho0 * pow(base > 1e-6 ? base : 1e-6, 1.0 / e->gamma);
}

#endif
