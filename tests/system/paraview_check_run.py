"""Checks that ParaView opens a run's OUT/run.xmf, fluid and solid together (core/run_xmf.h).

Run with pvbatch (tests/system/test_paraview_run_output.sh does):

  pvbatch paraview_check_run.py OUT/run.xmf --times 0,0.002 \
      --block fluid=pressure,mass,density --block solid=stress,mass,density \
      --constant smoothing_length --sph fluid

--block NAME=ARRAYS, in run.xmf's order: the point arrays each block must have.
--constant NAME: field data every block must have (a frame constant, e.g. the smoothing
length). --sph NAME: at the last time, ParaView's SPH interpolator (vtkSPHInterpolator
with the Wendland C2 kernel, the one the solvers use) at the middle one of block NAME's
points whose "flags" is 1 (fluid), taking the block's mass, density and smoothing_length
as ParaView's SPH filters take them: the Shepard sum, sum of m/rho W, must be 1 within
5 % inside the fluid (1.018 measured on C1), and the interpolated density (Shepard
normalised) within 1 % of that point's.

The file is read with the three readers ParaView offers for it: Xdmf3ReaderS (which
OpenDataFile picks; it makes the participants pieces of one data set), Xdmf3ReaderT and
the legacy "XDMF Reader" (blocks, the legacy one named after the participants). Prints
one line per mismatch and exits 1 if there was any, 0 otherwise.
"""
import argparse
import os
import sys

from paraview import servermanager
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCompositeDataSet, vtkPolyData
from vtkmodules.vtkFiltersPoints import vtkSPHInterpolator, vtkWendlandQuinticKernel

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from paraview_three_readers import each_reader, run  # noqa: E402 (after the path)

failures = []


def fail(msg):
    failures.append(msg)
    print("paraview_check_run: FAIL: " + msg, file=sys.stderr)


def parse_args():
    p = argparse.ArgumentParser()
    p.add_argument("xmf")
    p.add_argument("--dim", type=int, default=2, choices=(2, 3))
    p.add_argument("--times", required=True, help="comma-separated frame times")
    p.add_argument("--block", action="append", required=True, help="NAME=ARRAY,...")
    p.add_argument("--constant", action="append", default=[])
    p.add_argument("--sph", help="block whose fluid points the SPH interpolator samples")
    a = p.parse_args()
    a.times = [float(t) for t in a.times.split(",")]
    a.blocks = [(b.split("=")[0], b.split("=")[1].split(",")) for b in a.block]
    # Xdmf3's XInclude resolution breaks on a bare file name (it looks for
    # "run.xmffluid.frames/..."); the GUI always passes a full path.
    a.xmf = os.path.abspath(a.xmf)
    return a


def leaves(data):
    """(name or None, data set) of every leaf, in order."""
    out = []
    if data.IsA("vtkMultiBlockDataSet") or data.IsA("vtkMultiPieceDataSet"):
        multi = data.IsA("vtkMultiBlockDataSet")
        for i in range(data.GetNumberOfBlocks() if multi else data.GetNumberOfPieces()):
            child = data.GetBlock(i) if multi else data.GetPiece(i)
            if child is None:
                continue
            if child.IsA("vtkDataSet"):
                meta = data.GetMetaData(i) if data.HasMetaData(i) else None
                name = meta.Get(vtkCompositeDataSet.NAME()) if meta else None
                out.append((name, child))
            else:
                out.extend(leaves(child))
    elif data.IsA("vtkDataSet"):
        out.append((None, data))
    return out


def sph_check(label, block, h, dim):
    """Shepard sum and density of the SPH interpolation at a point inside the fluid."""
    pd = block.GetPointData()
    flags = pd.GetArray("flags")
    fluid = [i for i in range(block.GetNumberOfPoints())
             if flags is None or flags.GetValue(i) == 1]
    if not fluid:
        fail("%s: no fluid point" % label)
        return
    # the point nearest the fluid's centre: inside the water, away from the surfaces
    centre = [sum(block.GetPoint(i)[k] for i in fluid) / len(fluid) for k in range(3)]
    at = min(fluid, key=lambda i: sum((block.GetPoint(i)[k] - centre[k]) ** 2
                                      for k in range(3)))
    probe_points = vtkPoints()
    probe_points.InsertNextPoint(block.GetPoint(at))
    probe = vtkPolyData()
    probe.SetPoints(probe_points)
    kernel = vtkWendlandQuinticKernel()   # Wendland C2, support 2 h (core/wendland_c2.h)
    kernel.SetSpatialStep(h)
    kernel.SetDimension(dim)
    sph = vtkSPHInterpolator()
    sph.SetInputData(probe)
    sph.SetSourceData(block)
    sph.SetKernel(kernel)
    sph.SetMassArrayName("mass")
    sph.SetDensityArrayName("density")
    sph.SetComputeShepardSum(True)
    sph.SetShepardNormalization(True)
    sph.Update()
    out = sph.GetOutput().GetPointData()
    shepard = out.GetArray(sph.GetShepardSumArrayName()).GetValue(0)
    rho = out.GetArray("density").GetValue(0)
    rho_point = pd.GetArray("density").GetValue(at)
    if abs(shepard - 1.0) > 0.05:
        fail("%s: SPH Shepard sum %.4f at %r, expected 1 within 5 %% (mass, density or "
             "smoothing_length inconsistent)" % (label, shepard, block.GetPoint(at)))
    if abs(rho / rho_point - 1.0) > 0.01:
        fail("%s: SPH density %.6g at %r, the particle's %.6g (bound 1 %%)"
             % (label, rho, block.GetPoint(at), rho_point))
    print("paraview_check_run: %s: SPH at %r: Shepard sum %.4f, density %.6g (particle %.6g)"
          % (label, tuple(round(c, 6) for c in block.GetPoint(at)), shepard, rho, rho_point))


def check_reader(reader, args, named):
    name = reader.GetXMLName()
    times = list(reader.TimestepValues)
    if len(times) != len(args.times) or any(abs(a - b) > 1e-12 for a, b in zip(times, args.times)):
        fail("%s: time steps %r, expected %r" % (name, times, args.times))
        return
    t = times[-1]
    reader.UpdatePipeline(t)
    data = servermanager.Fetch(reader)
    found = leaves(data) if data is not None else []
    if len(found) != len(args.blocks):
        fail("%s: %d blocks or pieces, expected %d (%s)"
             % (name, len(found), len(args.blocks), ", ".join(b for b, _ in args.blocks)))
        return
    for (block, arrays), (got_name, ds) in zip(args.blocks, found):
        label = "%s t=%g %s" % (name, t, block)
        if named and got_name != block:
            fail("%s: block named %r" % (label, got_name))
        if ds.GetNumberOfPoints() == 0 or ds.GetNumberOfCells() != ds.GetNumberOfPoints():
            fail("%s: %d points, %d cells" % (label, ds.GetNumberOfPoints(),
                                              ds.GetNumberOfCells()))
        pd = ds.GetPointData()
        for a in arrays:
            arr = pd.GetArray(a)
            if arr is None:
                fail("%s: point array %s missing" % (label, a))
            elif arr.GetNumberOfTuples() != ds.GetNumberOfPoints():
                fail("%s: %s has %d values for %d points"
                     % (label, a, arr.GetNumberOfTuples(), ds.GetNumberOfPoints()))
        for c in args.constant:
            arr = ds.GetFieldData().GetArray(c)
            if arr is None or arr.GetNumberOfTuples() != 1 or not arr.GetValue(0) > 0:
                fail("%s: field data %s missing or not positive" % (label, c))
        if block == args.sph and ds.GetFieldData().GetArray("smoothing_length") is not None:
            sph_check(label, ds, ds.GetFieldData().GetArray("smoothing_length").GetValue(0),
                      args.dim)


def main():
    args = parse_args()
    each_reader(args.xmf, lambda reader, legacy: check_reader(reader, args, named=legacy),
                fail)
    if failures:
        print("paraview_check_run: %d check(s) failed" % len(failures), file=sys.stderr)
        return 1
    print("paraview_check_run: OK (%d time steps, %d blocks, 3 readers)"
          % (len(args.times), len(args.blocks)))
    return 0


if __name__ == "__main__":
    run("paraview_check_run", main)
