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


def read_probes(out_dir):
    """probes.csv as {column: [floats]}."""
    with open(os.path.join(out_dir, "probes.csv"), newline="") as f:
        rows = list(csv.reader(f))
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
