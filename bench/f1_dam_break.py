#!/usr/bin/python3
"""F1 dam break: surge front of the fluid runs against Martin & Moyce 1952 (n^2 = 2, a = 2.25 in).

    /usr/bin/python3 bench/f1_dam_break.py [--data CSV] [--png PLOT] [--csv-out FILE] RUN_DIR...

For every output folder RUN_DIR (a run of cases/f1_dam_break.ini, any spacing) it reads
the frames of fluid.h5 and takes the surge front Z(t) = the largest x of the fluid
particles whose centre is within 2 dx of the floor (0 <= ... y < 2 dx, y = 0 the floor;
particles below the floor count too), with a = the column width (the water block's
x extent) and dx the case's spacing. Z / a against T = t sqrt(2 g / a) is compared with
the data: Z_sim is interpolated linearly in time between the frames at the measured T,
and the error is RMS over the measured points of (Z_sim - Z_exp) / Z_exp (only points
within the simulated time; their number is printed). It also counts the fluid particles
whose centre is deeper than dx / 2 inside a wall's box (past the centres of the wall's
first row of particles; walls: the [fluid.wall] boxes of the case), the largest count
over the frames and the count in the last frame. One line per run:
    RUN_DIR dx=... particles=... points=... rms=... in_walls_max=... in_walls_end=...
and a PNG with every run's curve and the data.
"""
import argparse
import csv
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import fsi_results  # noqa: E402

DATA = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "data",
                    "martin_moyce1952_surge_n2_2_a225in_exp.csv")


def read_data(path):
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    assert rows[0][0].startswith("T_eq_t_sqrt_2g_over_a") and rows[0][1] == "Z_over_a", rows[0]
    d = np.array([[float(x) for x in r] for r in rows[1:] if r])
    return d[:, 0], d[:, 1]


def vec(text):
    return [float(x) for x in text.replace(",", " ").split()]


def surge_front(run_dir):
    """(dx, a, g, n_fluid, times, fronts, in_walls) of one run."""
    import h5py
    case = fsi_results.read_case(run_dir)
    fl = case["fluid"]
    dx = float(fl["spacing"])
    g = abs(vec(fl["gravity"])[1])
    blocks = [s for s in case if s.startswith("fluid.block")]
    a = vec(case[blocks[0]]["max"])[0] - vec(case[blocks[0]]["min"])[0]
    walls = [s for s in case if s.startswith("fluid.wall")]
    floor = 0.0 if not walls else max(
        vec(case[w]["max"])[1] for w in walls
        if vec(case[w]["max"])[0] - vec(case[w]["min"])[0] > 4 * a)
    boxes = fsi_results.wall_boxes(case)
    times, fronts, in_walls, n_fluid = [], [], [], 0
    with h5py.File(os.path.join(run_dir, "fluid.h5"), "r") as f:
        for k in sorted(f["frames"].keys()):
            fr = f["frames"][k]
            x = fr["position"][()]
            fluid = (fr["flags"][()].ravel() & 1) > 0
            n_fluid = int(fluid.sum())
            near = fluid & (x[:, 1] < floor + 2.0 * dx)
            times.append(float(fr.attrs["time"]))
            fronts.append(float(x[near, 0].max()) if near.any() else float("nan"))
            in_walls.append(fsi_results.fluid_in_walls(boxes, fr))
    return dx, a, g, n_fluid, np.array(times), np.array(fronts), np.array(in_walls)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("runs", nargs="+")
    ap.add_argument("--data", default=DATA)
    ap.add_argument("--png", default=None)
    ap.add_argument("--csv-out", default=None, help="one row per run: run,dx,particles,points,rms")
    args = ap.parse_args()
    T_exp, Z_exp = read_data(args.data)
    results = []
    for run in args.runs:
        dx, a, g, n, t, z, inw = surge_front(run)
        T = t * math.sqrt(2.0 * g / a)
        Z = z / a
        ok = T_exp <= T[-1] + 1e-9
        Zs = np.interp(T_exp[ok], T, Z)
        rel = (Zs - Z_exp[ok]) / Z_exp[ok]
        rms = float(np.sqrt(np.mean(rel ** 2))) if ok.any() else float("nan")
        results.append((run, dx, a, n, int(ok.sum()), rms, T, Z, inw))
        print(f"{run} dx={dx:.6g} a/dx={a / dx:.1f} particles={n} t_end={t[-1]:.4f} "
              f"points={int(ok.sum())}/{len(T_exp)} rms={rms:.4f} "
              f"in_walls_max={int(inw.max())} in_walls_end={int(inw[-1])}")
        for Te, Ze, Zi in zip(T_exp[ok], Z_exp[ok], Zs):
            print(f"    T={Te:6.3f}  Z_exp/a={Ze:7.3f}  Z_sim/a={Zi:7.3f}  {100 * (Zi - Ze) / Ze:+6.1f} %")
    if args.csv_out:
        with open(args.csv_out, "w", newline="") as f:
            w = csv.writer(f, lineterminator="\n")
            w.writerow(["run", "dx", "a_over_dx", "particles", "points", "rms",
                        "in_walls_max", "in_walls_end"])
            for run, dx, a, n, npts, rms, _, _, inw in results:
                w.writerow([run, f"{dx:.6g}", f"{a / dx:.1f}", n, npts, f"{rms:.6f}",
                            int(inw.max()), int(inw[-1])])
    if args.png:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(figsize=(6.4, 4.8))
        for run, dx, a, n, npts, rms, T, Z, _ in results:
            ax.plot(T, Z, label=f"{fsi_results.solvers(run)} a/dx = {a / dx:.0f} ({n} particles), "
                                f"RMS {100 * rms:.1f} %")
        ax.plot(T_exp, Z_exp, "ko", label="Martin & Moyce 1952, n$^2$ = 2, a = 2.25 in")
        ax.set_xlabel("T = t sqrt(2 g / a)")
        ax.set_ylabel("Z / a (surge front)")
        ax.set_title("F1 dam break, column a x 2a")
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=8)
        fig.tight_layout()
        fig.savefig(args.png, dpi=120)
        print(f"plot: {args.png}")


if __name__ == "__main__":
    main()
