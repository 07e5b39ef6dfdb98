/* The soft repulsive contact between a fluid particle and a wall or solid particle
 * (004 Eqs. 21-24, from Zhang et al. 2018), which keeps thin, fast, pressure-free
 * layers of fluid out of walls and solids where the pressure of 000 Eq. 52 cannot:
 *
 *     a_IJ = k c0^2 zeta(r) f(eta) x_JI / r^2,   x_JI = x_I - x_J, r = |x_JI|
 *     zeta = 1 - r / dx               for 0 < r < dx, else 0        (Eq. 23)
 *     eta  = r / (0.75 h)                                            (Eq. 22)
 *     f    = 2/3                      for eta <= 2/3                 (Eq. 24)
 *            2 eta - 1.5 eta^2        for 2/3 < eta <= 1
 *            0.5 (2 - eta)^2          for 1 < eta <= 2
 *            0                        beyond
 *
 * an acceleration of fluid particle I away from J (k = 0.01 in 004). 004 samples fluid
 * and solid alike; here dx is the pair's distance at rest, the mean of the fluid's and
 * J's spacing, so that a solid sampled finer than the fluid does not push water that
 * merely rests on it. 004's text prints the third branch as 0.5 (2 - eta^2), which is
 * negative (attractive) for eta > sqrt 2 and jumps to 0 at eta = 2; 0.5 (2 - eta)^2 is
 * the continuous function of Monaghan and Kajtar's (2009) boundary force that the
 * branches come from (equal at eta = 1: 0.5 = 0.5).
 * The force is central and depends on r alone, so against a fixed wall it is
 * conservative; it vanishes at and beyond dx, so a fluid at rest on a wall (its
 * particles a spacing from the wall's) does not feel it. Below dx / 2 its magnitude is
 * held at its value there: 004 describes the force as of finite magnitude, and the
 * printed 1 / r growth has a potential that grows without bound as r -> 0, so a particle
 * driven close to a wall particle could be thrown back at any speed. Held, the energy
 * the contact can return is at most 0.0046 c0^2 per unit mass (h = 1.2 dx), a speed of
 * 0.1 c0, about the fastest flow 000 Eq. 7 sizes c0 for. */
#ifndef FSI_SOFT_CONTACT_H
#define FSI_SOFT_CONTACT_H

/* k c0^2 zeta f / (r_held r) at distance r, r_held = max(r, dx / 2) (multiply by
 * x_I - x_J for the acceleration of I): 0 for r >= dx or r <= 0.
 * k_c2 = k c0^2, inv_eta_scale = 1 / (0.75 h). */
static inline double soft_contact_factor(double r, double dx, double k_c2, double inv_eta_scale)
{
    if (!(r > 0.0 && r < dx))
        return 0.0;
    const double r_held = r > 0.5 * dx ? r : 0.5 * dx;
    const double eta = r_held * inv_eta_scale;
    double f;
    if (eta <= 2.0 / 3.0)
        f = 2.0 / 3.0;
    else if (eta <= 1.0)
        f = 2.0 * eta - 1.5 * eta * eta;
    else if (eta <= 2.0)
        f = 0.5 * (2.0 - eta) * (2.0 - eta);
    else
        f = 0.0;
    return k_c2 * (1.0 - r_held / dx) * f / (r_held * r);
}

#endif
