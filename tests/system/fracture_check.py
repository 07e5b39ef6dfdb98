"""Checks the crack of a notched-plate run (cases/s4_notched_plate.ini) from its output.

  fracture_check.py cracked OUT [--threshold 0.3] [--expect-line Y] [--expect-tip X]
  fracture_check.py intact OUT

OUT is an fsi-run output folder (solid.h5, case.resolved.ini). The geometry comes from
the resolved case: the spacing, the horizon, the notch (the region with
action = remove: its end at max x is the notch tip, its mid-line the notch line) and
the plate's far edge (largest block max x). --expect-line and --expect-tip replace the
notch line and tip, only to check by hand that the checks can fail.

cracked: failure on. The crack starts at the notch tip before anywhere else, the
damaged points lie along the ray from the tip along the notch line, and the crack has
cut the ligament.
intact: failure off. No damage in any frame, the run reached end_time, and the plate
was stretched beyond the critical stretch at the notch tip (so the absence of damage
is the switch's doing, not a too small load).
onset CRACKED INTACT: the first bond breaks when the critical stretch is reached. The
two runs are the same until a bond breaks, so the time at which the intact run's bond
across the notch line at the tip reaches s0 (interpolated between its frames) must fall
between the cracked run's last frame without damage and its first frame with damage,
to a quarter of a frame interval (the stretch there grows by about 2 % of s0 per
frame of 1 us: a critical stretch 10 % off moves the break by 4 frames).

Prints one ok: or FAIL: line per check and a few measured numbers; exits 1 if any
check failed. Needs h5py and numpy (/usr/bin/python3 on Debian).
"""
import argparse
import configparser
import math
import os
import sys

import h5py
import numpy as np

failures = []


def check(condition, what):
    if condition:
        print("ok: " + what, flush=True)
    else:
        failures.append(what)
        print("FAIL: " + what, file=sys.stderr, flush=True)


def vector(text):
    return [float(v) for v in text.split(",")]


def read_case(out):
    """Geometry and failure keys of the resolved case of a run."""
    ini = configparser.ConfigParser(inline_comment_prefixes=(";",), interpolation=None)
    ini.optionxform = str
    ini.read(os.path.join(out, "case.resolved.ini"))
    solid = ini["solid"]
    model = ini["solid." + solid["solver"]]     # the model's own keys
    g = {
        "dx": float(solid["spacing"]),
        "horizon": float(model["horizon_factor"]) * float(solid["spacing"]),
        "E": float(solid["youngs_modulus"]),
        "G0": float(model["fracture_energy"]),
        "s0_key": float(model["critical_stretch"]),
        "plane": solid["plane"],
        "end_time": float(ini["run"]["end_time"]),
    }
    notches = [s for s in ini.sections()
               if s.startswith("solid.region ") and ini[s]["action"] == "remove"]
    if len(notches) != 1:
        sys.exit("fracture_check: expected exactly one removed region (the notch), found %d"
                 % len(notches))
    lo, hi = vector(ini[notches[0]]["min"]), vector(ini[notches[0]]["max"])
    g["tip"] = (hi[0], 0.5 * (lo[1] + hi[1]))
    g["far_edge"] = max(vector(ini[s]["max"])[0] for s in ini.sections()
                        if s.startswith("solid.block "))
    return g


def critical_stretch(g):
    """s0 as the model takes it (docs/nosbpd.md, Failure): critical_stretch when > 0,
    else from the fracture energy with the 2D form of the plane."""
    if g["s0_key"] > 0:
        return g["s0_key"]
    if g["plane"] == "stress":
        return math.sqrt(4 * math.pi * g["G0"] / (9 * g["E"] * g["horizon"]))
    return math.sqrt(5 * math.pi * g["G0"] / (12 * g["E"] * g["horizon"]))


def frames(h5):
    """(time, group) of every frame in time order."""
    groups = [h5["frames"][k] for k in sorted(h5["frames"].keys())]
    return [(float(gr.attrs["time"]), gr) for gr in groups]


def damage_of(group):
    if "damage" not in group:
        return None
    return group["damage"][:]


def check_cracked(out, args):
    g = read_case(out)
    dx = g["dx"]
    tip = np.array([args.expect_tip if args.expect_tip is not None else g["tip"][0],
                    args.expect_line if args.expect_line is not None else g["tip"][1]])
    ligament = g["far_edge"] - g["tip"][0]
    thr = args.threshold
    with h5py.File(os.path.join(out, "solid.h5"), "r") as h5:
        x0 = h5["static/x0"][:]
        series = frames(h5)
        damages = [damage_of(gr) for _, gr in series]
        check(all(d is not None for d in damages), "damage written in all %d frames"
              % len(series))
        if any(d is None for d in damages):
            return
        check(all(np.all(np.isfinite(d)) and d.min() >= 0 and d.max() <= 1
                  for d in damages), "damage finite and within 0..1 in every frame")
        times = [t for t, _ in series]

    def distance_to_tip(points):
        return np.hypot(points[:, 0] - tip[0], points[:, 1] - tip[1])

    def distance_to_path(points):
        """Distance to the ray from the tip along +x (the crack's expected path)."""
        along = points[:, 0] >= tip[0]
        return np.where(along, np.abs(points[:, 1] - tip[1]), distance_to_tip(points))

    print("notch tip (%.6g, %.6g) m, ligament %.6g m, spacing %.6g m, horizon %.6g m"
          % (tip[0], tip[1], ligament, dx, g["horizon"]))

    # The very first broken bonds: a bond breaks at both its ends at once, so the points
    # that first show any damage are its two ends. They must sit at the tip, where the
    # stress concentrates: within one horizon (the longest bond) of it.
    first_any = next((k for k, d in enumerate(damages) if d.max() > 0), None)
    check(first_any is not None, "some bond broke (failure on)")
    if first_any is None:
        return
    pts = x0[damages[first_any] > 0]
    far = distance_to_tip(pts).max()
    print("first broken bonds at t = %.6g s: %d points, farthest %.3g spacings from the tip"
          % (times[first_any], len(pts), far / dx))
    check(far <= g["horizon"] + 1e-9,
          "first broken bonds at the notch tip (all %d damaged points within one horizon "
          "of it, farthest %.2f spacings)" % (len(pts), far / dx))

    # Crack points: damage above the threshold. A point next to a straight crack face
    # loses the bonds that cross the crack: on the lattice with horizon 3 dx, 11 of its 28
    # bonds (0.39) for the row touching the crack, 6 of 28 (0.21) for the next row, 1 of
    # 28 for the third. 0.3 separates the points on the crack faces from the halo of
    # partly damaged points around them.
    first_crack = next((k for k, d in enumerate(damages) if d.max() > thr), None)
    check(first_crack is not None, "some point damaged above %g" % thr)
    if first_crack is None:
        return
    pts = x0[damages[first_crack] > thr]
    far = distance_to_tip(pts).max()
    print("crack initiation (damage > %g) at t = %.6g s: %d points, e.g. (%.6g, %.6g) m"
          % (thr, times[first_crack], len(pts), pts[0, 0], pts[0, 1]))
    check(far <= 2 * dx + 1e-9,
          "first crack points (damage > %g) at the notch tip: all %d within 2 spacings of "
          "it (farthest %.2f), none anywhere else" % (thr, len(pts), far / dx))

    # Path and length at the end.
    final = damages[-1]
    pts = x0[final > thr]
    deviation = distance_to_path(pts).max()
    length = pts[:, 0].max() - tip[0]
    print("end t = %.6g s: %d crack points, largest distance from the path %.3g spacings, "
          "crack length %.6g m (%.0f %% of the ligament)"
          % (times[-1], len(pts), deviation / dx, length, 100 * length / ligament))
    check(deviation <= 2 * dx + 1e-9,
          "crack along the notch line: every point with damage > %g within 2 spacings of "
          "the ray from the tip (largest %.2f)" % (thr, deviation / dx))
    # Under a held load the stress intensity of an edge crack grows with its length:
    # once started the crack cannot arrest, so by the end it must have cut the ligament
    # (reached the last column of points, within 2 spacings of the far edge).
    check(length >= ligament - 2 * dx,
          "crack through the ligament: length %.4g m >= ligament - 2 spacings = %.4g m"
          % (length, ligament - 2 * dx))

    # Crack-tip history for the record (not checked): when the tip passed half the
    # ligament and the far edge, and the mean speed in between.
    def tip_x(d):
        on = (d > thr) & (np.abs(x0[:, 1] - tip[1]) <= 2 * dx)
        return x0[on, 0].max() - tip[0] if on.any() else 0.0
    history = [tip_x(d) for d in damages]
    t_half = next((t for t, a in zip(times, history) if a >= 0.5 * ligament), None)
    t_full = next((t for t, a in zip(times, history) if a >= ligament - dx), None)
    if t_half is not None and t_full is not None and t_full > t_half:
        print("crack tip at half the ligament at t = %.6g s, at the far edge at t = %.6g s: "
              "mean speed %.0f m/s over the second half"
              % (t_half, t_full, (history[times.index(t_full)] -
                                  history[times.index(t_half)]) / (t_full - t_half)))


def check_intact(out, args):
    g = read_case(out)
    with h5py.File(os.path.join(out, "solid.h5"), "r") as h5:
        x0 = h5["static/x0"][:]
        series = frames(h5)
        damages = [damage_of(gr) for _, gr in series]
        check(all(d is not None for d in damages), "damage written in all %d frames"
              % len(series))
        worst = max((float(d.max()) for d in damages if d is not None), default=0.0)
        check(worst == 0.0, "no point damaged in any frame (largest damage %g)" % worst)
        t_end = series[-1][0]
        check(abs(t_end - g["end_time"]) <= 1e-9 * g["end_time"],
              "run reached end_time: last frame at t = %.6g s" % t_end)
        # The pair of points straddling the notch line just ahead of the tip: its
        # stretch at the end, against the critical stretch the same case would break at.
        top, bottom = tip_pair(x0, g)
        x = series[-1][1]["position"][:]
        stretch = np.linalg.norm(x[top] - x[bottom]) / np.linalg.norm(x0[top] - x0[bottom]) - 1
    s0 = critical_stretch(g)
    check(stretch > s0, "loaded past failure: stretch across the notch line at the tip %.3g "
          "> critical stretch %.3g (%.1f times)" % (stretch, s0, stretch / s0))


def tip_pair(x0, g):
    """The two points straddling the notch line just ahead of the tip: the bond that
    breaks first."""
    dx, tip = g["dx"], np.array(g["tip"])
    top = np.argmin(np.hypot(x0[:, 0] - tip[0] - dx / 2, x0[:, 1] - tip[1] - dx / 2))
    bottom = np.argmin(np.hypot(x0[:, 0] - tip[0] - dx / 2, x0[:, 1] - tip[1] + dx / 2))
    return top, bottom


def check_onset(cracked, intact):
    g = read_case(cracked)
    s0 = critical_stretch(g)
    with h5py.File(os.path.join(cracked, "solid.h5"), "r") as h5:
        series = frames(h5)
        first = next((k for k, (_, gr) in enumerate(series) if gr["damage"][:].max() > 0), None)
        check(first is not None and first > 0, "the cracked run has frames before and after "
              "its first broken bond")
        if first is None or first == 0:
            return
        t_before, t_after = series[first - 1][0], series[first][0]
    with h5py.File(os.path.join(intact, "solid.h5"), "r") as h5:
        x0 = h5["static/x0"][:]
        top, bottom = tip_pair(x0, g)
        length0 = np.linalg.norm(x0[top] - x0[bottom])
        history = [(t, np.linalg.norm(gr["position"][top] - gr["position"][bottom]) / length0 - 1)
                   for t, gr in frames(h5)]
    crossing = next((k for k in range(1, len(history)) if history[k][1] >= s0), None)
    check(crossing is not None, "the intact run's tip bond reaches s0 = %.4g" % s0)
    if crossing is None:
        return
    (ta, sa), (tb, sb) = history[crossing - 1], history[crossing]
    t_s0 = ta + (s0 - sa) / (sb - sa) * (tb - ta)
    slack = 0.25 * (t_after - t_before)
    print("tip bond reaches s0 = %.4g at t = %.4g us (intact run); first broken bond between "
          "%.4g and %.4g us (cracked run)" % (s0, 1e6 * t_s0, 1e6 * t_before, 1e6 * t_after))
    check(t_before - slack <= t_s0 <= t_after + slack,
          "first bond breaks when its stretch reaches s0: at %.4g us, the stretch reaches s0 "
          "at %.4g us (the break is off by %.1f frames: is the critical stretch the model "
          "uses s0 = %.4g?)" % (1e6 * t_after, 1e6 * t_s0,
                                max(t_before - t_s0, t_s0 - t_after, 0) / (t_after - t_before),
                                s0))


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("mode", choices=["cracked", "intact", "onset"])
    p.add_argument("out")
    p.add_argument("intact_out", nargs="?", help="onset: the intact run's folder")
    p.add_argument("--threshold", type=float, default=0.3)
    p.add_argument("--expect-line", type=float, default=None)
    p.add_argument("--expect-tip", type=float, default=None)
    args = p.parse_args()
    if args.mode == "onset":
        check_onset(args.out, args.intact_out)
    else:
        (check_cracked if args.mode == "cracked" else check_intact)(args.out, args)
    if failures:
        print("fracture_check: %d check(s) failed" % len(failures), file=sys.stderr)
        sys.exit(1)


if __name__ == "__main__":
    main()
