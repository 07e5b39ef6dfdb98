"""C1 (docs/validation.md): the horizontal displacement of the plate's upper-left corner
against the published numerical curves, with each curve's first peak.

    /usr/bin/python3 bench/c1_elastic_plate.py --png P.png --md T.md [--csv-out A.csv] RUN_DIR ...

The error of a run (its accuracy in A.csv, the columns of bench/accuracy_speed.py):
no experiment exists for C1, so it is the NRMSE of u_x over 0 <= t <= 0.4 s against
the mean of the four published curves, divided by the mean curve's first peak. The
same measure of each published curve against the mean of the other three is the
spread of the references: below it, a run is as close as the references are to each
other.
"""
import argparse
import csv
import glob
import os
import re

import fsi_results

DATA = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "data")
LABELS = {"idelsohn_2008_pfem": "Idelsohn 2008 (PFEM)", "bogaers_2016_qn_ls": "Bogaers 2016 (FEM, QN-LS)",
          "liu_2013_sph": "Liu 2013 (SPH)", "sun_2019_mps_dem": "Sun 2019 (MPS-DEM)"}


def references(data_dir):
    out = []
    for path in sorted(glob.glob(os.path.join(data_dir, "elastic_obstacle_xdisp_num_*.csv"))):
        key = re.sub(r"^elastic_obstacle_xdisp_num_|\.csv$", "", os.path.basename(path))
        with open(path, newline="") as f:
            rows = [(float(r[0]), float(r[1])) for r in list(csv.reader(f))[1:]]
        out.append((LABELS.get(key, key), [r[0] for r in rows], [r[1] for r in rows]))
    return out


def first_peak(t, u, t_max):
    """The largest value up to t_max and its time (the curves' first maximum lies
    before the plate's return at about 0.35 s)."""
    pts = [(v, tt) for tt, v in zip(t, u) if tt <= t_max]
    return max(pts) if pts else (float("nan"), float("nan"))


T_ERROR = 0.4  # s: the window of the error, the curves' common span


def mean_curve(refs, t):
    """The mean of the reference curves at the times t (each interpolated linearly)."""
    import numpy as np
    return np.mean([np.interp(t, rt, ru) for _, rt, ru in refs], axis=0)


def nrmse(t, u, refs):
    """RMS of u - mean curve over [0, T_ERROR], over the mean curve's first peak; None
    when the run stops before T_ERROR."""
    import numpy as np
    t, u = np.asarray(t), np.asarray(u)
    if t.size == 0 or t[-1] < T_ERROR - 1e-9:
        return None
    grid = np.linspace(0.0, T_ERROR, 401)
    ref = mean_curve(refs, grid)
    return float(np.sqrt(np.mean((np.interp(grid, t, u) - ref) ** 2)) / np.max(ref))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--png", required=True)
    ap.add_argument("--md", required=True)
    ap.add_argument("--data", default=DATA)
    ap.add_argument("--csv-out", help="accuracy against wall time (bench/accuracy_speed.py)")
    ap.add_argument("runs", nargs="+")
    a = ap.parse_args()
    refs = references(a.data)
    runs = []
    for run in a.runs:
        if not os.path.exists(os.path.join(run, "probes.csv")):
            continue
        pr = fsi_results.read_probes(run)
        dx = float(fsi_results.read_case(run)["solid"]["spacing"])
        runs.append(("%s, dx = %g mm" % (fsi_results.solvers(run), 1e3 * dx), pr["time"], pr["corner_ux"],
                     fsi_results.wall_time(run), dx, run))
    with open(a.md, "w") as md:
        md.write("| curve | first peak of u_x | at t | NRMSE against the mean curve | run to | wall time |\n"
                 "| --- | --- | --- | --- | --- | --- |\n")
        for label, t, u, wall, _, _ in runs:
            v, tp = first_peak(t, u, 0.35)
            e = nrmse(t, u, refs)
            md.write("| %s | %.4f m | %.3f s | %s | %.3g s | %s |\n"
                     % (label, v, tp, "%.1f %%" % (100 * e) if e is not None else "-", t[-1],
                        "%.0f s" % wall if wall else "did not finish"))
        for k, (label, t, u) in enumerate(refs):
            v, tp = first_peak(t, u, 0.35)
            others = refs[:k] + refs[k + 1:]
            md.write("| %s | %.4f m | %.3f s | %.1f %% (against the other three) | | |\n"
                     % (label, v, tp, 100 * nrmse(t, u, others)))
    if a.csv_out:
        with open(a.csv_out, "w") as f:
            f.write("solvers,resolution,dx_m,particles,threads,wall_s,error\n")
            for label, t, u, wall, dx, run in runs:
                e = nrmse(t, u, refs)
                if e is None or not wall:
                    continue
                nf = fsi_results.particle_counts(run)[0]
                threads = fsi_results.log_match(os.path.join(run, "fluid.log"),
                                                r"on (\d+) thread\(s\)") or "?"
                f.write("%s,dx=%g mm,%g,%d,%s,%.1f,%.5f\n"
                        % (fsi_results.solvers(run), 1e3 * dx, dx, nf, threads, wall, e))
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(7, 4))
    for label, t, u in refs:
        ax.plot(t, u, lw=1, ls="--", label=label)
    for label, t, u, _, _, _ in runs:
        ax.plot(t, u, lw=1.6, label=label)
    ax.set_xlim(0, max([r[1][-1] for r in runs] + [0.4]))
    ax.set_xlabel("t [s]")
    ax.set_ylabel("upper-left corner u_x [m]")
    ax.set_title("C1 dam break against an elastic plate")
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(a.png, dpi=120)


if __name__ == "__main__":
    main()
