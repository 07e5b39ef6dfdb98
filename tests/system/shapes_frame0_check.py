#!/usr/bin/python3
"""Frame 0 of the shapes case of test_write_initial.sh (fsi run --check
--write-initial): the solid is a disc of radius 10 spacings (clamped whole) with a
20 x 2 flag, the fluid has a wall box turned by 30 degrees, 20 x 3 spacings.
Usage: shapes_frame0_check.py OUT"""
import math
import sys

import h5py
import numpy as np

out = sys.argv[1]
dx = 0.004
problems = []

with h5py.File(f"{out}/solid.h5", "r") as f:
    x = f["/frames/000000/position"][()]
    block = f["/static/block"][()]
    flags = f["/static/flags"][()]
    t = f["/frames/000000"].attrs["time"]
disc = x[block == 0]
r = np.hypot(disc[:, 0] - 0.4, disc[:, 1] - 0.1)
want = math.pi * 0.04 ** 2 / dx ** 2
# The lattice count of a disc of radius 10 spacings lies within 5 % of pi r^2 / dx^2
# (the error is of the order of the perimeter's square root, ~ 8 points of 314).
if not (abs(len(disc) - want) < 0.05 * want and r.max() <= 0.04 + 1e-9):
    problems.append(f"disc: {len(disc)} points (pi r^2/dx^2 = {want:.1f}), largest r {r.max()}")
if not np.all(flags[block == 0] & 1):
    problems.append("not every disc point is clamped")
flag = x[block == 1]
if len(flag) != 40 or np.any(flags[block == 1] & 1):
    problems.append(f"flag: {len(flag)} points (want 40, none clamped)")
if t != 0.0:
    problems.append(f"solid frame 0 at t = {t}")

with h5py.File(f"{out}/fluid.h5", "r") as f:
    x = f["/frames/000000/position"][()]
    flags = f["/frames/000000/flags"][()]
wall = x[(flags & 2) != 0]
a = math.radians(30.0)
c = np.array([0.24, 0.206])
q = wall - c
u = q[:, 0] * math.cos(a) + q[:, 1] * math.sin(a)
v = -q[:, 0] * math.sin(a) + q[:, 1] * math.cos(a)
baffle = (np.abs(u) <= 0.04 + 1e-9) & (np.abs(v) <= 0.006 + 1e-9)
if baffle.sum() != 60:
    problems.append(f"baffle: {baffle.sum()} wall particles in the turned box, want 60")
# its rows lie at v = -1, 0, 1 spacings: the lattice is aligned with the box
rows = np.unique(np.round(v[baffle] / dx, 6))
if list(rows) != [-1.0, 0.0, 1.0]:
    problems.append(f"baffle rows at v / dx = {rows}")
water = x[(flags & 1) != 0]
if len(water) != 36 * 30:
    problems.append(f"water: {len(water)} particles, want 36 x 30")

for p in problems:
    print("FAIL:", p)
print(f"disc {len(disc)} points (pi r^2/dx^2 {want:.1f}), flag {len(flag)}, baffle "
      f"{baffle.sum()}, water {len(water)}")
sys.exit(1 if problems else 0)
