#!/usr/bin/python3
"""Plots the spring-dashpot demo against its closed-form solution.

Each solid particle i with the dashpot fluid is a damped oscillator
    m u'' + c u' + (k_i + k_f) u = 0,  u(0) = u0,  u'(0) = 0,
so the probe p0_uy and the last frame's displacements have exact values. Writes
OUT/demo.png and prints the error measures.

usage: plot_demo.py OUT_DIR
"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import fsi_results  # noqa: E402

import matplotlib  # noqa: E402
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def damped_oscillator(t, u0, m, k, c):
    """Free response of m u'' + c u' + k u = 0 from rest at u0 (underdamped)."""
    w0 = math.sqrt(k / m)
    zeta = c / (2.0 * math.sqrt(k * m))
    wd = w0 * math.sqrt(1.0 - zeta * zeta)
    t = np.asarray(t)
    return u0 * np.exp(-zeta * w0 * t) * (np.cos(wd * t) + zeta * w0 / wd * np.sin(wd * t))


def main(out_dir):
    case = fsi_results.read_case(out_dir)
    s, f = case["solid"], case["fluid"]
    m, k, u0 = float(s["mass"]), float(s["stiffness"]), float(s["initial_displacement"])
    spread, n = float(s["stiffness_spread"]), int(s["particles"])
    c, kf = float(f["damping"]), float(f["stiffness"])
    window = float(case["run"]["max_window"])

    probes = fsi_results.read_probes(out_dir)
    t = np.array(probes["time"])
    uy = np.array(probes["p0_uy"])
    exact = damped_oscillator(t, u0, m, k + kf, c)
    err_max = np.max(np.abs(uy - exact)) / abs(u0)
    err_rms = math.sqrt(np.mean((uy - exact) ** 2)) / abs(u0)

    t_last, frame = fsi_results.read_last_frame(os.path.join(out_dir, "solid.h5"), ["position"])
    u_last = frame["position"][:, 1]
    ki = k * (1.0 + spread * np.arange(n) / max(n - 1, 1))
    exact_last = np.array([damped_oscillator(t_last, u0, m, kk + kf, c) for kk in ki])
    err_frame = np.max(np.abs(u_last - exact_last)) / abs(u0)

    fig, (a, b) = plt.subplots(1, 2, figsize=(11, 4))
    a.plot(t, exact * 1e3, "k-", lw=1.2, label="exact damped oscillator")
    a.plot(t[::4], uy[::4] * 1e3, "o", ms=3, mfc="none", label=f"coupled run (window {window:g} s)")
    a.set_xlabel("t [s]")
    a.set_ylabel("particle 0 displacement u_y [mm]")
    a.set_title(f"probe p0_uy: max error {100 * err_max:.2f} % of u0")
    a.legend()
    b.plot(ki, exact_last * 1e3, "k-", lw=1.2, label="exact")
    b.plot(ki, u_last * 1e3, "o", ms=3, mfc="none", label="solid.h5, last frame")
    b.set_xlabel("particle stiffness k_i [N/m]")
    b.set_ylabel(f"u_y at t = {t_last:g} s [mm]")
    b.set_title(f"all {n} particles: max error {100 * err_frame:.2f} % of u0")
    b.legend()
    fig.suptitle("spring-mass solid + dashpot fluid through the coupler (serial-staggered)")
    fig.tight_layout()
    png = os.path.join(out_dir, "demo.png")
    fig.savefig(png, dpi=110)
    print(f"probe p0_uy against exact: max error {100 * err_max:.3f} % of u0, "
          f"RMS {100 * err_rms:.3f} % of u0 ({len(t)} samples)")
    print(f"last frame (t = {t_last:g} s), all {n} particles: max error {100 * err_frame:.3f} % of u0")
    print(f"plot: {png}")


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    main(sys.argv[1])
