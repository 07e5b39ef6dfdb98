#!/usr/bin/python3
"""Moving walls in a run (tests/system/test_fluid_moving_walls.sh): in every frame of
OUT/fluid.h5 each wall particle is at x0 + X(t) and has the velocity X'(t) of the case's
harmonic motion (fluid_solver/fluid_motion.h), and every fluid particle is inside the
moving tank. Arguments: OUT A T PHASE_DEG TANK_X_MIN TANK_X_MAX."""
import math
import sys

import h5py
import numpy as np

out, amp, period, phase = sys.argv[1], *map(float, sys.argv[2:5])
x_lo, x_hi = float(sys.argv[5]), float(sys.argv[6])
phase = math.radians(phase)
w = 2 * math.pi / period
with h5py.File(out + "/fluid.h5", "r") as f:
    x0 = f["static/x0"][...]
    wall = (f["static/flags"][...].ravel() & 2) != 0
    worst, frames, outside = 0.0, 0, 0
    for name in f["frames"]:
        g = f["frames"][name]
        t = float(g.attrs["time"])
        s = amp * (math.sin(w * t + phase) - math.sin(phase))
        v = amp * w * math.cos(w * t + phase)
        x, vel = g["position"][...], g["velocity"][...]
        worst = max(worst, np.max(np.abs(x[wall, 0] - (x0[wall, 0] + s))),
                    np.max(np.abs(x[wall, 1] - x0[wall, 1])),
                    np.max(np.abs(vel[wall, 0] - v)), np.max(np.abs(vel[wall, 1])))
        fx = x[~wall, 0] - s
        outside += int(np.sum((fx < x_lo) | (fx > x_hi)))
        frames += 1
print(f"{frames} frames: largest wall position/velocity error {worst:.3g}, "
      f"{outside} fluid particle positions outside the tank")
sys.exit(0 if frames > 1 and worst < 1e-12 and outside == 0 else 1)
