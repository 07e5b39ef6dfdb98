#!/usr/bin/python3
"""C3 sluice gate: point A (the gate's free end) of coupled runs, its history and snapshots.

    /usr/bin/python3 bench/c3_sluice_gate.py [--png PLOT] [--snapshots PLOT] [--md TABLE]
                                             [--times "t1 t2 t3 t4"] RUN_DIR...

For every output folder RUN_DIR (a run of cases/c3_sluice_gate.ini, any spacing) it reads
the probe "tip" of probes.csv (point A: the middle point of the gate's lowest row) and
reports when the gate starts to move (|ux| > 0.1 mm), its largest horizontal (downstream,
the opening) and vertical displacement and when, and ux at the last probe row, with the
run's particles, windows, wall time and the fluid particles the run found inside the
solid (fluid.log's "interface" line). There is no reference data for this scene (000
Fig. 19 is not digitised), so nothing is compared. One line per run on stdout; --md
writes the same as a markdown table, --png the displacement history of every run,
--snapshots the fluid pressure and the gate's displacement of the finest run at four
times (the nearest output frames): when the gate starts to move, the largest opening
within 0.1 s of that (the impact), the largest opening of the run and the end, or
--times.
"""
import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import fsi_results  # noqa: E402

THICKNESS = 0.007      # gate thickness T (m)
MOVE = 1e-4            # |ux| at which the gate counts as moving (m)


def summary(run):
    case = fsi_results.read_case(run)
    dx = float(case["solid"]["spacing"])
    pr = fsi_results.read_probes(run)
    t = np.array(pr["time"])
    ux, uy = np.array(pr["tip_ux"]), np.array(pr["tip_uy"])
    moving = np.nonzero(np.abs(ux) > MOVE)[0]
    nf, ng, nc = fsi_results.particle_counts(run)
    log = os.path.join(run, "run.log")
    flog = os.path.join(run, "fluid.log")
    inside = fsi_results.log_match(flog, r"interface: .*?(at most [0-9]+ at once, in [0-9]+ windows)")
    in_walls = walls_count(run, case)
    return dict(
        run=run, dx=dx, t=t, ux=ux, uy=uy, nf=nf, ng=ng, nc=nc,
        ended=t[-1] >= float(case["run"]["end_time"]) - 1e-9,
        t_move=float(t[moving[0]]) if moving.size else float("nan"),
        ux_max=(float(ux.max()), float(t[int(np.argmax(ux))])),
        uy_max=(float(uy.max()), float(t[int(np.argmax(uy))])),
        ux_end=float(ux[-1]),
        windows=fsi_results.log_match(log, r"\nwindows = ([0-9]+)", "?"),
        wall=fsi_results.wall_time(run),
        threads=fsi_results.log_match(flog, r"on ([0-9]+) thread\(s\)", "?"),
        inside=inside or "?", in_walls=in_walls)


def walls_count(run, case):
    """(most in any frame, in the last frame) of the fluid particles deeper than dx / 2
    in a wall (fsi_results.wall_boxes): the floor under the gate is where water leaked."""
    import h5py
    boxes = fsi_results.wall_boxes(case)
    with h5py.File(os.path.join(run, "fluid.h5"), "r") as f:
        counts = [fsi_results.fluid_in_walls(boxes, f["frames"][k]) for k in sorted(f["frames"])]
    return max(counts), counts[-1]


def markdown(results):
    lines = ["| dx | T / dx | fluid particles | solid points (gate + clamp) | end | windows "
             "| gate starts to move | largest ux (t) | largest uy (t) | ux at the end "
             "| fluid particles inside the solid | fluid in walls (most, end) | wall time | threads |",
             "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |"]
    for r in results:
        end = f"t = {r['t'][-1]:.3f} s" if r["ended"] else \
            f"stopped, last probe row t = {r['t'][-1]:.3f} s"
        wall = f"{r['wall']:.0f} s" if r["wall"] is not None else "-"
        lines.append(
            f"| {1000 * r['dx']:.4g} mm | {THICKNESS / r['dx']:.0f} | {r['nf']} | {r['ng']} + {r['nc']} "
            f"| {end} | {r['windows']} | {r['t_move']:.3f} s "
            f"| {r['ux_max'][0]:.4f} m ({r['ux_max'][1]:.3f} s) "
            f"| {r['uy_max'][0]:.4f} m ({r['uy_max'][1]:.3f} s) | {r['ux_end']:.4f} m "
            f"| {r['inside']} | {r['in_walls'][0]}, {r['in_walls'][1]} | {wall} | {r['threads']} |")
    return "\n".join(lines) + "\n"


def snapshot_times(r, times):
    """The four snapshot times: given, or the gate starting to move, the largest ux within
    0.1 s of that (the impact), the largest ux of the run and the end."""
    if times:
        return times
    t, ux = r["t"], r["ux"]
    t0 = r["t_move"] if np.isfinite(r["t_move"]) else 0.0
    early = (t >= t0) & (t <= t0 + 0.1)
    t_impact = float(t[early][int(np.argmax(ux[early]))]) if early.any() else t0
    return [t0, t_impact, r["ux_max"][1], float(t[-1])]


def snapshots(r, png, times):
    import h5py
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    run, dx = r["run"], r["dx"]
    case = fsi_results.read_case(run)
    gate_x = float(case["solid.block gate"]["min"].split(",")[0])
    reach = max(0.12, r["ux_max"][0] + 0.06)      # the zoom holds the open gate
    views = ((-0.01, 1.41, -0.01, 0.35, 7.0), (gate_x - 0.1, gate_x + reach, -0.01, 0.2, 2.2))
    fig, axes = plt.subplots(4, 2, figsize=(10.5, 8.2), layout="constrained",
                             gridspec_kw={"width_ratios": [7.0, 2.2]})
    with h5py.File(os.path.join(run, "fluid.h5"), "r") as ff, \
            h5py.File(os.path.join(run, "solid.h5"), "r") as sf:
        clamped = (sf["static/flags"][()].ravel() & 1) > 0
        frames = [(fsi_results.frame_at(ff, t), fsi_results.frame_at(sf, t))
                  for t in snapshot_times(r, times)]
        u_top = max(float(np.linalg.norm(s["displacement"][()], axis=1).max()) for _, s in frames)
        for row, (fr, sr) in zip(axes, frames):
            umag = np.linalg.norm(sr["displacement"][()], axis=1)
            for ax, (x0, x1, y0, y1, width_in) in zip(row, views):
                size = (1.3 * dx / (x1 - x0) * width_in * 72.0) ** 2   # a little over dx: no gaps
                pf, ps = fsi_results.draw_coupled_frame(
                    ax, fr, sr, clamped, size, 2500.0, solid_values=umag,
                    solid_cmap="autumn", solid_range=(0.0, max(u_top, 1e-6)))
                ax.set_xlim(x0, x1)
                ax.set_ylim(y0, y1)
                ax.set_aspect("equal")
                ax.tick_params(labelsize=7)
            row[0].set_title(f"t = {sr.attrs['time']:.2f} s", fontsize=9, loc="left")
            row[1].set_title("at the gate", fontsize=8)
    fig.colorbar(pf, ax=axes[:, 0], label="fluid pressure [Pa]", location="bottom", shrink=0.5)
    fig.colorbar(ps, ax=axes[:, 1], label="gate |u| [m]", location="bottom", shrink=0.9)
    fig.suptitle(f"C3 dam-break wave on an elastic sluice gate, dx = {1000 * dx:.3g} mm "
                 f"(T / dx = {THICKNESS / dx:.0f}): fluid pressure, gate displacement, "
                 "clamp (black), walls (grey)", fontsize=10)
    fig.savefig(png, dpi=110)
    print(f"snapshots: {png}")


def history(results, png):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(8, 4.4))
    for r in results:
        lab = f"T/dx = {THICKNESS / r['dx']:.0f} (dx = {1000 * r['dx']:.3g} mm)"
        if not r["ended"]:
            lab += f", stopped at t = {r['t'][-1]:.3f} s"
        line, = ax.plot(r["t"], r["ux"], label=f"ux (downstream), {lab}")
        ax.plot(r["t"], r["uy"], "--", color=line.get_color(), label=f"uy (up), {lab}")
        ax.plot(*r["ux_max"][::-1], "o", color=line.get_color())
        ax.annotate(f"{r['ux_max'][0]:.4f} m at {r['ux_max'][1]:.3f} s", r["ux_max"][::-1],
                    textcoords="offset points", xytext=(6, 4), fontsize=8)
    ax.axhline(0, color="k", lw=0.5)
    ax.set_xlabel("t [s]")
    ax.set_ylabel("displacement of point A (the gate's free end) [m]")
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=7)
    ax.set_title("C3 dam-break wave on an elastic sluice gate: point A (no reference data)",
                 fontsize=10)
    fig.tight_layout()
    fig.savefig(png, dpi=120)
    print(f"plot: {png}")


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("runs", nargs="+")
    ap.add_argument("--png", default=None, help="history of point A")
    ap.add_argument("--snapshots", default=None, help="pressure + gate frames of the finest run")
    ap.add_argument("--md", default=None, help="markdown table")
    ap.add_argument("--times", default=None, help="four snapshot times, e.g. \"0.2 0.4 0.6 0.8\"")
    args = ap.parse_args()
    results = []
    for run in args.runs:
        if not os.path.exists(os.path.join(run, "probes.csv")):
            print(f"{run}: no probes.csv, left out")
            continue
        r = summary(run)
        results.append(r)
        print(f"{run} dx={r['dx']:.6g} T/dx={THICKNESS / r['dx']:.1f} fluid={r['nf']} "
              f"solid={r['ng']}+{r['nc']} t_end={r['t'][-1]:.4f} windows={r['windows']} "
              f"t_move={r['t_move']:.3f} ux_max={r['ux_max'][0]:.4f}@{r['ux_max'][1]:.3f} "
              f"uy_max={r['uy_max'][0]:.4f}@{r['uy_max'][1]:.3f} ux_end={r['ux_end']:.4f} "
              f"inside: {r['inside']} in_walls_max={r['in_walls'][0]} "
              f"in_walls_end={r['in_walls'][1]} wall={r['wall']}")
    if not results:
        return
    if args.md:
        with open(args.md, "w") as f:
            f.write(markdown(results))
    if args.png:
        history(results, args.png)
    if args.snapshots:
        times = [float(x) for x in args.times.split()] if args.times else None
        snapshots(min(results, key=lambda r: r["dx"]), args.snapshots, times)


if __name__ == "__main__":
    main()
