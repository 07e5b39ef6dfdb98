"""Accuracy against speed (docs/validation.md): one chart per scene of a run's error
against its wall-clock time, one line per solver combination, from the
accuracy_speed.csv files the scenes' bench scripts write (columns: solvers,
resolution, dx_m, particles, threads, wall_s, error). The chart is how users choose
a resolution: the cheapest point below their error goal.

    /usr/bin/python3 bench/accuracy_speed.py --title T --error-label L --png P.png CSV ...
"""
import argparse
import csv


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--title", required=True)
    ap.add_argument("--error-label", required=True)
    ap.add_argument("--goal", type=float, default=None, help="error goal, drawn as a line")
    ap.add_argument("--goal-label", default="goal", help="the goal line's legend")
    ap.add_argument("--png", required=True)
    ap.add_argument("csvs", nargs="+")
    a = ap.parse_args()
    lines = {}
    for path in a.csvs:
        with open(path, newline="") as f:
            for r in csv.DictReader(f):
                lines.setdefault(r["solvers"], []).append(r)
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    # the legend beside the axes: with many combinations it would cover their points
    fig, ax = plt.subplots(figsize=(6 if len(lines) < 4 else 8.5, 4))
    for solvers, rows in sorted(lines.items()):
        rows.sort(key=lambda r: float(r["wall_s"]))
        t = [float(r["wall_s"]) for r in rows]
        e = [100 * float(r["error"]) for r in rows]
        ax.plot(t, e, "o-", label=solvers)
        for r, tt, ee in zip(rows, t, e):
            ax.annotate(r["resolution"], (tt, ee), textcoords="offset points", xytext=(4, 4),
                        fontsize=8)
    if a.goal is not None:
        ax.axhline(100 * a.goal, color="k", ls="--", lw=1, label=a.goal_label)
    ax.set_xscale("log")
    ax.set_xlabel("wall-clock time [s] (threads as in the table)")
    ax.set_ylabel(a.error_label + " [%]")
    ax.set_title(a.title)
    if len(lines) < 4:
        ax.legend(fontsize=8)
    else:
        ax.legend(fontsize=8, loc="upper left", bbox_to_anchor=(1.01, 1.0), borderaxespad=0)
    fig.tight_layout()
    fig.savefig(a.png, dpi=120)


if __name__ == "__main__":
    main()
