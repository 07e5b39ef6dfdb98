"""Reading a run's output folder: the resolved case, probes.csv and the HDF5 frames.
Shared by the bench/ scripts (post-processing only; run with /usr/bin/python3)."""
import configparser
import csv
import os
import re


def read_case(out_dir):
    """The resolved case (case.resolved.ini) as {section: {key: text}}."""
    parser = configparser.ConfigParser(inline_comment_prefixes=(";", "#"), interpolation=None)
    parser.optionxform = str
    parser.read(os.path.join(out_dir, "case.resolved.ini"))
    return {s: dict(parser[s]) for s in parser.sections()}


def solvers(out_dir):
    """The run's solver combination from its resolved case: "ULPH + NOSB-PD", "WCSPH"."""
    case = read_case(out_dir)
    names = {"nosbpd": "NOSB-PD", "pseudo_spring": "pseudo-spring"}
    found = [case[r]["solver"] for r in ("fluid", "solid") if r in case and "solver" in case[r]]
    return " + ".join(names.get(n, n.upper()) for n in found)


def read_probes(out_dir):
    """probes.csv as {column: [floats]} (the '# units: ...' line skipped)."""
    with open(os.path.join(out_dir, "probes.csv"), newline="") as f:
        rows = list(csv.reader(line for line in f if not line.startswith("#")))
    header, data = rows[0], rows[1:]
    return {name: [float(r[i]) for r in data] for i, name in enumerate(header)}


def read_last_frame(h5_path, fields):
    """(time, {field: array}) of the last frame of a participant's HDF5 file."""
    import h5py
    with h5py.File(h5_path, "r") as f:
        frames = sorted(f["frames"].keys())
        g = f["frames"][frames[-1]]
        return float(g.attrs["time"]), {k: g[k][()] for k in fields}


def log_match(path, pattern, default=None):
    """The first group of the last match of pattern in a log file (default if the file
    or the match is missing)."""
    try:
        with open(path) as fh:
            hits = re.findall(pattern, fh.read())
    except OSError:
        return default
    return hits[-1] if hits else default


def wall_time(out_dir):
    """Wall time of a finished run from its run.log [s], or None."""
    hit = log_match(os.path.join(out_dir, "run.log"), r"exit = ok \(([0-9.]+) s wall\)")
    return float(hit) if hit else None


def particle_counts(run_dir):
    """(fluid particles, free solid points, clamped solid points) of a coupled run."""
    import h5py
    with h5py.File(os.path.join(run_dir, "fluid.h5"), "r") as f:
        n_fluid = int(((f["static/flags"][()].ravel() & 1) > 0).sum())
    with h5py.File(os.path.join(run_dir, "solid.h5"), "r") as f:
        clamped = (f["static/flags"][()].ravel() & 1) > 0
    return n_fluid, int((~clamped).sum()), int(clamped.sum())


def frame_times(h5_path):
    """The sorted times of a participant file's frames."""
    import h5py
    with h5py.File(h5_path, "r") as f:
        return sorted(float(g.attrs["time"]) for g in f["frames"].values())


def frame_at(h5, t):
    """The frame group of an open participant file whose time is nearest t."""
    import numpy as np
    frames = h5["frames"]
    keys = sorted(frames.keys())
    times = np.array([frames[k].attrs["time"] for k in keys])
    return frames[keys[int(np.argmin(np.abs(times - t)))]]


def draw_coupled_frame(ax, fluid_frame, solid_frame, clamped, size, p_max,
                       solid_values=None, solid_cmap="magma", solid_range=None):
    """Draw one frame of a coupled run on ax: walls grey, fluid coloured by pressure
    (0 .. p_max), the solid's clamped points black and its free points red, or coloured
    by solid_values (one per solid point) when given. size: marker area in points^2.
    Returns (fluid scatter, free-solid scatter) for colour bars."""
    x = fluid_frame["position"][()]
    p = fluid_frame["pressure"][()].ravel()
    fluid = (fluid_frame["flags"][()].ravel() & 1) > 0
    ax.scatter(x[~fluid, 0], x[~fluid, 1], s=size, c="0.75", marker="s", lw=0)
    fs = ax.scatter(x[fluid, 0], x[fluid, 1], s=size, c=p[fluid], cmap="viridis",
                    vmin=0.0, vmax=p_max, lw=0)
    xs = solid_frame["position"][()]
    if solid_values is None:
        ss = ax.scatter(xs[~clamped, 0], xs[~clamped, 1], s=size, c="tab:red", lw=0)
    else:
        lo, hi = solid_range if solid_range else (None, None)
        ss = ax.scatter(xs[~clamped, 0], xs[~clamped, 1], s=size, c=solid_values[~clamped],
                        cmap=solid_cmap, vmin=lo, vmax=hi, lw=0)
    ax.scatter(xs[clamped, 0], xs[clamped, 1], s=size, c="k", lw=0)
    return fs, ss


def wall_boxes(case):
    """The [fluid.wall] boxes of a case shrunk by dx / 2 on every side: a fluid particle
    whose centre is in one is deeper in the wall than the centres of its first row."""
    import numpy as np

    def vec(text):
        return np.array([float(x) for x in text.replace(",", " ").split()])
    dx = float(case["fluid"]["spacing"])
    return [(vec(case[w]["min"]) + 0.5 * dx, vec(case[w]["max"]) - 0.5 * dx)
            for w in case if w.startswith("fluid.wall")]


def fluid_in_walls(boxes, frame):
    """How many fluid particles of a fluid.h5 frame group are inside wall_boxes."""
    import numpy as np
    if not boxes:
        return 0
    x = frame["position"][()][:, :len(boxes[0][0])]
    fluid = (frame["flags"][()].ravel() & 1) > 0
    inside = np.zeros(len(x), dtype=bool)
    for lo, hi in boxes:
        inside |= np.all((x >= lo) & (x <= hi), axis=1)
    return int((inside & fluid).sum())

