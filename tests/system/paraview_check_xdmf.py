"""Checks that ParaView reads a particle XDMF series (core/h5_output) as written.

Run with pvbatch (tests/system/test_paraview_xdmf.sh does):

  pvbatch paraview_check_xdmf.py FILE.xmf --dim 2 --times 0.5,1.25,2 --counts 5,5,7 \
      --fields pressure:scalar,velocity:vector,stress:tensor \
      --value 2:velocity:6:1=-261.125 --point 2:6=26,26.25

--value FRAME:FIELD:POINT:COMP=V and --point FRAME:POINT=X,Y[,Z] use frame indices in
time order. The file is read with the reader OpenDataFile picks (Xdmf3ReaderS),
with Xdmf3ReaderT and with the legacy "XDMF Reader", since the GUI offers all of
them for .xmf. Every reader must give one vertex cell per particle (without cells
the Points representation shows nothing and Threshold returns nothing). Prints one line per
mismatch and exits 1 if there was any, 0 otherwise.
"""
import argparse
import os
import sys

from paraview import servermanager

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from paraview_three_readers import each_reader, run  # noqa: E402 (after the path)

COMPONENTS = {"scalar": lambda d: 1, "vector": lambda d: d, "tensor": lambda d: d * d}
failures = []


def fail(msg):
    failures.append(msg)
    print("paraview_check_xdmf: FAIL: " + msg, file=sys.stderr)


def close(a, b):
    return abs(a - b) <= 1e-12 * max(1.0, abs(a), abs(b))


def parse_args():
    p = argparse.ArgumentParser()
    p.add_argument("xmf")
    p.add_argument("--dim", type=int, required=True, choices=(2, 3))
    p.add_argument("--times", required=True, help="comma-separated frame times")
    p.add_argument("--counts", required=True, help="comma-separated points per frame")
    p.add_argument("--fields", required=True, help="NAME:scalar|vector|tensor,...")
    p.add_argument("--value", action="append", default=[], help="FRAME:FIELD:POINT:COMP=V")
    p.add_argument("--point", action="append", default=[], help="FRAME:POINT=X,Y[,Z]")
    a = p.parse_args()
    a.times = [float(t) for t in a.times.split(",")]
    a.counts = [int(n) for n in a.counts.split(",")]
    a.fields = [tuple(f.split(":")) for f in a.fields.split(",")]
    if len(a.times) != len(a.counts):
        p.error("--times and --counts differ in length")
    return a


def fetch(reader, t):
    reader.UpdatePipeline(t)
    data = servermanager.Fetch(reader)
    if data is None or not data.IsA("vtkDataSet"):
        return None
    return data


def check_components(label, arr, want, legacy):
    got = arr.GetNumberOfComponents()
    if got == want:
        return
    # The legacy reader pads 2-D vectors to 3 components; fine if the padding is 0.
    if legacy and want == 2 and got == 3:
        if all(arr.GetComponent(i, 2) == 0.0 for i in range(arr.GetNumberOfTuples())):
            return
    fail("%s has %d components, expected %d" % (label, got, want))


def check_fields(label, data, frame, args, legacy):
    pd = data.GetPointData()
    for name, kind in args.fields:
        arr = pd.GetArray(name)
        if arr is None:
            fail("%s: point field '%s' missing" % (label, name))
            continue
        check_components("%s: %s" % (label, name), arr, COMPONENTS[kind](args.dim), legacy)
        if arr.GetNumberOfTuples() != args.counts[frame]:
            fail("%s: %s has %d values, expected %d"
                 % (label, name, arr.GetNumberOfTuples(), args.counts[frame]))
    for spec in args.value:
        where, value = spec.split("=")
        f, name, point, comp = where.split(":")
        if int(f) != frame:
            continue
        arr = pd.GetArray(name)
        point, comp = int(point), int(comp)
        if arr is None or point >= arr.GetNumberOfTuples() or comp >= arr.GetNumberOfComponents():
            fail("%s: %s[%d][%d] not present" % (label, name, point, comp))
        elif not close(arr.GetComponent(point, comp), float(value)):
            fail("%s: %s[%d][%d] = %r, expected %s"
                 % (label, name, point, comp, arr.GetComponent(point, comp), value))


def check_points(label, data, frame, args):
    for spec in args.point:
        where, coords = spec.split("=")
        f, point = (int(x) for x in where.split(":"))
        if f != frame:
            continue
        want = [float(c) for c in coords.split(",")] + [0.0] * (3 - args.dim)
        if point >= data.GetNumberOfPoints():
            fail("%s: point %d missing" % (label, point))
            continue
        got = list(data.GetPoint(point))
        if not all(close(g, w) for g, w in zip(got, want)):
            fail("%s: point %d at %r, expected %r" % (label, point, got, want))


def check_reader(reader, args, legacy):
    name = reader.GetXMLName()
    times = list(reader.TimestepValues)
    if len(times) != len(args.times) or not all(close(a, b) for a, b in zip(times, args.times)):
        fail("%s: time steps %r, expected %r" % (name, times, args.times))
        return
    for frame, t in enumerate(times):
        label = "%s t=%g" % (name, t)
        data = fetch(reader, t)
        if data is None:
            fail("%s: no data set" % label)
            continue
        if data.GetNumberOfPoints() != args.counts[frame]:
            fail("%s: %d points, expected %d"
                 % (label, data.GetNumberOfPoints(), args.counts[frame]))
            continue
        if data.GetNumberOfCells() != data.GetNumberOfPoints():
            fail("%s: %d cells for %d points, expected one vertex cell per point"
                 % (label, data.GetNumberOfCells(), data.GetNumberOfPoints()))
        elif data.GetNumberOfPoints() > 0 and (
                data.GetCell(0).GetNumberOfPoints() != 1
                or data.GetCell(data.GetNumberOfCells() - 1).GetPointId(0)
                != data.GetNumberOfPoints() - 1):
            fail("%s: cells are not one vertex per point in order" % label)
        check_fields(label, data, frame, args, legacy)
        check_points(label, data, frame, args)


def main():
    args = parse_args()
    each_reader(args.xmf, lambda reader, legacy: check_reader(reader, args, legacy), fail)
    if failures:
        print("paraview_check_xdmf: %d check(s) failed" % len(failures), file=sys.stderr)
        return 1
    print("paraview_check_xdmf: OK (%d time steps, 3 readers, cells == points)"
          % len(args.times))
    return 0


if __name__ == "__main__":
    run("paraview_check_xdmf", main)
