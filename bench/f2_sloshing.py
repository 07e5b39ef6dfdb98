#!/usr/bin/python3
"""F2 sloshing: the free-surface elevation FS1 of the ULPH runs of bench/f2_sloshing.sh.

    /usr/bin/python3 bench/f2_sloshing.py OUT [--data CSV]

OUT/seed (cases/f2_sloshing.ini, 000 §4.3) and OUT/faltinsen
(cases/f2_sloshing_faltinsen.ini) each hold a run; FS1_eta of their probes.csv is the
elevation above the still level 0.05 m from the left wall (the probe moves with the
tank). Writes
  OUT/f2_sloshing.png            FS1 of the seed's scene (no measured data exist for it,
                                 SOURCES.md section 5)
  OUT/f2_sloshing_faltinsen.png  FS1 against Faltinsen et al. 2000's measurement
  OUT/f2_sloshing.md             one row per run
Error measure (Faltinsen run): the simulated elevation interpolated linearly in time at
the measured times within the simulated span, E = RMS(eta_sim - eta_exp) / max|eta_exp|
(the measured amplitude over the whole record), plus the simulated and measured
largest |eta| over the same span.
"""
import argparse
import csv
import os
import re

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

DATA = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "data",
                    "faltinsen2000_sloshing_h0p6_T1p3_probe0p05m_exp.csv")


def read_probe(run):
    with open(os.path.join(run, "probes.csv"), newline="") as f:
        rows = list(csv.reader(line for line in f if not line.startswith("#")))
    col = rows[0].index("FS1_eta")
    t, eta = [], []
    for r in rows[1:]:
        if r and r[col] not in ("", "nan"):
            t.append(float(r[0]))
            eta.append(float(r[col]))
    return np.array(t), np.array(eta)


def read_data(path):
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    assert rows[0] == ["time_s", "free_surface_elevation_m"], rows[0]
    d = np.array([[float(x) for x in r] for r in rows[1:] if r])
    order = np.argsort(d[:, 0], kind="stable")
    return d[order, 0], d[order, 1]


def end_of(run, name, out):
    """'finished' or 'stopped: <reason>' from the run's console log OUT/NAME.txt."""
    path = os.path.join(out, name + ".txt")
    text = open(path).read() if os.path.exists(path) else ""
    if re.search(r"^exit 0$", text, re.M):
        return "finished"
    why = [line for line in text.splitlines() if "unstable" in line or "left the domain" in line]
    return "stopped: " + (why[-1].strip()[:200] if why else "see " + path)


def steps_line(run):
    path = os.path.join(run, "fluid.log")
    text = open(path).read() if os.path.exists(path) else ""
    m = re.search(r"performance: (\d+) steps of (\d+) fluid particles.*?\(([\d.e+]+) "
                  r"particle-steps/s\)", text)
    return (int(m.group(1)), int(m.group(2)), float(m.group(3))) if m else (None, None, None)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("out")
    ap.add_argument("--data", default=DATA)
    a = ap.parse_args()
    rows = []

    seed = os.path.join(a.out, "seed")
    if os.path.exists(os.path.join(seed, "probes.csv")):
        t, eta = read_probe(seed)
        fig, ax = plt.subplots(figsize=(8, 3.5))
        ax.plot(t, eta, "b-", lw=1.2, label="ULPH, dx = 0.025 m")
        ax.set_xlabel("t [s]")
        ax.set_ylabel("elevation at FS1 [m]")
        ax.set_title("F2 sloshing (000 §4.3): H = 0.5 m, A0 = 0.032 m, T = 1.875 s")
        ax.grid(alpha=0.3)
        ax.legend()
        fig.tight_layout()
        fig.savefig(os.path.join(a.out, "f2_sloshing.png"), dpi=120)
        steps, n, rate = steps_line(seed)
        rows.append(["seed (H = 0.5 m, T = 1.875 s)", n, f"{t[-1]:.2f} s",
                     end_of(seed, "seed", a.out), "-", "-",
                     f"{np.max(np.abs(eta)):.4f} m", "-", rate])

    falt = os.path.join(a.out, "faltinsen")
    if os.path.exists(os.path.join(falt, "probes.csv")):
        t, eta = read_probe(falt)
        te, ee = read_data(a.data)
        inside = (te >= t[0]) & (te <= t[-1])
        sim = np.interp(te[inside], t, eta)
        amp = np.max(np.abs(ee))
        rms = np.sqrt(np.mean((sim - ee[inside]) ** 2))
        fig, ax = plt.subplots(figsize=(8, 3.5))
        ax.plot(te, ee, "ko", ms=3, label="Faltinsen et al. 2000 (experiment)")
        ax.plot(t, eta, "r-", lw=1.2, label="ULPH, dx = 0.025 m")
        ax.set_xlabel("t [s]")
        ax.set_ylabel("elevation 0.05 m from the left wall [m]")
        ax.set_title(f"F2, H = 0.6 m, T = 1.3 s: RMS / max|eta_exp| = {rms / amp:.1%}")
        ax.grid(alpha=0.3)
        ax.legend(loc="lower left", fontsize=8)
        fig.tight_layout()
        fig.savefig(os.path.join(a.out, "f2_sloshing_faltinsen.png"), dpi=120)
        steps, n, rate = steps_line(falt)
        rows.append(["Faltinsen (H = 0.6 m, T = 1.3 s)", n, f"{t[-1]:.2f} s",
                     end_of(falt, "faltinsen", a.out), f"{int(inside.sum())} / {len(te)}",
                     f"{rms:.4f} m = {rms / amp:.1%} of {amp:.4f} m",
                     f"{np.max(np.abs(sim)):.4f} m", f"{np.max(np.abs(ee[inside])):.4f} m",
                     rate])

    head = ["run", "fluid particles", "simulated", "end", "measured points",
            "RMS(eta_sim - eta_exp) / max abs(eta_exp)", "max abs(eta_sim)", "max abs(eta_exp)",
            "particle-steps/s"]
    lines = ["| " + " | ".join(head) + " |", "|" + " --- |" * len(head)]
    for r in rows:
        lines.append("| " + " | ".join("-" if x is None else str(x) for x in r) + " |")
    text = "\n".join(lines) + "\n"
    with open(os.path.join(a.out, "f2_sloshing.md"), "w") as f:
        f.write(text)
    print(text, end="")


if __name__ == "__main__":
    main()
