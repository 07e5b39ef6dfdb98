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


UNITS = {}    # column name -> unit, from the files' "# units:" lines


def read(path):
    """Columns of a diagnostics CSV as lists of floats, by header name; the units of the
    second line ("# units: s,...") go to UNITS."""
    with open(path) as f:
        lines = f.read().splitlines()
    if not lines:
        return None
    names = lines[0].split(",")
    units = [l for l in lines[1:] if l.startswith("# units:")]
    if units:
        UNITS.update(zip(names, units[0][len("# units:"):].strip().split(",")))
    rows = list(csv.reader(l for l in lines[1:] if not l.startswith("#")))
    if not rows:
        return None
    return {name: [float(r[k]) for r in rows if len(r) == len(names)]
            for k, name in enumerate(names)}


def unit(name, fallback):
    """The unit a file declared for column name."""
    return UNITS.get(name, fallback)


def energy_panel(ax, data):
    """Every energy as its change from the first row: the potentials' zero is the origin
    and the fluid's compression energy at rest is far larger than what moves."""
    for who, d in data.items():
        t = d["time"]
        for key, label in (("kinetic_energy", "kinetic"),
                           ("compression_energy", "compression"),
                           ("strain_energy", "strain"),
                           ("potential_energy", "potential")):
            e = d.get(key)
            if e and any(v != e[0] for v in e):
                ax.plot(t, [v - e[0] for v in e], "--" if label == "potential" else "-",
                        label="%s %s" % (who, label))
    ax.set_ylabel("energy - initial [%s]" % unit("kinetic_energy", "J"))
    ax.set_title("energy changes from the first window")


def work_panel(ax, data):
    """Work through the interface from both sides, and the solid's energy change it
    should account for (with the impedance's share)."""
    drawn = False
    for who, d in data.items():
        t = d["time"]
        for key, label in (("interface_work", "interface work"),
                           ("boundary_work", "work on the moving boundary"),
                           ("interface_work_at_sent", "interface work at the velocity sent"),
                           ("impedance_work", "impedance work"),
                           ("wall_work", "moving walls' work")):
            if key in d and any(d[key]):
                ax.plot(t, d[key], label="%s %s" % (who, label))
                drawn = True
        if "strain_energy" in d and "interface_work" in d and any(d["interface_work"]):
            e = [k + u + p for k, u, p in zip(d["kinetic_energy"], d["strain_energy"],
                                              d["potential_energy"])]
            ax.plot(t, [v - e[0] for v in e], "k:", label="%s energy change (K + U + P)" % who)
    ax.set_ylabel("work [%s]" % unit("interface_work", "J"))
    ax.set_title("work through the interface" if drawn else "work through the interface (none)")


def load_panels(ax_force, ax_moment, data):
    """The fluid's force and moment (about the origin) on each solid block."""
    drawn = False
    for who, d in data.items():
        t = d["time"]
        for key in d:
            if ".force_" in key and any(d[key]):
                ax_force.plot(t, d[key], label=key)
                drawn = True
            if ".moment_" in key and any(d[key]):
                ax_moment.plot(t, d[key], label=key)
    ax_force.set_ylabel("force [%s]" % next((u for k, u in UNITS.items() if ".force_" in k), "N"))
    ax_force.set_title("fluid force on each solid block" if drawn else "fluid force (no solid loaded)")
    ax_moment.set_ylabel("moment [%s]" % next((u for k, u in UNITS.items() if ".moment_" in k), "N m"))
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
        if not window_drawn and d.get("dt"):
            ax.plot(t, d["dt"][1:], "k-", lw=1, label="coupling window")
            window_drawn = True
        if d.get("step"):
            ax.plot(t, d["step"][1:], label="%s step" % who)
        positive |= any(v > 0 for v in d.get("dt", []) + d.get("step", []))
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
