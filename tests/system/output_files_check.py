"""Checks that a run's particle output is complete and consistent as it stands, also
while the run is still writing it (docs/output.md, "What a reader may rely on").

  /usr/bin/python3 output_files_check.py OUT NAME [NAME...]

For each NAME: OUT/NAME.h5 opens; every frame it lists opens, has the attributes of
its name, a position of n rows and fields of n rows; OUT/NAME.xmf parses as XML and
every HDF5 file and dataset it names exists with the row count it declares. Prints
"NAME FRAMES_IN_H5 GRIDS_IN_XMF" per name and exits 0, or prints what is wrong and
exits 1.
"""
import os
import sys
import xml.etree.ElementTree as ET

import h5py


def check_h5(path):
    with h5py.File(path, "r") as f:
        for key in ("participant", "solver", "dimension", "fsi_version"):
            if key not in f.attrs:
                raise ValueError("%s: root attribute %s missing" % (path, key))
        f["static"].keys()
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
        return len(names)


def check_xmf(path):
    root = ET.parse(path).getroot()
    folder = os.path.dirname(path)
    grids = root.findall("./Domain/Grid/Grid")
    opened = {}
    try:
        for grid in grids:
            for item in grid.iter("DataItem"):
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


def main():
    out, names = sys.argv[1], sys.argv[2:]
    for name in names:
        frames = check_h5(os.path.join(out, name + ".h5"))
        grids = check_xmf(os.path.join(out, name + ".xmf"))
        print(name, frames, grids)
    return 0


if __name__ == "__main__":
    try:
        sys.exit(main())
    except Exception as e:
        print("output_files_check: FAIL: %s: %s" % (type(e).__name__, e), file=sys.stderr)
        sys.exit(1)
