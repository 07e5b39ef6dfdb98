"""C4 (docs/validation.md): the plate's mid-span deflection history of each run against
plate theory, and the settled value (mean over the second half of the run).

    /usr/bin/python3 bench/c4_plate_under_water.py --png P.png --md T.md RUN_DIR ...
"""
import argparse
import os

import fe_clamped_plate
import fsi_results


def vec(text):
    return [float(v) for v in text.split(",")]


def references(case):
    """From the case's own numbers: plate theory (003 Eq. 53), the same with a Timoshenko
    beam's shear deflection, and the 2D plane-strain finite-element answer with fully
    clamped ends (bench/fe_clamped_plate.py), the elastic problem the PD solid solves."""
    s, f = case["solid"], case["fluid"]
    plate, water = case["solid.block plate"], case["fluid.block water"]
    p0, p1 = vec(plate["min"]), vec(plate["max"])
    w0, w1 = vec(water["min"]), vec(water["max"])
    numbers = dict(L=p1[0] - p0[0], T=p1[1] - p0[1], E=float(s["youngs_modulus"]),
                   nu=float(s["poisson_ratio"]), rho_s=float(s["density"]),
                   rho_w=float(f["density"]), H=w1[1] - w0[1], g=abs(vec(s["gravity"])[1]))
    bending, with_shear = fe_clamped_plate.plate_formulas(**numbers)
    return bending, with_shear, fe_clamped_plate.midspan_deflection(**numbers), numbers["T"]


def summary(run):
    case = fsi_results.read_case(run)
    delta, delta_shear, delta_fe, T = references(case)
    dx = float(case["solid"]["spacing"])
    pr = fsi_results.read_probes(run)
    t, uy = pr["time"], pr["mid_uy"]
    t_end = t[-1]
    late = [u for tt, u in zip(t, uy) if tt >= 0.5 * t_end]
    settled = -sum(late) / len(late) if late else float("nan")
    windows = fsi_results.log_match(os.path.join(run, "run.log"), r"\nwindows = (\d+)")
    substeps = fsi_results.log_match(os.path.join(run, "solid.log"), r"performance: (\d+) sub-steps")
    n_fluid = fsi_results.log_match(os.path.join(run, "fluid.log"), r"\((\d+) fluid in")
    n_solid = fsi_results.log_match(os.path.join(run, "solid.log"), r"\] (\d+) particles")
    wall = fsi_results.wall_time(run)
    return dict(run=run, T_over_dx=T / dx, dx=dx, delta=delta, delta_shear=delta_shear,
                delta_fe=delta_fe, settled=settled,
                swing=(max(late) - min(late)) / 2 if late else float("nan"), t=t, uy=uy,
                t_end=t_end, windows=windows, substeps=substeps, n_fluid=n_fluid,
                n_solid=n_solid, wall=wall, finished=wall is not None)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--png", required=True)
    ap.add_argument("--md", required=True)
    ap.add_argument("runs", nargs="+")
    a = ap.parse_args()
    rows = [summary(r) for r in a.runs if os.path.exists(os.path.join(r, "probes.csv"))]
    with open(a.md, "w") as md:
        md.write("| T / dx | dx | fluid / solid particles | end | windows | solid sub-steps per "
                 "window | settled deflection | error (plate theory) | error (with shear) | error (2D "
                 "elasticity) | swing (half range) | wall time |\n")
        md.write("| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |\n")
        for r in rows:
            per = (int(r["substeps"]) / int(r["windows"])
                   if r["substeps"] and r["windows"] else float("nan"))
            md.write("| %.0f | %.4g m | %s / %s | %s | %s | %.1f | %.2f um | %+.2f %% | %+.2f %% "
                     "| %+.2f %% | %.2f um | %s |\n" % (r["T_over_dx"], r["dx"], r["n_fluid"], r["n_solid"],
                                   "t = %.3g s" % r["t_end"] if r["finished"]
                                   else "stopped at t = %.3g s" % r["t_end"],
                                   r["windows"] or "?", per, 1e6 * r["settled"],
                                   100 * (r["settled"] / r["delta"] - 1),
                                   100 * (r["settled"] / r["delta_shear"] - 1),
                                   100 * (r["settled"] / r["delta_fe"] - 1), 1e6 * r["swing"],
                                   "%.1f s" % r["wall"] if r["wall"] else "?"))
        if rows:
            md.write("\nPlate theory (003 Eq. 53): %.2f um; with the shear deflection of a "
                     "Timoshenko beam: %.2f um; 2D plane-strain elasticity with fully clamped "
                     "ends (finite elements): %.2f um; settled = mean of -u_y over the second "
                     "half of the run.\n" % (1e6 * rows[0]["delta"], 1e6 * rows[0]["delta_shear"],
                                             1e6 * rows[0]["delta_fe"]))
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(7, 4))
    for r in rows:
        ax.plot(r["t"], [-1e6 * u for u in r["uy"]], lw=1,
                label="T/dx = %.0f (settled %.1f um)" % (r["T_over_dx"], 1e6 * r["settled"]))
    if rows:
        ax.axhline(1e6 * rows[0]["delta"], color="k", ls="--",
                   label="plate theory %.1f um" % (1e6 * rows[0]["delta"]))
        ax.axhline(1e6 * rows[0]["delta_shear"], color="k", ls=":",
                   label="with shear (Timoshenko) %.1f um" % (1e6 * rows[0]["delta_shear"]))
        ax.axhline(1e6 * rows[0]["delta_fe"], color="C3", ls="-.",
                   label="2D elasticity (finite elements) %.1f um" % (1e6 * rows[0]["delta_fe"]))
    ax.set_xlabel("t [s]")
    ax.set_ylabel("mid-span deflection -u_y [um]")
    combos = sorted({fsi_results.solvers(r) for r in a.runs
                     if os.path.exists(os.path.join(r, "probes.csv"))})
    ax.set_title("C4 water column on an aluminium plate (%s)" % ", ".join(combos))
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(a.png, dpi=120)


if __name__ == "__main__":
    main()
