"""Every fluid x solid combination on one scene (docs/validation.md, "Every fluid with
every solid"): one table row per run and the accuracy-against-wall-time CSV of
bench/accuracy_speed.py.

    /usr/bin/python3 bench/combinations.py --scene c1|c2 --md T.md --csv-out A.csv RUN_DIR ...

Columns: the combination and resolution, the particle counts, the error against the
scene's reference (C1: NRMSE of the corner's u_x against the published curves' mean,
bench/c1_elastic_plate.py; C2: NRMSE of the gate's free end, x and y, against Antoci's
experiment, bench/c2_elastic_gate.py), the first peak and its time, the fluid particles
found inside the solid (fluid.log: the most at once and in how many windows), the
balance of the interface loads (the impulse the fluid sent against the impulse the solid
received, largest component difference over the impulse's size), the wall time and the
thread count. A run that stopped early keeps its row, marked, and stays off the chart.
"""
import argparse
import os
import re
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import fsi_results  # noqa: E402

VEC = r"\(([-0-9.e+]+), ([-0-9.e+]+)(?:, ([-0-9.e+]+))?\)"


def impulses(run):
    """(sent by the fluid, received by the solid) as arrays, or None where not logged."""
    def read(name, pattern):
        hit = fsi_results.log_match(os.path.join(run, name), pattern)
        return None if hit is None else np.array([float(v) for v in hit if v])
    sent = read("fluid.log", r"loads sent to the solid: impulse " + VEC)
    got = read("solid.log", r"loads received from the fluid: impulse " + VEC)
    return sent, got


def inside(run):
    """(most at once, windows) of fluid particles inside the solid, from fluid.log."""
    hit = fsi_results.log_match(os.path.join(run, "fluid.log"),
                                r"inside the solid[^:]*: at most (\d+) at once, in (\d+) windows")
    return (int(hit[0]), int(hit[1])) if hit else None


def c1_metrics(run):
    import c1_elastic_plate as c1
    refs = c1.references(c1.DATA)
    pr = fsi_results.read_probes(run)
    t, u = pr["time"], pr["corner_ux"]
    v, tp = c1.first_peak(t, u, 0.35)
    e = c1.nrmse(t, u, refs)
    dx = float(fsi_results.read_case(run)["solid"]["spacing"])
    return dict(resolution="dx=%g mm" % (1e3 * dx), dx=dx, error=e, t_end=t[-1],
                error_text="-" if e is None else "%.1f %%" % (100 * e),
                peak_text="%.4f m at %.3f s" % (v, tp))


def c2_metrics(run):
    import c2_elastic_gate as c2
    pr = fsi_results.read_probes(run)
    t = np.array(pr["time"])
    ex = c2.nrmse(t, np.array(pr["tip_ux"]), *c2.read_series("antoci2007_gate_xdisp_exp.csv"))
    ey = c2.nrmse(t, np.array(pr["tip_uy"]), *c2.read_series("antoci2007_gate_ydisp_exp.csv"))
    ux = np.array(pr["tip_ux"])
    k = int(np.argmax(ux))
    dx = float(fsi_results.read_case(run)["solid"]["spacing"])
    full = ex[1] == 9
    return dict(resolution="T/dx=%d" % round(c2.THICKNESS / dx), dx=dx,
                error=ex[0] if full else None, t_end=t[-1],
                error_text="x %.1f %%, y %.1f %% (%d / 9 points)" % (100 * ex[0], 100 * ey[0], ex[1]),
                peak_text="ux %.4f m at %.3f s" % (ux[k], t[k]))


SCENES = {"c1": c1_metrics, "c2": c2_metrics}


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--scene", required=True, choices=sorted(SCENES))
    ap.add_argument("--md", required=True)
    ap.add_argument("--csv-out", required=True)
    ap.add_argument("runs", nargs="+")
    a = ap.parse_args()
    rows = []
    for run in a.runs:
        if not os.path.exists(os.path.join(run, "probes.csv")):
            print(f"{run}: no probes.csv, left out", file=sys.stderr)
            continue
        m = SCENES[a.scene](run)
        nf, ns, nc = fsi_results.particle_counts(run)
        wall = fsi_results.wall_time(run)
        threads = fsi_results.log_match(os.path.join(run, "fluid.log"), r"on (\d+) thread\(s\)") or "?"
        sent, got = impulses(run)
        if sent is None or got is None:
            balance = "not logged"
        else:
            balance = "%.1e" % (np.abs(sent - got).max() / max(np.linalg.norm(sent), 1e-300))
        ins = inside(run)
        rows.append(dict(m, run=run, solvers=fsi_results.solvers(run), nf=nf, ns=ns, nc=nc,
                         wall=wall, threads=threads, balance=balance,
                         inside="?" if ins is None else "%d (%d windows)" % ins))
    rows.sort(key=lambda r: (r["solvers"], -r["dx"]))
    with open(a.md, "w") as md:
        md.write("| fluid + solid | resolution | fluid particles | solid points (free + clamped) "
                 "| error against the reference | first peak | fluid inside the solid, most at once "
                 "| impulse sent - received | wall time | threads |\n"
                 "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |\n")
        for r in rows:
            wall = "%.0f s" % r["wall"] if r["wall"] else "stopped at t = %.4f s" % r["t_end"]
            md.write("| %s | %s | %d | %d + %d | %s | %s | %s | %s | %s | %s |\n"
                     % (r["solvers"], r["resolution"], r["nf"], r["ns"], r["nc"], r["error_text"],
                        r["peak_text"], r["inside"], r["balance"], wall, r["threads"]))
    with open(a.csv_out, "w") as f:
        f.write("solvers,resolution,dx_m,particles,threads,wall_s,error\n")
        for r in rows:
            if r["wall"] and r["error"] is not None:
                f.write("%s,%s,%g,%d,%s,%.1f,%.5f\n" % (r["solvers"], r["resolution"], r["dx"],
                                                         r["nf"], r["threads"], r["wall"], r["error"]))


if __name__ == "__main__":
    main()
