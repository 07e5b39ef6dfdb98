#!/usr/bin/python3
"""The global quantities of a run over time (docs/output.md, "Diagnostics"): energies,
the work through the interface, the fluid's force and moment on each solid block, the
fluid particles inside the solid and the step sizes, from OUT/*_diagnostics.csv, to
OUT/diagnostics.png.

    /usr/bin/python3 launch/plot_diagnostics.py OUT      (fsi plot OUT)
"""
import csv
import glob
import os
import sys

USAGE = "usage: fsi plot OUT"


def read(path):
    """Columns of a diagnostics CSV as lists of floats, by header name."""
    with open(path) as f:
        rows = list(csv.reader(f))
    if len(rows) < 2:
        return None
    names = rows[0]
    return {name: [float(r[k]) for r in rows[1:] if len(r) == len(names)]
            for k, name in enumerate(names)}


def energy_panel(ax, data):
    """Every energy as its change from the first row: the potentials' zero is the origin
    and the fluid's compression energy at rest is far larger than what moves."""
    for who, d in data.items():
        t = d["time"]
        for key, label in (("kinetic_energy [J]", "kinetic"),
                           ("compression_energy [J]", "compression"),
                           ("strain_energy [J]", "strain"),
                           ("potential_energy [J]", "potential")):
            e = d.get(key)
            if e and any(v != e[0] for v in e):
                ax.plot(t, [v - e[0] for v in e], "--" if label == "potential" else "-",
                        label="%s %s" % (who, label))
    ax.set_ylabel("energy - initial [J]")
    ax.set_title("energy changes from the first window")


def work_panel(ax, data):
    """Work through the interface from both sides, and the solid's energy change it
    should account for (with the impedance's share)."""
    drawn = False
    for who, d in data.items():
        t = d["time"]
        for key, label in (("interface_work [J]", "interface work"),
                           ("boundary_work [J]", "work on the moving boundary"),
                           ("interface_work_at_sent [J]", "interface work at the velocity sent"),
                           ("impedance_work [J]", "impedance work"),
                           ("wall_work [J]", "moving walls' work")):
            if key in d and any(d[key]):
                ax.plot(t, d[key], label="%s %s" % (who, label))
                drawn = True
        if "strain_energy [J]" in d and "interface_work [J]" in d and any(d["interface_work [J]"]):
            e = [k + u + p for k, u, p in zip(d["kinetic_energy [J]"], d["strain_energy [J]"],
                                              d["potential_energy [J]"])]
            ax.plot(t, [v - e[0] for v in e], "k:", label="%s energy change (K + U + P)" % who)
    ax.set_ylabel("work [J]")
    ax.set_title("work through the interface" if drawn else "work through the interface (none)")


def load_panels(ax_force, ax_moment, data):
    """The fluid's force and moment (about the origin) on each solid block."""
    drawn = False
    for who, d in data.items():
        t = d["time"]
        for key in d:
            if ".force_" in key and any(d[key]):
                ax_force.plot(t, d[key], label=key.replace(" [N]", ""))
                drawn = True
            if ".moment_" in key and any(d[key]):
                ax_moment.plot(t, d[key], label=key.replace(" [N m]", ""))
    ax_force.set_ylabel("force [N]")
    ax_force.set_title("fluid force on each solid block" if drawn else "fluid force (no solid loaded)")
    ax_moment.set_ylabel("moment [N m]")
    ax_moment.set_title("fluid moment on each block, about the origin")


def inside_panel(ax, data):
    for who, d in data.items():
        if "particles_inside" in d:
            ax.step(d["time"], d["particles_inside"], where="post", label=who)
    ax.set_ylabel("particles")
    ax.set_title("fluid particles inside the solid")


def step_panel(ax, data):
    """Window, steps (log scale) and sub-steps per window."""
    window_drawn = positive = False
    for who, d in data.items():
        t = d["time"][1:]   # window 0 has length zero
        if not window_drawn and d.get("dt [s]"):
            ax.plot(t, d["dt [s]"][1:], "k-", lw=1, label="coupling window")
            window_drawn = True
        if d.get("step [s]"):
            ax.plot(t, d["step [s]"][1:], label="%s step" % who)
        positive |= any(v > 0 for v in d.get("dt [s]", []) + d.get("step [s]", []))
    if positive:
        ax.set_yscale("log")
    ax.set_ylabel("step [s]")
    ax.set_title("window and steps")


def main():
    if len(sys.argv) != 2:
        print(USAGE, file=sys.stderr)
        sys.exit(2)
    out = sys.argv[1]
    paths = sorted(glob.glob(os.path.join(out, "*_diagnostics.csv")))
    data = {}
    for path in paths:
        d = read(path)
        if d:
            data[os.path.basename(path)[:-len("_diagnostics.csv")]] = d
    if not data:
        print("fsi plot: %s: no diagnostics (fluid_diagnostics.csv, solid_diagnostics.csv: "
              "every run of our solvers writes them)" % out, file=sys.stderr)
        sys.exit(2)
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(3, 2, figsize=(12, 10), sharex=True)
    energy_panel(axes[0][0], data)
    work_panel(axes[0][1], data)
    load_panels(axes[1][0], axes[1][1], data)
    inside_panel(axes[2][0], data)
    step_panel(axes[2][1], data)
    for ax in axes.flat:
        if ax.get_legend_handles_labels()[0]:
            ax.legend(fontsize=7)
        ax.grid(alpha=0.3)
    for ax in axes[2]:
        ax.set_xlabel("time [s]")
    fig.suptitle("%s (2D: energies, work, forces per metre of thickness)" % os.path.abspath(out),
                 fontsize=9)
    fig.tight_layout()
    png = os.path.join(out, "diagnostics.png")
    tmp = png + ".tmp.png"
    fig.savefig(tmp, dpi=100)
    os.replace(tmp, png)
    print("fsi plot: %s" % png)


if __name__ == "__main__":
    main()
