"""F0 hydrostatic tank checks shared by the system tests (test_fluid_hydrostatic.sh,
test_fluid_wcsph.sh): f0_check.py OUT. For the run in OUT of cases/f0_hydrostatic_tank.ini
(H = 0.5 m of water in a 1 m tank) at t = 2 s:
  - the pressure at the three bottom probes within 1 % of rho0 g H = 4905 Pa;
  - the largest fluid particle speed below 1 % of sqrt(g H) = 2.215 m/s;
  - no fluid particle outside the tank (0 < x < 1, y > 0) in any frame;
  - nothing non-finite in any frame.
Exit status 0 when all hold."""
import csv
import sys

import h5py
import numpy as np

out = sys.argv[1]
rho0, g, H, W, T = 1000.0, 9.81, 0.5, 1.0, 2.0
ref = rho0 * g * H
row = list(csv.DictReader(l for l in open(out + "/probes.csv") if not l.startswith("#")))[-1]
ok = abs(float(row["time"]) - T) < 1e-9
for name in ("bottom_left_p", "bottom_middle_p", "bottom_right_p"):
    p = float(row[name])
    err = p / ref - 1
    print("%s: %s at t = %s s: %.2f Pa, rho0 g H = %.2f Pa, error %+.3f %%"
          % (out, name, row["time"], p, ref, 100 * err))
    ok = ok and abs(err) < 0.01
with h5py.File(out + "/fluid.h5", "r") as f:
    names = sorted(f["frames"].keys())
    for k in names:
        fr = f["frames"][k]
        fluid = (fr["flags"][...].reshape(-1) & 1) != 0
        for field in ("position", "velocity", "density", "pressure"):
            if not np.all(np.isfinite(fr[field][...])):
                print("frame %s: non-finite %s" % (k, field))
                ok = False
        x = fr["position"][...][fluid]
        out_of_tank = (x[:, 0] <= 0) | (x[:, 0] >= W) | (x[:, 1] <= 0)
        if out_of_tank.any():
            print("frame %s: %d fluid particles outside the tank" % (k, out_of_tank.sum()))
            ok = False
    last = f["frames"][names[-1]]
    fluid = (last["flags"][...].reshape(-1) & 1) != 0
    vmax = np.linalg.norm(last["velocity"][...][fluid], axis=1).max()
    t = last.attrs["time"]
bound = 0.01 * (g * H) ** 0.5
print("%s: t = %.3f s: largest speed %.5f m/s, bound 1 %% of sqrt(g H) = %.5f m/s; %d frames "
      "checked" % (out, t, vmax, bound, len(names)))
ok = ok and vmax < bound and abs(t - T) < 1e-9
sys.exit(0 if ok else 1)
