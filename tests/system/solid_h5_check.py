"""Reads a solid participant's output (solid.h5, docs/output.md) for the system tests.

  /usr/bin/python3 solid_h5_check.py finite FILE
      Every real dataset of every frame (and of /static) must be finite. Prints
      "frames N last_time T"; exits 1 naming each non-finite dataset.

  /usr/bin/python3 solid_h5_check.py spurious FILE [--exclude X,Y --radius R]
      Prints one line "time S L U" per frame: the spurious-mode number S = L / U of
      the displacement field u (below). Points within R of (X, Y) in the reference
      configuration are left out of both sums (a point load's own neighbourhood).

The spurious-mode number. With u_i the displacement of lattice point i and <u>_i the
mean of its four lattice neighbours (i +- 1, j +- 1), the residual r_i = u_i - <u>_i is
minus a quarter of the discrete Laplacian times dx^2. For a Fourier mode of
wavenumber (kx, ky) it is 1 - (cos(kx dx) + cos(ky dx)) / 2 times the mode:
about (k dx)^2 / 4 for a field that varies over many spacings (a physical solution
the lattice resolves), 1 for stripes of period 2 dx, and 2 for the checkerboard
(-1)^(i+j) -- the zero-energy (hourglass) pattern of the correspondence model, which
costs no force at interior points without the stabilisation (docs/nosbpd.md).
So S = RMS(r) / RMS(u), both over the same points, is the share of lattice-scale
content in the field: of order 1 when the spurious mode dominates, small when the
field is smooth. Only points that have all four neighbours and are not clamped
count, so free surfaces (no neighbour) and the clamp (u = 0 by construction) do not
enter; clamped points do serve as neighbours (u = 0 is their true displacement).
The lattice index of a point is x0 / dx, dx = volume^(1/dim) (geometry.c: every
point has volume dx^dim).
"""
import argparse
import sys

import h5py
import numpy as np

SOLID_CLAMPED = 1  # solid_particles.h


def frames_in_order(f):
    return sorted(f["frames"].keys())


def cmd_finite(path):
    bad = []
    with h5py.File(path, "r") as f:
        groups = [("static", f["static"])] + [(k, f["frames"][k]) for k in frames_in_order(f)]
        for name, g in groups:
            for field, ds in g.items():
                data = ds[()]
                if data.dtype.kind == "f" and not np.all(np.isfinite(data)):
                    n = int(np.count_nonzero(~np.isfinite(data)))
                    bad.append(f"{name}/{field}: {n} non-finite values")
        keys = frames_in_order(f)
        last = float(f["frames"][keys[-1]].attrs["time"]) if keys else float("nan")
        print(f"frames {len(keys)} last_time {last:.9g}")
    for b in bad:
        print("not finite: " + b, file=sys.stderr)
    return 1 if bad else 0


def cmd_spurious(path, exclude, radius):
    with h5py.File(path, "r") as f:
        dim = int(f.attrs["dimension"])
        if dim != 2:
            print("spurious: only 2D lattices are handled", file=sys.stderr)
            return 2
        x0 = f["static/x0"][()]
        flags = f["static/flags"][()]
        dx = float(np.median(f["static/volume"][()])) ** (1.0 / dim)
        ij = np.rint((x0 - x0.min(axis=0)) / dx).astype(int)
        index = {(int(a), int(b)): n for n, (a, b) in enumerate(ij)}
        keep = (flags & SOLID_CLAMPED) == 0
        if exclude is not None:
            keep &= np.linalg.norm(x0 - np.asarray(exclude), axis=1) > radius
        points, neighbours = [], []
        for n, (a, b) in enumerate(ij):
            if not keep[n]:
                continue
            nb = [index.get((int(a) + da, int(b) + db))
                  for da, db in ((1, 0), (-1, 0), (0, 1), (0, -1))]
            if None in nb:
                continue
            points.append(n)
            neighbours.append(nb)
        if not points:
            print("spurious: no point has four neighbours", file=sys.stderr)
            return 2
        points = np.array(points)
        neighbours = np.array(neighbours)
        for k in frames_in_order(f):
            u = f["frames"][k]["displacement"][()]
            r = u[points] - u[neighbours].mean(axis=1)
            rms_r = float(np.sqrt((r ** 2).sum(axis=1).mean()))
            rms_u = float(np.sqrt((u[points] ** 2).sum(axis=1).mean()))
            s = rms_r / rms_u if rms_u > 0.0 else 0.0
            t = float(f["frames"][k].attrs["time"])
            print(f"{t:.6g} {s:.6g} {rms_r:.6g} {rms_u:.6g}")
    return 0


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("command", choices=("finite", "spurious"))
    ap.add_argument("file")
    ap.add_argument("--exclude", help="X,Y: centre of the region left out of 'spurious'")
    ap.add_argument("--radius", type=float, default=0.0, help="radius of that region [m]")
    a = ap.parse_args()
    if a.command == "finite":
        return cmd_finite(a.file)
    exclude = [float(v) for v in a.exclude.split(",")] if a.exclude else None
    return cmd_spurious(a.file, exclude, a.radius)


if __name__ == "__main__":
    sys.exit(main())
