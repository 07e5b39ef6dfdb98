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
measure and drawn in grey.
"""
import argparse

import h5py
import numpy as np


MIRRORED = 4   # SOLID_MIRRORED, solid_solver/solid_particles.h


def material(path):
    """Mask of the solid's material points (not mirrored clamp images)."""
    with h5py.File(path, "r") as f:
        return (f["static/flags"][()].reshape(-1) & MIRRORED) == 0


def frames(path):
    with h5py.File(path, "r") as f:
        x0 = f["static/x0"][()]
        out = []
        for k in sorted(f["frames"].keys()):
            g = f["frames"][k]
            out.append((float(g.attrs["time"]), g["position"][()],
                        g["damage"][()].reshape(-1) if "damage" in g else np.zeros(len(x0)),
                        g["pressure"][()].reshape(-1) if "pressure" in g else None,
                        g["flags"][()].reshape(-1) if "flags" in g else None))
        return x0, out


def initiation(run, threshold):
    x0, fr = frames(run + "/solid.h5")
    initial, body = fr[0][2], material(run + "/solid.h5")
    for t, x, dmg, _, _ in fr:
        growth = np.where(body, dmg - initial, 0.0)
        i = int(np.argmax(growth))
        if growth[i] >= threshold:
            return t, x0[i], fr
    return None, None, fr


def pair(text):
    return tuple(float(v) for v in text.split(","))


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
    ap.add_argument("with_failure")
    ap.add_argument("without_failure")
    a = ap.parse_args()
    rows = []
    for label, run in (("failure = true", a.with_failure), ("failure = false", a.without_failure)):
        t0, where, fr = initiation(run, a.threshold)
        body = material(run + "/solid.h5")
        growth = (fr[-1][2] - fr[0][2])[body]
        rows.append((label, t0, where, fr[-1][0], float(growth.max()),
                     int((growth >= a.threshold).sum()), len(growth)))
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
    fig, axes = plt.subplots(2, len(a.times), figsize=(3.0 * len(a.times), 5.6), squeeze=False,
                             constrained_layout=True)
    for row, run in enumerate((a.with_failure, a.without_failure)):
        _, sfr = frames(run + "/solid.h5")
        _, ffr = frames(run + "/fluid.h5")
        for col, t in enumerate(a.times):
            ax = axes[row][col]
            s = min(sfr, key=lambda f: abs(f[0] - t))
            fl = min(ffr, key=lambda f: abs(f[0] - t))
            water = (fl[4] & 1) != 0
            near = (water & (fl[1][:, 0] > a.xlim[0]) & (fl[1][:, 0] < a.xlim[1]) &
                    (fl[1][:, 1] < a.ylim[1]))
            sc = ax.scatter(fl[1][near, 0], fl[1][near, 1], c=fl[3][near], s=3, cmap="Blues",
                            vmin=0, vmax=a.pmax)
            body = material(run + "/solid.h5")
            ax.scatter(s[1][~body, 0], s[1][~body, 1], c="0.7", s=12)
            d = ax.scatter(s[1][body, 0], s[1][body, 1], c=s[2][body], s=12, cmap="inferno_r",
                           vmin=0, vmax=1)
            ax.set_xlim(*a.xlim)
            ax.set_ylim(*a.ylim)
            ax.set_aspect("equal")
            ax.set_title("%s, t = %.2f s" % ("failure" if row == 0 else "no failure", s[0]),
                         fontsize=8)
            ax.tick_params(labelsize=6)
    fig.colorbar(d, ax=axes, shrink=0.6, label="damage (solid)")
    fig.colorbar(sc, ax=axes, shrink=0.6, label="water pressure [Pa]")
    fig.suptitle(a.title)
    fig.savefig(a.png, dpi=110)


if __name__ == "__main__":
    main()
