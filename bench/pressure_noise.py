#!/usr/bin/python3
"""The noise of a pressure signal in several runs, for the comparison of the fluid
schemes (docs/isph.md, "Pressure noise"): F1's pressure at the wall's foot (the default:
probes.csv, column wall_foot_p), or the fluid's load on C1's plate (--file
solid_diagnostics.csv --column plate.force_x: one row per coupling window, the pressure
and viscous pair terms on the plate summed, N/m).

    /usr/bin/python3 bench/pressure_noise.py [--file CSV] [--column NAME] [--interval S]
        [--t0 T] [--title T] [--png PLOT] LABEL=RUN_DIR...

Each signal is first put on one grid of --interval seconds (linear interpolation;
default 0.0025 s, F1's probe interval), so that runs whose windows differ compare alike.
For each run it prints, after t0 (default 0.05 s: the start's transient left out), the
mean and the noise: the RMS of the signal's departure from its running mean over 5
samples (0.0125 s at the default interval), absolute and as a fraction of the mean. One
line per run, and a PNG of every history."""
import argparse
import csv
import sys

import numpy as np


def history(run, name, column):
    with open("%s/%s" % (run, name), newline="") as f:
        lines = f.readlines()
    rows = list(csv.DictReader(line for line in lines if not line.startswith("#")))
    if not rows or column not in rows[0]:
        raise SystemExit("%s/%s: no column %s" % (run, name, column))
    units = next((line for line in lines if line.startswith("# units:")), None)
    unit = "?"
    if units:
        unit = units[len("# units:"):].strip().split(",")[list(rows[0]).index(column)]
    t = np.array([float(r["time"]) for r in rows])
    v = np.array([float(r[column]) for r in rows])
    return t, v, unit


def noise(p, width=5):
    kernel = np.ones(width) / width
    smooth = np.convolve(p, kernel, mode="same")
    core = slice(width, len(p) - width)
    return float(np.sqrt(np.mean((p[core] - smooth[core]) ** 2)))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--file", default="probes.csv", help="the CSV in each run directory")
    ap.add_argument("--column", default="wall_foot_p")
    ap.add_argument("--interval", type=float, default=0.0025, help="grid of the signal [s]")
    ap.add_argument("--png")
    ap.add_argument("--title", default="F1: pressure at the left wall's foot")
    ap.add_argument("--t0", type=float, default=0.05)
    ap.add_argument("runs", nargs="+", metavar="LABEL=RUN_DIR")
    a = ap.parse_args()
    curves = []
    unit = "?"
    for item in a.runs:
        label, run = item.split("=", 1)
        t_raw, v_raw, u = history(run, a.file, a.column)
        unit = u if u != "?" else unit     # runs of older builds have no units line
        t = np.arange(0.0, t_raw[-1] + 1e-12, a.interval)
        v = np.interp(t, t_raw, v_raw)
        keep = t >= a.t0
        n = noise(v[keep])
        mean = float(np.mean(v[keep]))
        print("%s: %d samples after t = %g s, mean %.4g %s, noise %.4g %s (%.1f %% of the mean)"
              % (label, int(keep.sum()), a.t0, mean, unit, n, unit, 100 * n / abs(mean)))
        curves.append((label, t, v, n))
    if a.png:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(figsize=(7, 4))
        for label, t, v, n in curves:
            ax.plot(t, v, lw=0.9, label="%s (noise %.3g %s)" % (label, n, unit))
        ax.set_xlabel("t [s]")
        ax.set_ylabel("%s [%s]" % (a.column, unit))
        ax.set_title(a.title)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
        fig.tight_layout()
        fig.savefig(a.png, dpi=110)
    return 0


if __name__ == "__main__":
    sys.exit(main())
