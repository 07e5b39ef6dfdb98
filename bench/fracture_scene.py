"""C5 and C6 (docs/validation.md): where and when a structure's damage grows, for the
run with bond failure and the same run without it, with snapshots of water pressure
and solid damage.

    /usr/bin/python3 bench/fracture_scene.py --png P.png --md T.md [--threshold D]
        [--times T1,T2,..] [--xlim X0,X1] [--ylim Y0,Y1] [--pmax P] [--title TEXT]
        RUN_WITH_FAILURE RUN_WITHOUT

Crack initiation: the first output frame in which a point's damage (the share of its
family's volume whose bonds are broken, 000 Eq. 49) has grown by at least D since the
first frame. D = 0.5 (the default, C5: half of a point's bonds lost) or less where the
crack runs between rows of points: a point next to a straight crack through its whole
family loses about 0.3 of it (tests/unit/test_nosbpd_failure.c), so C6 uses 0.25.
Measuring growth leaves out bonds cut from the start ([solid.crack]). Mirrored clamp
points (flag 4) are images of the body, not material: they are left out of the
measure and drawn in grey. bench/c6_notch_or_foot.sh uses damage_growth too.
"""
import argparse
import os
import sys

import h5py
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import fsi_results  # noqa: E402

MIRRORED = 4   # SOLID_MIRRORED, solid_solver/solid_particles.h


def material(h5):
    """Mask of an open solid file's material points (not mirrored clamp images)."""
    return (h5["static/flags"][()].reshape(-1) & MIRRORED) == 0


def damage_growth(solid_h5_path):
    """Reference positions, material mask and, per frame, (time, damage growth since
    the first frame; 0 on mirrored clamp points)."""
    with h5py.File(solid_h5_path, "r") as f:
        x0, body = f["static/x0"][()], material(f)
        keys = sorted(f["frames"].keys())
        d0 = f["frames"][keys[0]]["damage"][()].reshape(-1)
        growth = [(float(f["frames"][k].attrs["time"]),
                   np.where(body, f["frames"][k]["damage"][()].reshape(-1) - d0, 0.0))
                  for k in keys]
    return x0, body, growth


def initiation(growth, x0, threshold):
    """(time, reference position) of the first frame with a growth >= threshold, or
    (None, None)."""
    for t, g in growth:
        i = int(np.argmax(g))
        if g[i] >= threshold:
            return t, x0[i]
    return None, None


def pair(text):
    return tuple(float(v) for v in text.split(","))


def snapshot(ax, run, t, a):
    """Water by pressure near the structure and the solid by damage, at the frames
    nearest t; returns the two scatters for colour bars."""
    with h5py.File(run + "/fluid.h5", "r") as ff, h5py.File(run + "/solid.h5", "r") as sf:
        fl, s = fsi_results.frame_at(ff, t), fsi_results.frame_at(sf, t)
        x, p = fl["position"][()], fl["pressure"][()].reshape(-1)
        water = (fl["flags"][()].reshape(-1) & 1) != 0
        near = water & (x[:, 0] > a.xlim[0]) & (x[:, 0] < a.xlim[1]) & (x[:, 1] < a.ylim[1])
        sc = ax.scatter(x[near, 0], x[near, 1], c=p[near], s=3, cmap="Blues", vmin=0,
                        vmax=a.pmax)
        xs, dmg, body = s["position"][()], s["damage"][()].reshape(-1), material(sf)
        ax.scatter(xs[~body, 0], xs[~body, 1], c="0.7", s=12)
        d = ax.scatter(xs[body, 0], xs[body, 1], c=dmg[body], s=12, cmap="inferno_r", vmin=0,
                       vmax=1)
        ax.set_title("%s, t = %.2f s" % (a.label, s.attrs["time"]), fontsize=8)
    return sc, d


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--png", required=True)
    ap.add_argument("--md", required=True)
    ap.add_argument("--threshold", type=float, default=0.5)
    ap.add_argument("--times", type=pair, default=(0.16, 0.20, 0.26, 0.32))
    ap.add_argument("--xlim", type=pair, default=(0.2, 0.4))
    ap.add_argument("--ylim", type=pair, default=(-0.015, 0.15))
    ap.add_argument("--pmax", type=float, default=4000.0)
    ap.add_argument("--title", default="C5 dam break against a Drucker-Prager baffle (ULPH + NOSB-PD)")
    ap.add_argument("--also", action="append", default=[], metavar="LABEL=RUN_DIR",
                    help="a further run, a row of the table and of the plot")
    ap.add_argument("with_failure")
    ap.add_argument("without_failure")
    a = ap.parse_args()
    runs = [("failure = true", a.with_failure), ("failure = false", a.without_failure)]
    runs += [tuple(extra.rsplit("=", 1)) for extra in a.also]
    rows = []
    for label, run in runs:
        x0, body, growth = damage_growth(run + "/solid.h5")
        t0, where = initiation(growth, x0, a.threshold)
        t_end, last = growth[-1]
        rows.append((label, t0, where, t_end, float(last[body].max()),
                     int((last[body] >= a.threshold).sum()), int(body.sum())))
    with open(a.md, "w") as md:
        md.write("| run | crack initiation (first frame with damage grown by >= %g) | where "
                 "(reference position) | end | largest damage growth at the end | material "
                 "points with damage grown by >= %g |\n| --- | --- | --- | --- | --- | --- |\n"
                 % (a.threshold, a.threshold))
        for label, t0, where, t_end, dmax, nbroken, n in rows:
            md.write("| %s | %s | %s | t = %.3g s | %.2f | %d of %d |\n" % (
                label, "t = %.3f s" % t0 if t0 is not None else "none",
                "(%.4f, %.4f) m" % tuple(where[:2]) if where is not None else "-", t_end, dmax,
                nbroken, n))
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(len(runs), len(a.times), figsize=(3.0 * len(a.times), 2.8 * len(runs)),
                             squeeze=False, constrained_layout=True)
    for row, (label, run) in enumerate(runs):
        a.label = ("failure", "no failure")[row] if row < 2 else label
        for col, t in enumerate(a.times):
            ax = axes[row][col]
            sc, d = snapshot(ax, run, t, a)
            ax.set_xlim(*a.xlim)
            ax.set_ylim(*a.ylim)
            ax.set_aspect("equal")
            ax.tick_params(labelsize=6)
            if row == len(runs) - 1:
                ax.set_xlabel("x [m]", fontsize=8)
            if col == 0:
                ax.set_ylabel("y [m]", fontsize=8)
    fig.colorbar(d, ax=axes, shrink=0.6, label="solid damage [-]")
    fig.colorbar(sc, ax=axes, shrink=0.6, label="water pressure [Pa]")
    fig.suptitle(a.title)
    fig.savefig(a.png, dpi=110)


if __name__ == "__main__":
    main()
