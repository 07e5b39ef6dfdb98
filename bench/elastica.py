#!/usr/bin/python3
"""Large-deflection cantilever under a tip load of fixed (vertical) direction: the
geometrically nonlinear reference of benchmark S5 (cases/s5_large_deflection_cantilever.ini,
003 §3.1's beam). Post-processing only.

The inextensible, shear-rigid Euler-Bernoulli beam ("elastica") clamped at s = 0, with
arc length s, slope angle theta(s) and a tip load P that stays vertical: the moment at s
is P (x(L) - x(s)), so with M = E I theta'

    E I theta'' = -P cos(theta),   theta(0) = 0,   theta'(L) = 0,
    x' = cos(theta),  y' = sin(theta),  x(0) = y(0) = 0.

With s / L, the only parameter is alpha = P L^2 / (E I); the tip deflections are
delta_v / L = y(1) and delta_h / L = 1 - x(1). Two independent solutions:

* solve_bvp (scipy) on the system above, started from the small-deflection solution
  theta = alpha (s - s^2 / 2);
* the first integral theta'^2 = 2 alpha (sin theta_0 - sin theta) (theta_0 the tip angle)
  turns the problem into quadratures (the elliptic-integral form of Bisshopp & Drucker
  1945, Q. Appl. Math. 3, 272-275):
      sqrt(2 alpha) = int_0^theta_0 dtheta / sqrt(sin theta_0 - sin theta),
      delta_v / L   = int_0^theta_0 sin theta dtheta / sqrt(2 alpha (sin theta_0 - sin theta)),
      delta_h / L   = 1 - sqrt(2 sin theta_0 / alpha)  (the cos theta integral is exact).

--check compares the two, the values Bisshopp & Drucker tabulate at alpha = 1
(delta_v / L = 0.30172, delta_h / L = 0.05643), and the small-load limits
delta_v / L -> alpha / 3 (linear theory) and delta_h / L -> alpha^2 / 15 (half the mean
square of the linear slope alpha (s - s^2 / 2)); it exits nonzero on a failure.

For information it also solves Reissner's (1972) geometrically exact beam, which adds to
the elastica the axial strain N / (E A) and the shear strain Q / (kappa G A) with the
section's axial and shear forces N = P sin(theta), Q = P cos(theta), so that the axis
moves by r' = (1 + N / (E A)) t + Q / (kappa G A) n (t, n the section's tangent and normal;
_rhs below); its linear limit is
Timoshenko's delta = P L^3 / (3 E I) + P L / (kappa G A), the form of 003 Eq. 50. A 2D
continuum (the particle solids) has the shear deformation, so its converged tip
deflection lies near Reissner's value, above the elastica by about the shear addition.

2D and thickness: the particle solids are per unit thickness, so the beam of width b
(out of plane) carries q = P / b and has I = T^3 / 12 per unit width; alpha is the same.
003's beam has b = 1 mm against T = 10 mm in the plane: thin out of plane, so plane
stress, with E itself as the bending modulus (a wide plate in plane strain would bend
with E / (1 - nu^2), 10 % stiffer at nu = 0.3).

    /usr/bin/python3 bench/elastica.py                   003 §3.1's beam: alpha = 1
    /usr/bin/python3 bench/elastica.py --length 0.0995   the same load at 0.0995 m
    /usr/bin/python3 bench/elastica.py --alpha 0.5       dimensionless only
    /usr/bin/python3 bench/elastica.py --check           the checks above
    /usr/bin/python3 bench/elastica.py --length A --quiet   prints "dv dh dv_R dh_R" [m]
                                                  (elastica, then Reissner's beam)
"""
import argparse
import math
import sys

import numpy as np
from scipy.integrate import quad, solve_bvp
from scipy.optimize import brentq

# 003 §3.1: L = 100 mm, T = 10 mm, b = 1 mm, E = 210 GPa, nu = 0.3, P = 1750 N.
LENGTH, THICKNESS, WIDTH, YOUNGS, POISSON, FORCE = 0.1, 0.01, 0.001, 210e9, 0.3, 1750.0
KAPPA = 5.0 / 6.0  # shear coefficient of a rectangle, as in 003 Eq. 50 (6/5 = 1/kappa)


def _rhs(alpha, e, g):
    """Reissner's beam in s / L: y = (theta, theta', x, y); e = P/(EA), g = P/(kGA).
    e = g = 0 is the elastica."""
    def f(s, y):
        th, dth = y[0], y[1]
        c, sn = np.cos(th), np.sin(th)
        axial = 1.0 + e * sn            # stretch of the axis, 1 + N / (E A)
        shear = g * c                   # shear strain Q / (kappa G A)
        dx = axial * c - shear * sn     # r' = (1 + eps) t + gamma n
        dy = axial * sn + shear * c
        # E I theta' = P (x(L) - x(s)) differentiated: the moment arm is horizontal.
        return np.vstack((dth, -alpha * dx, dx, dy))
    return f


def _bc(ya, yb):
    return np.array([ya[0], yb[1], ya[2], ya[3]])


def solve(alpha, e=0.0, g=0.0):
    """Tip deflections (delta_v / L, delta_h / L, theta_0) by solve_bvp; continuation in
    alpha from the small-deflection solution, so that large loads converge too."""
    s = np.linspace(0.0, 1.0, 201)
    steps = max(1, int(math.ceil(alpha / 0.5)))
    sol = None
    for k in range(1, steps + 1):
        a = alpha * k / steps
        if sol is None:
            th = a * (s - s * s / 2)
            guess = np.vstack((th, a * (1 - s), s, a * (s * s / 2 - s ** 3 / 6)))
        else:
            guess = sol.sol(s)
        sol = solve_bvp(_rhs(a, e * a / alpha if alpha else 0.0, g * a / alpha if alpha else 0.0),
                        _bc, s, guess, tol=1e-10, max_nodes=100000)
        if not sol.success:
            raise RuntimeError(f"solve_bvp did not converge at alpha = {a}: {sol.message}")
    tip = sol.sol(1.0)
    return tip[3], 1.0 - tip[2], tip[0]


def _sqrt_weighted(theta0, numerator):
    """int_0^theta0 numerator(theta) / sqrt(sin theta0 - sin theta) dtheta, with the
    inverse square-root singularity at theta0 taken by quad's algebraic weight."""
    def smooth(t):
        # sin theta0 - sin t = 2 cos((theta0 + t) / 2) sin((theta0 - t) / 2): no
        # cancellation, and d / (2 sin(d / 2)) -> 1 as d -> 0.
        d = theta0 - t
        ratio = d / (2 * math.sin(d / 2)) if d > 0 else 1.0
        return numerator(t) * math.sqrt(ratio / math.cos((theta0 + t) / 2))
    val, _ = quad(smooth, 0.0, theta0, weight="alg", wvar=(0.0, -0.5), epsabs=1e-14, epsrel=1e-12,
                  limit=200)
    return val


def solve_quadrature(alpha):
    """The same elastica by the first integral (Bisshopp & Drucker's form): the tip angle
    theta_0 < pi/2 from sqrt(2 alpha) = int dtheta / sqrt(sin theta_0 - sin theta)."""
    def length_mismatch(t0):
        return _sqrt_weighted(t0, lambda t: 1.0) - math.sqrt(2 * alpha)
    # The left end is the unloaded beam; at 1.55 rad (alpha about 60) the tip is
    # nearly vertical, beyond any load this script is used for.
    theta0 = brentq(length_mismatch, 1e-9, 1.55, xtol=1e-15, rtol=1e-14)
    dv = _sqrt_weighted(theta0, math.sin) / math.sqrt(2 * alpha)
    dh = 1.0 - math.sqrt(2 * math.sin(theta0) / alpha)
    return dv, dh, theta0


def beam_parameters(length, thickness, youngs, poisson, load_per_width):
    """alpha and Reissner's e = P/(EA), g = P/(kGA) per unit width (plane stress: E)."""
    inertia = thickness ** 3 / 12.0
    shear_modulus = youngs / (2 * (1 + poisson))
    alpha = load_per_width * length ** 2 / (youngs * inertia)
    e = load_per_width / (youngs * thickness)
    g = load_per_width / (KAPPA * shear_modulus * thickness)
    return alpha, e, g


def check():
    ok = True

    def report(name, got, want, tol):
        nonlocal ok
        good = abs(got - want) <= tol
        ok = ok and good
        print(f"{'ok  ' if good else 'FAIL'} {name}: {got:.7g} against {want:.7g} (tolerance {tol:g})")

    dv, dh, t0 = solve(1.0)
    report("alpha = 1, delta_v / L, Bisshopp & Drucker 1945", dv, 0.30172, 6e-6)
    report("alpha = 1, delta_h / L, Bisshopp & Drucker 1945", dh, 0.05643, 6e-6)
    for alpha in (0.01, 0.1, 0.5, 1.0, 2.0, 5.0, 10.0):
        b = solve(alpha)
        q = solve_quadrature(alpha)
        for name, i in (("delta_v / L", 0), ("delta_h / L", 1), ("theta_0", 2)):
            report(f"alpha = {alpha:g}, {name}, solve_bvp against the quadrature", b[i], q[i], 1e-7)
    for alpha in (1e-3, 1e-2):
        dv, dh, _ = solve(alpha)
        report(f"alpha = {alpha:g}, delta_v / (alpha L / 3)", dv / (alpha / 3), 1.0, 1e-4)
        report(f"alpha = {alpha:g}, delta_h / (alpha^2 L / 15)", dh / (alpha ** 2 / 15), 1.0, 1e-3)
    # Reissner's beam at a small load is Timoshenko's formula (003 Eq. 50).
    alpha, e, g = beam_parameters(LENGTH, THICKNESS, YOUNGS, POISSON, FORCE / WIDTH * 1e-3)
    dv, _, _ = solve(alpha, e, g)
    report("alpha = 1e-3, Reissner against Timoshenko (alpha / 3 + P / (kappa G A))",
           dv / (alpha / 3 + g), 1.0, 1e-4)
    # 003 Eq. 50's number, to show what 003 compared with.
    alpha, e, g = beam_parameters(LENGTH, THICKNESS, YOUNGS, POISSON, FORCE / WIDTH)
    report("003 Eq. 50 (linear Timoshenko) [mm]", 1e3 * LENGTH * (alpha / 3 + g), 33.59, 0.005)
    print("all checks passed" if ok else "some checks FAILED")
    return ok


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--check", action="store_true", help="run the checks and exit (nonzero on failure)")
    ap.add_argument("--alpha", type=float, help="alpha = P L^2 / (E I) (dimensionless output only)")
    ap.add_argument("--length", type=float, default=LENGTH, help="lever arm of the load [m] (0.1)")
    ap.add_argument("--thickness", type=float, default=THICKNESS, help="depth T in the plane [m] (0.01)")
    ap.add_argument("--youngs", type=float, default=YOUNGS, help="E [Pa] (210e9)")
    ap.add_argument("--poisson", type=float, default=POISSON, help="nu, for the shear modulus (0.3)")
    ap.add_argument("--load", type=float, default=FORCE / WIDTH,
                    help="tip force per unit width [N/m] (1750 N / 0.001 m = 1.75e6)")
    ap.add_argument("--quiet", action="store_true", help='print only "delta_v delta_h" [m] of the elastica and of Reissner\'s beam')
    args = ap.parse_args()
    if args.check:
        sys.exit(0 if check() else 1)
    if args.alpha is not None:
        dv, dh, t0 = solve(args.alpha)
        print(f"alpha = {args.alpha:g}: delta_v / L = {dv:.6f}, delta_h / L = {dh:.6f}, "
              f"tip angle {t0:.6f} rad (linear theory: delta_v / L = {args.alpha / 3:.6f})")
        return
    length = args.length
    alpha, e, g = beam_parameters(length, args.thickness, args.youngs, args.poisson, args.load)
    dv, dh, t0 = solve(alpha)
    rv, rh, _ = solve(alpha, e, g)
    if args.quiet:
        print(" ".join(f"{v * length:.9e}" for v in (dv, dh, rv, rh)))
        return
    lin = alpha / 3
    print(f"beam: lever arm L = {length:g} m, T = {args.thickness:g} m, E = {args.youngs:g} Pa, "
          f"nu = {args.poisson:g}, load {args.load:g} N/m (per unit width, plane stress)")
    print(f"alpha = P L^2 / (E I) = {alpha:.6f}")
    print(f"elastica: delta_v = {dv * length * 1e3:.4f} mm ({dv:.6f} L), "
          f"delta_h = {dh * length * 1e3:.4f} mm ({dh:.6f} L), tip angle {t0:.6f} rad")
    print(f"linear theory: P L^3 / (3 E I) = {lin * length * 1e3:.4f} mm "
          f"({100 * (lin / dv - 1):+.2f} % against the elastica); with Timoshenko's shear "
          f"term (003 Eq. 50): {(lin + g) * length * 1e3:.4f} mm")
    print(f"shear addition P L / (kappa G A) = {g * length * 1e3:.4f} mm = {g:.6f} L "
          f"= {100 * g / dv:.2f} % of the elastica's delta_v (information)")
    print(f"Reissner (elastica + shear + axial strain, information): delta_v = "
          f"{rv * length * 1e3:.4f} mm ({100 * (rv / dv - 1):+.2f} %), "
          f"delta_h = {rh * length * 1e3:.4f} mm ({100 * (rh / dh - 1):+.2f} %)")


if __name__ == "__main__":
    main()
