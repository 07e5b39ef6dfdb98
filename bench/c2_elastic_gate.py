#!/usr/bin/python3
"""C2 elastic gate: the gate's free end of coupled runs against Antoci et al. 2007.

    /usr/bin/python3 bench/c2_elastic_gate.py [--png PLOT] [--snapshots PLOT]
                                              [--csv-out FILE] RUN_DIR...

For every output folder RUN_DIR (a run of cases/c2_elastic_gate.ini, any spacing) it
reads the probe "tip" of probes.csv (the gate's lower end, mid-thickness) and compares
its displacement with Antoci's experiment (data/antoci2007_gate_*_exp.csv;
positive magnitudes: x downstream = +tip_ux, y lift = +tip_uy). The simulation is
interpolated linearly in time at the measured times within the simulated time (the
y record's first point, t = -0.0008 s, a digitisation artefact, falls outside and is
left out), and NRMSE = RMS(sim - exp) / (max(exp) - min(exp)) over those points. One
line per run:
    RUN_DIR dx=... T/dx=... fluid=... solid=... t_end=... nrmse_x=... nrmse_y=...
and a PNG with both displacements of every run, the experiment and the numerical
curves of Khayyer et al. 2018 (ISPH-SPH) and Yang et al. 2012 (SPH-FEM). --snapshots
draws the fluid pressure and the gate of the finest run that got to 0.16 s at t = 0.04,
0.08, 0.12, 0.16 s (the times of Antoci's photographs) from fluid.h5 and solid.h5, or
if no run got that far, the last four frames of the run that got furthest.
"""
import argparse
import csv
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import fsi_results  # noqa: E402

DATA = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "data")
THICKNESS = 0.005                       # gate thickness T (m)
SNAP_TIMES = (0.04, 0.08, 0.12, 0.16)


def read_series(name):
    """(t, value) of a two-column CSV of the data folder."""
    with open(os.path.join(DATA, name), newline="") as f:
        rows = list(csv.reader(f))
    assert rows[0][0] == "time_s", rows[0]
    d = np.array([[float(x) for x in r] for r in rows[1:] if r])
    return d[:, 0], d[:, 1]


def nrmse(t_sim, u_sim, t_exp, u_exp):
    """(NRMSE, points used) of the simulation against the measured points it covers."""
    ok = (t_exp >= 0.0) & (t_exp <= t_sim[-1] + 1e-9)
    if not ok.any():
        return float("nan"), 0
    err = np.interp(t_exp[ok], t_sim, u_sim) - u_exp[ok]
    return float(np.sqrt(np.mean(err ** 2)) / (u_exp.max() - u_exp.min())), int(ok.sum())


def snapshot_times(run_dir):
    """SNAP_TIMES if the run's solid frames reach them, else its last four frames' times."""
    times = fsi_results.frame_times(os.path.join(run_dir, "solid.h5"))
    return SNAP_TIMES if times[-1] >= SNAP_TIMES[-1] - 1e-9 else times[-4:]


def snapshots(run_dir, png, dx):
    import h5py
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(2, 2, figsize=(9.6, 6.4), sharex=True, sharey=True)
    with h5py.File(os.path.join(run_dir, "fluid.h5"), "r") as ff, \
            h5py.File(os.path.join(run_dir, "solid.h5"), "r") as sf:
        clamped = (sf["static/flags"][()].ravel() & 1) > 0
        last = None
        for ax, t in zip(axes.ravel(), snapshot_times(run_dir)):
            fr, sr = fsi_results.frame_at(ff, t), fsi_results.frame_at(sf, t)
            size = (dx * 72.0 * 3.0 / 0.27) ** 2    # points^2: dx on axes 3 in wide for 0.27 m
            last, _ = fsi_results.draw_coupled_frame(ax, fr, sr, clamped, size, 1400.0)
            ax.set_title(f"t = {sr.attrs['time']:.2f} s", fontsize=9)
            ax.set_aspect("equal")
            ax.set_xlim(-0.01, 0.26)
            ax.set_ylim(-0.01, 0.16)
    fig.colorbar(last, ax=axes, label="fluid pressure [Pa]", shrink=0.8)
    fig.suptitle(f"C2 elastic gate, dx = {1000 * dx:.3g} mm: fluid pressure, gate (red), "
                 "clamp (black), walls (grey)", fontsize=10)
    fig.savefig(png, dpi=120)
    print(f"snapshots: {png}")


def material_text(case):
    """', neo_hookean, E = 7.8 MPa' for a gate that is not the case's linear elastic one
    of E = 12 MPa, nu = 0.4 (empty for that one): the legend of runs that differ only
    in the material."""
    solid = case["solid"]
    law = solid.get("constitutive", "linear_elastic")
    text = "" if law == "linear_elastic" else f", {law}"
    e, nu = float(solid["youngs_modulus"]), float(solid["poisson_ratio"])
    if abs(e - 12e6) > 1.0 or abs(nu - 0.4) > 1e-9:
        text += f", E = {e / 1e6:g} MPa, nu = {nu:g}"
    return text


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("runs", nargs="+")
    ap.add_argument("--png", default=None)
    ap.add_argument("--snapshots", default=None, help="pressure + gate frames of the finest run")
    ap.add_argument("--csv-out", default=None)
    args = ap.parse_args()
    exp = {"x": read_series("antoci2007_gate_xdisp_exp.csv"),
           "y": read_series("antoci2007_gate_ydisp_exp.csv")}
    results = []
    for run in args.runs:
        if not os.path.exists(os.path.join(run, "probes.csv")):
            print(f"{run}: no probes.csv, left out")
            continue
        case = fsi_results.read_case(run)
        dx = float(case["solid"]["spacing"])
        pr = fsi_results.read_probes(run)
        t = np.array(pr["time"])
        u = {"x": np.array(pr["tip_ux"]), "y": np.array(pr["tip_uy"])}
        err = {k: nrmse(t, u[k], *exp[k]) for k in u}
        nf, ng, nc = fsi_results.particle_counts(run)
        peak = {k: (float(u[k].max()), float(t[int(np.argmax(u[k]))])) for k in u}
        ended = t[-1] >= float(case["run"]["end_time"]) - 1e-9
        results.append(dict(run=run, dx=dx, t=t, u=u, err=err, nf=nf, ng=ng, nc=nc, peak=peak,
                            ended=ended, solvers=fsi_results.solvers(run),
                            material=material_text(case)))
        print(f"{run} dx={dx:.6g} T/dx={THICKNESS / dx:.1f} fluid={nf} solid={ng}+{nc} "
              f"t_end={t[-1]:.4f} nrmse_x={err['x'][0]:.4f} ({err['x'][1]} points) "
              f"nrmse_y={err['y'][0]:.4f} ({err['y'][1]} points) "
              f"peak_ux={peak['x'][0]:.4f}@{peak['x'][1]:.3f} "
              f"peak_uy={peak['y'][0]:.4f}@{peak['y'][1]:.3f}")
        for k in ("x", "y"):
            te, ue = exp[k]
            ok = (te >= 0.0) & (te <= t[-1] + 1e-9)
            for ti, ui in zip(te[ok], ue[ok]):
                print(f"    {k}: t={ti:.3f}  exp={ui:.4f}  sim={np.interp(ti, t, u[k]):.4f}")
    if args.csv_out:
        with open(args.csv_out, "w", newline="") as f:
            w = csv.writer(f, lineterminator="\n")
            w.writerow(["run", "dx", "t_over_dx", "fluid_particles", "solid_points", "t_end",
                        "nrmse_x", "points_x", "nrmse_y", "points_y",
                        "peak_ux", "t_peak_ux", "peak_uy", "t_peak_uy"])
            for r in results:
                w.writerow([r["run"], f"{r['dx']:.6g}", f"{THICKNESS / r['dx']:.0f}", r["nf"],
                            f"{r['ng']} + {r['nc']}", f"{r['t'][-1]:.4f}",
                            f"{r['err']['x'][0]:.6f}", r["err"]["x"][1],
                            f"{r['err']['y'][0]:.6f}", r["err"]["y"][1],
                            f"{r['peak']['x'][0]:.4f}", f"{r['peak']['x'][1]:.3f}",
                            f"{r['peak']['y'][0]:.4f}", f"{r['peak']['y'][1]:.3f}"])
    if args.png and results:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, axes = plt.subplots(1, 2, figsize=(11, 4.4))
        for ax, k, what in zip(axes, ("x", "y"), ("horizontal (downstream)", "vertical (lift)")):
            for r in results:
                lab = f"{r['solvers']}{r['material']} T/dx = {THICKNESS / r['dx']:.0f}"
                if r["ended"]:
                    lab += f", NRMSE {100 * r['err'][k][0]:.1f} %"
                if not r["ended"]:
                    lab += f", unstable at t = {r['t'][-1]:.3f} s"
                ax.plot(r["t"], r["u"][k], label=lab)
            for name, style, lab in (("khayyer_2018_isph_sph", "--", "Khayyer et al. 2018, ISPH-SPH"),
                                     ("yang_2012_sph_fem", ":", "Yang et al. 2012, SPH-FEM")):
                tn, un = read_series(f"antoci2007_gate_{k}disp_num_{name}.csv")
                ax.plot(tn, un, "k" + style, lw=1, label=lab)
            ax.plot(*exp[k], "ko", label="Antoci et al. 2007, experiment")
            ax.set_xlabel("t [s]")
            ax.set_ylabel(f"{what} displacement of the free end [m]")
            ax.set_xlim(0, 0.4)
            ax.grid(True, alpha=0.3)
            ax.legend(fontsize=7)
        fig.suptitle("C2 dam break through an elastic gate: the gate's free end", fontsize=10)
        fig.tight_layout()
        fig.savefig(args.png, dpi=120)
        print(f"plot: {args.png}")
    if args.snapshots and results:
        # The finest run that reached the last snapshot time, else the one that got furthest.
        done = [r for r in results if r["t"][-1] >= SNAP_TIMES[-1] - 1e-9]
        pick = min(done, key=lambda r: r["dx"]) if done else max(results, key=lambda r: r["t"][-1])
        snapshots(pick["run"], args.snapshots, pick["dx"])


if __name__ == "__main__":
    main()
