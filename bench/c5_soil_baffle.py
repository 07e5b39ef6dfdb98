"""C5 (docs/validation.md): where and when the baffle's damage grows, for the run with
bond failure and the same run without it, with snapshots of water pressure and
baffle damage.

    /usr/bin/python3 bench/c5_soil_baffle.py --png P.png --md T.md RUN_WITH_FAILURE RUN_WITHOUT

Crack initiation: the first output frame in which a point of the baffle has lost half
of its bonds (damage >= 0.5), the damage measure of 000 Eq. 49.
"""
import argparse

import h5py
import numpy as np

TIMES = (0.16, 0.20, 0.26, 0.32)


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


def initiation(run):
    x0, fr = frames(run + "/solid.h5")
    for t, x, dmg, _, _ in fr:
        i = int(np.argmax(dmg))
        if dmg[i] >= 0.5:
            return t, x0[i], fr
    return None, None, fr


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--png", required=True)
    ap.add_argument("--md", required=True)
    ap.add_argument("with_failure")
    ap.add_argument("without_failure")
    a = ap.parse_args()
    rows = []
    for label, run in (("failure = true", a.with_failure), ("failure = false", a.without_failure)):
        t0, where, fr = initiation(run)
        last = fr[-1]
        rows.append((label, run, t0, where, last[0], float(last[2].max()), int((last[2] >= 0.5).sum()), len(last[2])))
    with open(a.md, "w") as md:
        md.write("| run | crack initiation (first frame with damage >= 0.5) | where (reference position) "
                 "| end | largest damage at the end | points with damage >= 0.5 |\n"
                 "| --- | --- | --- | --- | --- | --- |\n")
        for label, run, t0, where, t_end, dmax, nbroken, n in rows:
            md.write("| %s | %s | %s | t = %.3g s | %.2f | %d of %d |\n" % (
                label, "t = %.3f s" % t0 if t0 is not None else "none",
                "(%.3f, %.3f) m" % tuple(where[:2]) if where is not None else "-", t_end, dmax,
                nbroken, n))
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(2, len(TIMES), figsize=(3.0 * len(TIMES), 5.6), squeeze=False,
                             constrained_layout=True)
    for row, run in enumerate((a.with_failure, a.without_failure)):
        _, sfr = frames(run + "/solid.h5")
        _, ffr = frames(run + "/fluid.h5")
        for col, t in enumerate(TIMES):
            ax = axes[row][col]
            s = min(sfr, key=lambda f: abs(f[0] - t))
            fl = min(ffr, key=lambda f: abs(f[0] - t))
            water = (fl[4] & 1) != 0
            near = water & (np.abs(fl[1][:, 0] - 0.298) < 0.1) & (fl[1][:, 1] < 0.16)
            sc = ax.scatter(fl[1][near, 0], fl[1][near, 1], c=fl[3][near], s=3, cmap="Blues",
                            vmin=0, vmax=4000)
            d = ax.scatter(s[1][:, 0], s[1][:, 1], c=s[2], s=12, cmap="inferno_r", vmin=0, vmax=1)
            ax.set_xlim(0.2, 0.4)
            ax.set_ylim(-0.015, 0.15)
            ax.set_aspect("equal")
            ax.set_title("%s, t = %.2f s" % ("failure" if row == 0 else "no failure", s[0]),
                         fontsize=8)
            ax.tick_params(labelsize=6)
    fig.colorbar(d, ax=axes, shrink=0.6, label="damage (baffle)")
    fig.colorbar(sc, ax=axes, shrink=0.6, label="water pressure [Pa]")
    fig.suptitle("C5 dam break against a Drucker-Prager baffle (ULPH + NOSB-PD)")
    fig.savefig(a.png, dpi=110)


if __name__ == "__main__":
    main()
