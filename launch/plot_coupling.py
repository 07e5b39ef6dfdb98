#!/usr/bin/python3
"""The implicit coupling of a run (docs/coupling.md, "Implicit coupling"): iterations per
window and the residuals of every iteration, from OUT/coupling.csv, to OUT/coupling.png.

    /usr/bin/python3 launch/plot_coupling.py OUT      (fsi plot-coupling OUT)
"""
import csv
import os
import sys


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: fsi plot-coupling OUT")
    out = sys.argv[1]
    path = os.path.join(out, "coupling.csv")
    if not os.path.exists(path):
        print("fsi plot-coupling: %s: no coupling.csv (it is written by runs with "
              "[run] scheme = implicit)" % out, file=sys.stderr)
        sys.exit(2)
    rows = list(csv.DictReader(open(path)))
    if not rows:
        print("fsi plot-coupling: %s is empty" % path, file=sys.stderr)
        sys.exit(2)
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    t = [float(r["time"]) for r in rows]
    it = [int(float(r["iteration"])) for r in rows]
    accepted = [(float(r["time"]), int(float(r["iteration"])) + 1, r["converged"] == "1",
                 int(float(r["history_restarted"])) & 1) for r in rows if r["accepted"] == "1"]
    fig, (a, b) = plt.subplots(2, 1, figsize=(8, 6), sharex=True)
    a.step([x[0] for x in accepted], [x[1] for x in accepted], where="post", lw=1)
    bad = [x for x in accepted if not x[2]]
    if bad:
        a.plot([x[0] for x in bad], [x[1] for x in bad], "rx", label="accepted unconverged")
    restarts = [x for x in accepted if x[3]]
    if restarts:
        a.plot([x[0] for x in restarts], [x[1] for x in restarts], "o", mfc="none",
               label="interface set changed (history restarted)")
    if bad or restarts:
        a.legend(fontsize=8)
    a.set_ylabel("iterations per window")
    a.set_title("%s: %d windows, %.2f iterations per window" %
                (os.path.basename(os.path.abspath(out)), len(accepted),
                 len(rows) / max(len(accepted), 1)), fontsize=10)
    for key, label, marker in (("displacement_residual", "displacement |d_out - d_in| / |d_out|", "."),
                               ("force_residual", "load |F_i - F_i-1| / |F_i|", "+")):
        pts = [(tt, float(r[key])) for tt, r in zip(t, rows) if float(r[key]) > 0]
        b.semilogy([p[0] for p in pts], [p[1] for p in pts], marker, ms=3, ls="none", label=label)
    b.set_xlabel("window start t [s]")
    b.set_ylabel("relative residual of each iteration")
    b.legend(fontsize=8)
    fig.tight_layout()
    png = os.path.join(out, "coupling.png")
    fig.savefig(png, dpi=110)
    print("fsi plot-coupling: %s (max %d iterations in a window)" % (png, max(it) + 1))


if __name__ == "__main__":
    main()
