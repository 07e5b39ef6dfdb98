"""Checks that a run's particle output is complete and consistent as it stands, also
while the run is still writing it (docs/output.md, "What a reader may rely on").

  /usr/bin/python3 output_files_check.py OUT NAME [NAME...]

For each NAME: OUT/NAME.h5 opens; every frame it lists opens, has the attributes of
its name, a position of n rows and fields of n rows; every static and frame dataset
says what it holds (docs/output.md): non-empty string attributes unit and
description, and a dataset named flags, or any with flag_values or flag_masks, names
its values (flag_meanings, one word per value) and holds only those values (or sums
of those bits); OUT/NAME.xmf parses as XML and every HDF5 file and dataset it names
exists with the row count it declares, and every grid has the same constants
(grid-centred attributes). When OUT/run.xmf exists it includes the
sidecar of every NAME, and every sidecar it includes exists. When OUT/probes.csv has
been begun, its second line names a unit for every column of the header. Prints "NAME FRAMES_IN_H5 GRIDS_IN_XMF" per
name and exits 0, or prints what is wrong and exits 1.
"""
import os
import sys
import xml.etree.ElementTree as ET

import h5py


def text_attr(ds, key):
    value = ds.attrs.get(key)
    if isinstance(value, bytes):
        value = value.decode()
    return value if isinstance(value, str) else None


def check_described(path, where, ds):
    """unit and description, and the flags' names, of one dataset."""
    for key in ("unit", "description"):
        if not text_attr(ds, key):
            raise ValueError("%s: %s has no %s attribute" % (path, where, key))
    kind = "flag_values" if "flag_values" in ds.attrs else \
        "flag_masks" if "flag_masks" in ds.attrs else None
    if kind is None:
        if where.rsplit("/", 1)[-1] == "flags":
            raise ValueError("%s: %s does not name its values (flag_values or flag_masks)"
                             % (path, where))
        return
    values = [int(v) for v in ds.attrs[kind]]
    meanings = (text_attr(ds, "flag_meanings") or "").split(" ")
    if len(meanings) != len(values) or not all(meanings):
        raise ValueError("%s: %s: flag_meanings %r does not name its %d %s"
                         % (path, where, ds.attrs.get("flag_meanings"), len(values), kind))
    data = set(int(v) for v in ds[...].ravel())
    if kind == "flag_values":
        bad = data - set(values)
    else:
        every = 0
        for v in values:
            every |= v
        bad = set(v for v in data if v & ~every)
    if bad:
        raise ValueError("%s: %s holds %s, not among its %s %s"
                         % (path, where, sorted(bad), kind, values))


def check_h5(path):
    with h5py.File(path, "r") as f:
        for key in ("participant", "solver", "dimension", "fsi_version"):
            if key not in f.attrs:
                raise ValueError("%s: root attribute %s missing" % (path, key))
        for field, ds in f["static"].items():
            check_described(path, "static/" + field, ds)
        names = list(f["frames"].keys())
        for name in names:
            g = f["frames"][name]
            if int(g.attrs["frame"]) != int(name):
                raise ValueError("%s: frame %s has frame attribute %s"
                                 % (path, name, g.attrs["frame"]))
            float(g.attrs["time"])
            n = g["position"].shape[0]
            for field, ds in g.items():
                if ds.shape[0] != n:
                    raise ValueError("%s: frame %s: %s has %d rows, position %d"
                                     % (path, name, field, ds.shape[0], n))
                ds[...]
                check_described(path, "frames/%s/%s" % (name, field), ds)
        return len(names)


def check_xmf(path):
    root = ET.parse(path).getroot()
    folder = os.path.dirname(path)
    grids = root.findall("./Domain/Grid/Grid")
    # Every frame has the same constants (a restart reads them back from the frames).
    constants = set(tuple(sorted(a.get("Name") for a in g.findall("Attribute")
                                 if a.get("Center") == "Grid")) for g in grids)
    if len(constants) > 1:
        raise ValueError("%s: the grids' constants differ: %s" % (path, sorted(constants)))
    opened = {}
    try:
        for grid in grids:
            for item in grid.iter("DataItem"):
                if item.get("Format") == "XML":   # a frame constant, given inline
                    float(item.text)
                    continue
                rows = int(item.get("Dimensions").split()[0])
                file_name, dataset = item.text.strip().split(":")
                if file_name not in opened:
                    opened[file_name] = h5py.File(os.path.join(folder, file_name), "r")
                if opened[file_name][dataset].shape[0] != rows:
                    raise ValueError("%s: %s has %d rows, the sidecar says %d"
                                     % (path, item.text, opened[file_name][dataset].shape[0],
                                        rows))
    finally:
        for f in opened.values():
            f.close()
    return len(grids)


XINCLUDE = "{http://www.w3.org/2001/XInclude}include"


def check_run_xmf(path, names):
    """run.xmf includes the sidecar of every name, and only sidecars that exist."""
    domain = ET.parse(path).getroot().find("Domain")
    hrefs = [e.get("href") for e in domain.iter(XINCLUDE)]
    missing = [n + ".xmf" for n in names if n + ".xmf" not in hrefs]
    absent = [h for h in hrefs if not os.path.exists(os.path.join(os.path.dirname(path), h))]
    if missing or absent:
        raise ValueError("%s includes %s: %s missing, %s not there"
                         % (path, hrefs, missing, absent))


def check_probes_units(path):
    """probes.csv's '# units: ...' line: one unit per column of the header, none unknown."""
    with open(path) as f:
        header, units = f.readline(), f.readline()
    if not header:
        return              # created, not yet written
    columns = header.rstrip("\n").split(",")
    if not units.startswith("# units: "):
        raise ValueError("%s: the second line is not '# units: ...': %r" % (path, units))
    names = units[len("# units: "):].rstrip("\n").split(",")
    if len(names) != len(columns) or "?" in names or "" in names:
        raise ValueError("%s: units %s for the columns %s" % (path, names, columns))


def main():
    out, names = sys.argv[1], sys.argv[2:]
    for name in names:
        frames = check_h5(os.path.join(out, name + ".h5"))
        grids = check_xmf(os.path.join(out, name + ".xmf"))
        print(name, frames, grids)
    if os.path.exists(os.path.join(out, "run.xmf")):
        check_run_xmf(os.path.join(out, "run.xmf"), names)
    if os.path.exists(os.path.join(out, "probes.csv")):
        check_probes_units(os.path.join(out, "probes.csv"))
    return 0


if __name__ == "__main__":
    try:
        sys.exit(main())
    except Exception as e:
        print("output_files_check: FAIL: %s: %s" % (type(e).__name__, e), file=sys.stderr)
        sys.exit(1)
