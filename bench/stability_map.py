"""Stability maps (docs/stability.md): one row per fluid x solid x coupling scheme, one
column per value of the swept parameter; each cell stable and accurate, inaccurate, or
stopped, with the settled deflection's error against 2D elasticity and, for implicit
runs, the coupling iterations per window.

    /usr/bin/python3 bench/stability_map.py --axis density --png P.png --md T.md RUN_DIR ...

RUN_DIR is .../FLUID_SOLID_SCHEME/vVALUE (bench/stability_map.sh).
"""
import argparse
import os
import re

import c4_plate_under_water
import fsi_results

# The solid model's own error at the scene's T / dx = 4: the plate alone under the
# water's hydrostatic load, `bench/c4_plate_alone.sh OUT --n 4 --solver S` (74.58, 76.73
# and 86.80 um against 2D elasticity's 70.66 um). A coupled run is accurate when its
# settled deflection is within ACCURATE of what its solid gives alone: the first maps'
# 12 % from 2D elasticity for NOSB-PD, less NOSB-PD's own +5.6 %, leaves 6.5 % for the
# fluid's resolution and the coupling.
SOLID_OWN_ERROR = {"nosbpd": 0.0555, "tlsph": 0.0859, "pseudo_spring": 0.2284}
ACCURATE = 0.065
AXIS_LABEL = {"density": "solid / fluid density ratio", "stiffness": "E / 67.5 GPa",
              "safety": "step factors / defaults"}


def label(row):
    """ulph_nosbpd_plain -> "ulph + nosbpd, explicit without impedance"."""
    for tail, words in (("_serial_staggered", ", explicit"),
                        ("_plain", ", explicit without impedance"), ("_implicit", ", implicit")):
        if row.endswith(tail):
            row = row[: -len(tail)] + words
    return row.replace("_", " + ", 1)


def stop_reason(run):
    """The coupler's failure line of run.log, shortened, or None for a finished run."""
    why = fsi_results.log_match(os.path.join(run, "run.log"), r"coupler_exit = failure: (.*)")
    if why is None and not os.path.exists(os.path.join(run, "run.log")):
        return "no run.log"
    return why


def cell(run):
    group, value = os.path.split(run.rstrip("/"))
    row = os.path.basename(group)
    r = dict(row=row, value=float(value[1:]), run=run)
    r["stop"] = stop_reason(run)
    r["iterations"] = fsi_results.log_match(os.path.join(run, "run.log"),
                                            r"coupling_iterations_per_window = ([0-9.]+)")
    try:
        s = c4_plate_under_water.summary(run)
        r["error"] = s["settled"] / s["delta_fe"] - 1
        r["t_end"] = s["t_end"]
        r["wall"] = s["wall"]
    except (OSError, KeyError, ValueError, IndexError, ZeroDivisionError):
        r["error"], r["t_end"], r["wall"] = float("nan"), 0.0, None
    solid = next((k for k in SOLID_OWN_ERROR if "_%s_" % k in row + "_"), None)
    own = SOLID_OWN_ERROR.get(solid, 0.0)
    if r["stop"]:
        r["state"] = "stopped"
    elif abs(r["error"] - own) <= ACCURATE:
        r["state"] = "stable"
    else:
        r["state"] = "inaccurate"
    return r


def text(r):
    it = " (%.2f it/window)" % float(r["iterations"]) if r["iterations"] else ""
    if r["state"] == "stopped":
        return "stopped at %.3g s%s" % (r["t_end"], it)
    return "%s %+.1f %%%s" % ("ok" if r["state"] == "stable" else "inaccurate",
                              100 * r["error"], it)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--axis", required=True)
    ap.add_argument("--png", required=True)
    ap.add_argument("--md", required=True)
    ap.add_argument("runs", nargs="+")
    a = ap.parse_args()
    cells = [cell(r) for r in a.runs if os.path.isdir(r)]
    rows = list(dict.fromkeys(c["row"] for c in cells))
    values = sorted({c["value"] for c in cells}, reverse=True)
    at = {(c["row"], c["value"]): c for c in cells}
    with open(a.md, "w") as md:
        md.write("| combination, coupling | " + " | ".join("%g" % v for v in values) + " |\n")
        md.write("| --- |" + " --- |" * len(values) + "\n")
        for row in rows:
            md.write("| %s | " % label(row))
            md.write(" | ".join(text(at[(row, v)]) if (row, v) in at else "" for v in values))
            md.write(" |\n")
        md.write("\n%s across; the cells give the settled mid-span deflection's error from 2D "
                 "elasticity (bench/fe_clamped_plate.py); ok = within %.1f %% of the solid's own "
                 "error at this resolution (%s).\n\nWhy the stopped runs stopped:\n\n"
                 % (AXIS_LABEL.get(a.axis, a.axis), 100 * ACCURATE,
                    ", ".join("%s %+.1f %%" % (k, 100 * v) for k, v in SOLID_OWN_ERROR.items())))
        for c in cells:
            if c["stop"]:
                md.write("- %s, %s = %g: %s\n" % (c["row"], a.axis, c["value"],
                                                  re.sub(r"\s+", " ", c["stop"])[:400]))
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    colour = {"stable": "#4caf50", "inaccurate": "#ffc107", "stopped": "#e53935"}
    fig, ax = plt.subplots(figsize=(1.6 + 1.1 * len(values), 0.9 + 0.42 * len(rows)))
    for i, row in enumerate(rows):
        for j, v in enumerate(values):
            c = at.get((row, v))
            if not c:
                continue
            ax.add_patch(plt.Rectangle((j, i), 1, 1, color=colour[c["state"]]))
            text_in = "%.1f it" % float(c["iterations"]) if c["iterations"] else ""
            if c["state"] != "stopped":
                text_in = ("%+.0f%%" % (100 * c["error"])) + ("\n" + text_in if text_in else "")
            ax.text(j + 0.5, i + 0.5, text_in, ha="center", va="center", fontsize=7)
    ax.set_xlim(0, len(values))
    ax.set_ylim(0, len(rows))
    ax.set_xticks([j + 0.5 for j in range(len(values))])
    ax.set_xticklabels(["%g" % v for v in values])
    ax.set_yticks([i + 0.5 for i in range(len(rows))])
    ax.set_yticklabels([label(r) for r in rows], fontsize=8)
    ax.set_xlabel(AXIS_LABEL.get(a.axis, a.axis))
    ax.set_title("C4, 0.5 m of water, T/dx = 4: green stable, yellow > %.1f %% off the solid "
                 "alone, red stopped" % (100 * ACCURATE), fontsize=9)
    ax.invert_yaxis()
    fig.tight_layout()
    fig.savefig(a.png, dpi=110)


if __name__ == "__main__":
    main()
