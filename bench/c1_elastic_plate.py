"""C1 (docs/validation.md): the horizontal displacement of the plate's upper-left corner
against the published numerical curves, with each curve's first peak.

    /usr/bin/python3 bench/c1_elastic_plate.py --png P.png --md T.md RUN_DIR ...
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


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--png", required=True)
    ap.add_argument("--md", required=True)
    ap.add_argument("--data", default=DATA)
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
                     fsi_results.wall_time(run), dx))
    with open(a.md, "w") as md:
        md.write("| curve | first peak of u_x | at t | run to | wall time |\n| --- | --- | --- | --- | --- |\n")
        for label, t, u, wall, _ in runs:
            v, tp = first_peak(t, u, 0.35)
            md.write("| %s | %.4f m | %.3f s | %.3g s | %s |\n"
                     % (label, v, tp, t[-1], "%.0f s" % wall if wall else "did not finish"))
        for label, t, u in refs:
            v, tp = first_peak(t, u, 0.35)
            md.write("| %s | %.4f m | %.3f s | | |\n" % (label, v, tp))
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(7, 4))
    for label, t, u in refs:
        ax.plot(t, u, lw=1, ls="--", label=label)
    for label, t, u, _, _ in runs:
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
