#!/usr/bin/python3
"""F1 dam break: the pressure at the wall's foot (probe wall_foot) of several runs, and
its noise, for the comparison of the fluid schemes (docs/isph.md, "Pressure noise").

    /usr/bin/python3 bench/f1_pressure_noise.py [--png PLOT] [--t0 T] LABEL=RUN_DIR...

For each run it reads probes.csv and prints, after t0 (default 0.05 s: the start's
transient left out), the mean pressure and the noise: the RMS of the signal's
departure from its running mean over 5 probe samples (0.0125 s at the case's
probe_interval), in Pa and as a fraction of the mean. One line per run, and a PNG of
every history."""
import argparse
import csv
import sys

import numpy as np


def history(run):
    with open(run + "/probes.csv", newline="") as f:
        rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
    t = np.array([float(r["time"]) for r in rows])
    p = np.array([float(r["wall_foot_p"]) for r in rows])
    return t, p


def noise(p, width=5):
    kernel = np.ones(width) / width
    smooth = np.convolve(p, kernel, mode="same")
    core = slice(width, len(p) - width)
    return float(np.sqrt(np.mean((p[core] - smooth[core]) ** 2)))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--png")
    ap.add_argument("--t0", type=float, default=0.05)
    ap.add_argument("runs", nargs="+", metavar="LABEL=RUN_DIR")
    a = ap.parse_args()
    curves = []
    for item in a.runs:
        label, run = item.split("=", 1)
        t, p = history(run)
        keep = t >= a.t0
        n = noise(p[keep])
        mean = float(np.mean(p[keep]))
        print("%s: %d samples after t = %g s, mean %.1f Pa, noise %.1f Pa (%.1f %% of the mean)"
              % (label, int(keep.sum()), a.t0, mean, n, 100 * n / mean))
        curves.append((label, t, p, n))
    if a.png:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(figsize=(7, 4))
        for label, t, p, n in curves:
            ax.plot(t, p, lw=0.9, label="%s (noise %.0f Pa)" % (label, n))
        ax.set_xlabel("t [s]")
        ax.set_ylabel("pressure at the wall's foot [Pa]")
        ax.set_title("F1: pressure at the left wall's foot")
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
        fig.tight_layout()
        fig.savefig(a.png, dpi=110)
    return 0


if __name__ == "__main__":
    sys.exit(main())
