#!/usr/bin/python3
"""fsi view: the fluid and solid particles of a run's output folder, drawn together
(docs/output.md, "fsi view").

    fsi view OUT [--time T[,T...] | --frames] [--field NAME] [--movie] [--fps N]
                 [--out FILE]

Reads OUT/P.h5 of every participant P with frames (h5py) and draws one frame, several
frames side by side (--time 0.2,0.3,0.4), one PNG per frame (--frames) or those PNGs
and a GIF (--movie) with matplotlib's Agg backend. Each participant is coloured by the
field with its own colour bar (quantity and unit); a participant without the field is
drawn in a neutral grey, as are the fluid's wall particles and the solid's mirrored
clamp points. Exit status 0, or 2 with a message for bad arguments or a folder
without particle output.
"""
import argparse
import configparser
import math
import os
import sys

PROG = "fsi view"
FIELDS = ("pressure", "velocity", "displacement", "stress", "damage")
# Unit of each field when its dataset does not carry a "unit" attribute.
UNITS = {"pressure": "Pa", "velocity": "m/s", "displacement": "m", "stress": "Pa",
         "damage": "-"}
# Without --field each participant shows the first of these it has.
DEFAULT_ORDER = ("pressure", "displacement", "velocity", "damage", "stress")
COMPONENTS = "xyz"
# Particle kinds drawn grey (flags bits, fluid_solver/fluid_particles.h and
# solid_solver/solid_particles.h) or not at all.
FLUID_WALL, FLUID_MOVING_BOUNDARY = 2, 4
SOLID_MIRRORED = 4
NEUTRAL = {"fluid": "0.72", "solid": "0.45"}
WALL_GREY = "0.55"
COLOUR_MAPS = {"fluid": "Blues", "solid": "YlOrRd"}
DIVERGING_MAP = "coolwarm"


class UsageError(Exception):
    """Bad arguments or an output folder that cannot be viewed: exit status 2."""


def die(message):
    print("%s: %s" % (PROG, message), file=sys.stderr)
    sys.exit(2)


def parse_times(text):
    """--time's list of times [s]."""
    try:
        times = [float(v) for v in text.split(",")]
    except ValueError:
        raise UsageError("--time %s: expected a time in seconds or a comma-separated "
                         "list of them (0.2,0.3,0.4)" % text)
    if not times or any(not math.isfinite(t) for t in times):
        raise UsageError("--time %s: expected finite times in seconds" % text)
    return times


def parse_field(text):
    """(base field, component index or None) of --field NAME or NAME_C (velocity_x,
    stress_xy); a tensor component's index is row-major."""
    if text in FIELDS:
        return text, None
    base, _, comp = text.rpartition("_")
    if base in ("velocity", "displacement") and len(comp) == 1 and comp in COMPONENTS:
        return base, COMPONENTS.index(comp)
    if base == "stress" and len(comp) == 2 and all(c in COMPONENTS for c in comp):
        return base, comp
    raise UsageError("unknown field '%s' (one of %s; a component as velocity_x, "
                     "displacement_y, stress_xy)" % (text, ", ".join(FIELDS)))


def parse_args(argv):
    ap = argparse.ArgumentParser(prog=PROG, description=__doc__.split("\n\n")[0])
    ap.add_argument("out", metavar="OUT", help="a run's output folder")
    when = ap.add_mutually_exclusive_group()
    when.add_argument("--time", help="the frame nearest this time [s] (default: the "
                      "last frame); a comma-separated list draws one panel per time")
    when.add_argument("--frames", action="store_true", help="one PNG per frame")
    ap.add_argument("--field", help="pressure, velocity, displacement, stress (von Mises) "
                    "or damage, or a component (velocity_x, stress_xy); default: "
                    "pressure, else displacement, else velocity, per participant")
    ap.add_argument("--movie", action="store_true", help="one PNG per frame and a GIF")
    ap.add_argument("--fps", type=float, default=10.0, help="frames per second of the "
                    "GIF (default 10)")
    ap.add_argument("--out", dest="file", help="the PNG (default OUT/view.png), the "
                    "frames' folder with --frames (default OUT/view_frames), the GIF with "
                    "--movie (default OUT/view.gif, frames in its name + _frames)")
    try:
        a = ap.parse_args(argv)
    except SystemExit as e:
        sys.exit(0 if e.code == 0 else 2)
    if a.movie and a.time is not None:
        raise UsageError("--movie draws every frame; it does not take --time")
    if not (a.fps > 0 and math.isfinite(a.fps)):
        raise UsageError("--fps %g: expected a positive number" % a.fps)
    a.times = parse_times(a.time) if a.time is not None else None
    a.field_spec = parse_field(a.field) if a.field else None
    return a


class Participant:
    """One participant's output file: its name, open h5py file, frames as (time, key)
    sorted by time, and its particle spacing [m]."""

    def __init__(self, name, h5, frames, spacing):
        self.name, self.h5, self.frames, self.spacing = name, h5, frames, spacing

    def frame(self, key):
        return self.h5["frames"][key]

    def nearest(self, t):
        """(time, key) of the frame nearest t."""
        return min(self.frames, key=lambda f: abs(f[0] - t))


def read_case(out):
    """OUT/case.resolved.ini, or None when missing or unreadable."""
    parser = configparser.ConfigParser(inline_comment_prefixes=(";", "#"), interpolation=None)
    try:
        return parser if parser.read(os.path.join(out, "case.resolved.ini")) else None
    except configparser.Error:
        return None


def spacing_of(name, h5, case, positions):
    """The participant's particle spacing [m]: the case's [P] spacing, else the solid's
    reference volume dx^D, else the median nearest-neighbour distance."""
    import numpy as np
    if case is not None and case.has_option(name, "spacing"):
        try:
            return float(case.get(name, "spacing"))
        except ValueError:
            pass
    if "static" in h5 and "volume" in h5["static"]:
        vol = h5["static"]["volume"][()].reshape(-1)
        if vol.size and vol[0] > 0:
            return float(np.median(vol)) ** (1.0 / positions.shape[1])
    if len(positions) < 2:
        return 1.0
    from scipy.spatial import cKDTree
    d, _ = cKDTree(positions).query(positions, k=2)
    return float(np.median(d[:, 1])) or 1.0


def open_participants(out):
    """Every participant of OUT with at least one frame, fluid first and solid last
    (drawn on top)."""
    import h5py
    if not os.path.isdir(out):
        raise UsageError("%s: not a folder (give a run's output folder)" % out)
    case = read_case(out)
    names = sorted(f[:-3] for f in os.listdir(out) if f.endswith(".h5"))
    names.sort(key=lambda n: {"fluid": 0, "solid": 2}.get(n, 1))
    found = []
    for name in names:
        try:
            h5 = h5py.File(os.path.join(out, name + ".h5"), "r")
        except OSError:
            continue
        frames = []
        if "frames" in h5:
            frames = sorted((float(h5["frames"][k].attrs["time"]), k) for k in h5["frames"])
        if not frames:
            h5.close()
            continue
        x = h5["frames"][frames[0][1]]["position"][()]
        found.append(Participant(name, h5, frames, spacing_of(name, h5, case, x)))
    if not found:
        raise UsageError("%s: no particle output (no P.h5 with frames, e.g. fluid.h5 or "
                         "solid.h5; is it a run's output folder?)" % out)
    return found


def title_of(out):
    """The case's [run] title, else the folder's name."""
    case = read_case(out)
    if case is not None and case.has_option("run", "title"):
        return case.get("run", "title").strip()
    return os.path.basename(os.path.abspath(out))


def masks(p, frame):
    """(coloured, grey) boolean masks of a frame's particles: the fluid's wall particles
    and the solid's mirrored clamp points are grey, the moving boundary particles the
    fluid writes (the solid's, seen by the fluid) are not drawn."""
    import numpy as np
    n = frame["position"].shape[0]
    grey = np.zeros(n, bool)
    hidden = np.zeros(n, bool)
    if p.name == "solid" and "static" in p.h5 and "flags" in p.h5["static"]:
        flags = p.h5["static"]["flags"][()].reshape(-1)
        if flags.size == n:
            grey = (flags & SOLID_MIRRORED) != 0
    elif "flags" in frame:
        flags = frame["flags"][()].reshape(-1)
        grey = (flags & FLUID_WALL) != 0
        hidden = (flags & FLUID_MOVING_BOUNDARY) != 0
    return ~grey & ~hidden, grey & ~hidden


def von_mises(s, dim):
    """Von Mises stress of row-major D x D stress tensors (in-plane in 2-D)."""
    import numpy as np
    s = s.reshape(-1, dim, dim)
    dev = s - np.trace(s, axis1=1, axis2=2)[:, None, None] / 3.0 * np.eye(dim)
    if dim == 2:
        # The out-of-plane normal stress is 0 (in-plane), its deviator -tr/3.
        extra = (np.trace(s, axis1=1, axis2=2) / 3.0) ** 2
    else:
        extra = 0.0
    return np.sqrt(1.5 * ((dev ** 2).sum(axis=(1, 2)) + extra))


def field_values(frame, spec):
    """(values, label) of a frame's field as one scalar per particle, or (None, None)
    when the frame has no such field. Vectors give their magnitude, the stress its von
    Mises value, unless a component is asked for."""
    import numpy as np
    base, comp = spec
    if base not in frame:
        return None, None
    ds = frame[base]
    unit = ds.attrs.get("unit", UNITS[base])
    unit = unit.decode() if isinstance(unit, bytes) else str(unit)
    v = ds[()]
    dim = frame["position"].shape[1]
    if v.ndim == 1 or (v.ndim == 2 and v.shape[1] == 1):
        return v.reshape(-1).astype(float), "%s [%s]" % (base, unit)
    if comp is None:
        if base == "stress":
            return von_mises(v, dim), "von Mises stress [%s]" % unit
        return np.linalg.norm(v, axis=1), "|%s| [%s]" % (base, unit)
    if isinstance(comp, str):
        i, j = COMPONENTS.index(comp[0]), COMPONENTS.index(comp[1])
        if i >= dim or j >= dim:
            return None, None
        return v[:, i * dim + j], "%s_%s [%s]" % (base, comp, unit)
    if comp >= v.shape[1]:
        return None, None
    return v[:, comp], "%s_%s [%s]" % (base, COMPONENTS[comp], unit)


def field_for(p, spec):
    """The field spec participant p is coloured by, or None (drawn grey)."""
    first = p.frame(p.frames[0][1])
    if spec is not None:
        return spec if field_values(first, spec)[0] is not None else None
    for base in DEFAULT_ORDER:
        if base in first:
            return (base, None)
    return None


def colour_scale(values, base):
    """(vmin, vmax, colour map, extend) of a field over all drawn frames: damage 0-1,
    else the 0.5 and 99.5 percentiles (a pressure peak of a few particles does not wash
    out the rest; the colour bar's arrows say so), symmetric about 0 with a diverging
    map for a quantity of both signs."""
    import numpy as np
    allv = np.concatenate([v for v in values if v.size]) if values else np.zeros(1)
    allv = allv[np.isfinite(allv)]
    if allv.size == 0:
        allv = np.zeros(1)
    if base == "damage":
        return 0.0, 1.0, None, "neither"
    lo, hi = np.percentile(allv, [0.5, 99.5])
    if allv.min() >= 0:
        lo = 0.0   # a magnitude: the scale starts at 0
    extend = ("min" if allv.min() < lo else "") + ("max" if allv.max() > hi else "")
    extend = {"": "neither", "minmax": "both"}.get(extend, extend)
    if lo < 0 < hi and min(-lo, hi) > 0.05 * max(-lo, hi):
        m = max(-lo, hi)
        return -m, m, DIVERGING_MAP, extend
    if hi <= lo:
        hi = lo + (abs(lo) if lo else 1.0)
    return float(lo), float(hi), None, extend


def truncated(name):
    """The colour map without its palest quarter, so a particle at the bottom of the
    scale still shows on white."""
    import matplotlib
    from matplotlib.colors import LinearSegmentedColormap
    import numpy as np
    base = matplotlib.colormaps[name]
    return LinearSegmentedColormap.from_list(name + "_dark", base(np.linspace(0.25, 1, 256)))


def plan(parts, spec, panels):
    """Per participant: its field spec and colour scale over the frames drawn (panels:
    one {name: key} per panel)."""
    scales = {}
    for p in parts:
        fs = field_for(p, spec)
        if fs is None:
            scales[p.name] = None
            continue
        values, label = [], None
        for keys in panels:
            frame = p.frame(keys[p.name][1])
            v, label = field_values(frame, fs)
            if v is not None:
                values.append(v[masks(p, frame)[0]])
        lo, hi, cmap, extend = colour_scale(values, fs[0])
        if cmap is None:
            cmap = "inferno_r" if fs[0] == "damage" else COLOUR_MAPS.get(p.name, "viridis")
            cmap = truncated(cmap)
        scales[p.name] = (fs, lo, hi, cmap, extend, label)
    return scales


def bounds(parts, panels):
    """(xmin, xmax, ymin, ymax) of every particle drawn in any panel, plus a spacing."""
    import numpy as np
    lo, hi = None, None
    for keys in panels:
        for p in parts:
            x = p.frame(keys[p.name][1])["position"][()]
            if not len(x):
                continue
            xl, xh = x.min(axis=0) - p.spacing, x.max(axis=0) + p.spacing
            lo = xl if lo is None else np.minimum(lo, xl)
            hi = xh if hi is None else np.maximum(hi, xh)
    if lo is None:
        return -1.0, 1.0, -1.0, 1.0
    return lo[0], hi[0], lo[1], hi[1]


def draw_panel(ax, parts, keys, scales):
    """Scatter every participant's particles of one panel's frames; returns
    [(scatter, participant)] for marker sizes and {name: coloured scatter} for the
    colour bars."""
    drawn, coloured = [], {}
    for p in parts:
        frame = p.frame(keys[p.name][1])
        x = frame["position"][()]
        show, grey = masks(p, frame)
        if grey.any():
            drawn.append((ax.scatter(x[grey, 0], x[grey, 1], c=WALL_GREY, linewidths=0), p))
        scale = scales[p.name]
        if scale is None:
            drawn.append((ax.scatter(x[show, 0], x[show, 1], c=NEUTRAL.get(p.name, "0.6"),
                                     linewidths=0), p))
            continue
        fs, lo, hi, cmap, _, _ = scale
        v = field_values(frame, fs)[0]
        sc = ax.scatter(x[show, 0], x[show, 1], c=v[show], cmap=cmap, vmin=lo, vmax=hi,
                        linewidths=0)
        drawn.append((sc, p))
        coloured[p.name] = sc
    return drawn, coloured


def size_markers(fig, axes_drawn):
    """Marker diameter 0.9 of each participant's spacing on screen (particles touch
    without hiding each other), at least half a point."""
    fig.canvas.draw()
    for ax, drawn in axes_drawn:
        box = ax.get_window_extent()
        (x0, x1), (y0, y1) = ax.get_xlim(), ax.get_ylim()
        px_per_m = min(box.width / (x1 - x0), box.height / (y1 - y0))
        for sc, p in drawn:
            d_pt = 0.9 * p.spacing * px_per_m * 72.0 / fig.dpi
            sc.set_sizes([max(d_pt, 0.5) ** 2])


def panel_title(parts, keys):
    """"t = 0.200 s", naming each participant's time when they differ."""
    times = sorted({round(keys[p.name][0], 12) for p in parts})
    if len(times) == 1:
        return "t = %.4g s" % times[0]
    return ", ".join("%s t = %.4g s" % (p.name, keys[p.name][0]) for p in parts)


def grid_shape(n, aspect):
    """(rows, cols) for n panels of height/width aspect: a figure near 0.7 as high as
    wide, few empty places."""
    best = None
    for cols in range(1, n + 1):
        rows = -(-n // cols)
        ratio = rows * aspect / cols
        score = abs(math.log(ratio / 0.7)) + 0.5 * (rows * cols - n)
        if best is None or score < best[0]:
            best = (score, rows, cols)
    return best[1], best[2]


def axes_pixels(fig, ax):
    """The axes box in image pixels (left, top, right, bottom; origin top left)."""
    b = ax.get_window_extent()
    h = fig.bbox.height
    return "%d,%d,%d,%d" % (round(b.x0), round(h - b.y1), round(b.x1), round(h - b.y0))


def figure(n_panels, n_bars, lims):
    """(figure, axes array) for n panels of the domain lims with n colour bars: panels
    of the domain's aspect, at most 16 x 10 inches of them."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    xmin, xmax, ymin, ymax = lims
    aspect = (ymax - ymin) / (xmax - xmin)
    rows, cols = grid_shape(n_panels, aspect)
    panels_width = min(5.5 * cols, 16.0)
    panels_height = min(max(panels_width * rows * aspect / cols, 2.0), 10.0)
    panels_width = min(panels_width, max(panels_height * cols / (rows * aspect), 3.0))
    size = (panels_width + 1.3 * n_bars + 0.8, panels_height + 1.0 + 0.4 * rows)
    return plt.subplots(rows, cols, figsize=size, squeeze=False, layout="constrained",
                        dpi=110)


def decorate(ax, lims, title):
    """Axes in metres with equal aspect over lims."""
    ax.set_xlim(lims[0], lims[1])
    ax.set_ylim(lims[2], lims[3])
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_xlabel("x [m]")
    ax.set_ylabel("y [m]")
    ax.set_title(title, fontsize=10)


def render(parts, panels, scales, title, png, lims):
    """Draw the panels (one {name: (time, key)} each) into png; its PNG text holds the
    frames' times and the axes' boxes (fsi:time, fsi:axes) for tests and scripts."""
    import matplotlib.pyplot as plt
    fig, axes = figure(len(panels), sum(1 for s in scales.values() if s), lims)
    axes_drawn, coloured = [], {}
    for ax, keys in zip(axes.flat, panels):
        drawn, col = draw_panel(ax, parts, keys, scales)
        coloured.update(col)
        axes_drawn.append((ax, drawn))
        decorate(ax, lims, panel_title(parts, keys))
    for ax in axes.flat[len(panels):]:
        ax.set_visible(False)
    for p in parts:
        if p.name in coloured:
            _, _, _, _, extend, label = scales[p.name]
            fig.colorbar(coloured[p.name], ax=axes, shrink=0.8 if axes.shape[0] == 1 else 0.6,
                         extend=extend, label="%s: %s" % (p.name, label))
    fig.suptitle(title)
    size_markers(fig, axes_drawn)
    meta = {"fsi:time": ";".join(panel_title(parts, k) for k in panels),
            "fsi:axes": ";".join(axes_pixels(fig, ax) for ax, _ in axes_drawn)}
    fig.savefig(png, metadata=meta)
    plt.close(fig)


def all_frames(parts):
    """One {name: (time, key)} per frame of the participant with the most frames, each
    other participant's frame nearest it."""
    lead = max(parts, key=lambda p: len(p.frames))
    return [{p.name: (f if p is lead else p.nearest(f[0])) for p in parts}
            for f in lead.frames]


def write_gif(pngs, gif, fps):
    """The PNGs as an animated GIF (Pillow, python3-pil)."""
    from PIL import Image
    images = [Image.open(f).convert("RGB") for f in pngs]
    images = [im.quantize(colors=255, method=Image.Quantize.MEDIANCUT) for im in images]
    images[0].save(gif, save_all=True, append_images=images[1:], loop=0,
                   duration=int(round(1000.0 / fps)))


def check_field(parts, a):
    """UsageError when no participant has the asked field."""
    if a.field_spec is None or any(field_for(p, a.field_spec) is not None for p in parts):
        return
    have = "; ".join("%s: %s" % (p.name, ", ".join(
        f for f in FIELDS if f in p.frame(p.frames[0][1])) or "none of them") for p in parts)
    raise UsageError("%s: no participant has the field '%s' (%s)" % (a.out, a.field, have))


def view_frames(parts, a, title):
    """--frames and --movie: one PNG per frame in a folder (earlier frame_*.png in it
    removed), with --movie the GIF of them."""
    panels = all_frames(parts)
    gif = a.file or os.path.join(a.out, "view.gif")
    if a.movie:
        folder = os.path.splitext(gif)[0] + "_frames"
    else:
        folder = a.file or os.path.join(a.out, "view_frames")
    os.makedirs(folder, exist_ok=True)
    for old in os.listdir(folder):
        if old.startswith("frame_") and old.endswith(".png"):
            os.remove(os.path.join(folder, old))
    scales, lims = plan(parts, a.field_spec, panels), bounds(parts, panels)
    pngs = [os.path.join(folder, "frame_%06d.png" % i) for i in range(len(panels))]
    for keys, png in zip(panels, pngs):
        render(parts, [keys], scales, title, png, lims)
    print("%s: %d frames in %s" % (PROG, len(pngs), folder))
    if a.movie:
        write_gif(pngs, gif, a.fps)
        print("%s: %s (%d frames at %g per second)" % (PROG, gif, len(pngs), a.fps))


def view_times(parts, a, title):
    """One PNG: the frames nearest --time's times (the last frame without it)."""
    times = a.times if a.times is not None else [max(p.frames[-1][0] for p in parts)]
    panels = [{p.name: p.nearest(t) for p in parts} for t in times]
    png = a.file or os.path.join(a.out, "view.png")
    render(parts, panels, plan(parts, a.field_spec, panels), title, png,
           bounds(parts, panels))
    print("%s: %s (%s)" % (PROG, png, "; ".join(panel_title(parts, k) for k in panels)))


def run(a):
    parts = open_participants(a.out)
    check_field(parts, a)
    if a.frames or a.movie:
        view_frames(parts, a, title_of(a.out))
    else:
        view_times(parts, a, title_of(a.out))


def main(argv):
    try:
        run(parse_args(argv))
    except UsageError as e:
        die(str(e))


if __name__ == "__main__":
    main(sys.argv[1:])
