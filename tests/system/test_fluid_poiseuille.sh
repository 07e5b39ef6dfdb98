#!/usr/bin/env bash
# FP plane Poiseuille flow (cases/fp_poiseuille_channel.ini): a channel periodic along x
# between no-slip plates H = 0.02 m apart, driven by g = 0.2 m/s^2, nu = 1e-3 m^2/s,
# started from rest. Every frame's fluid velocities are compared with the analytical
# start-up solution
#     u(y, t) = g / (2 nu) y (H - y)
#               - sum_{n odd} 4 g H^2 / (nu pi^3 n^3) sin(n pi y / H) exp(-n^2 pi^2 nu t / H^2)
# Bound: the largest |u - u_exact| over all fluid particles and frames (t >= 0.1 s)
# within 1 % of u_max = g H^2 / (8 nu) = 0.01 m/s. Measured 0.47 % at dx = H / 20; the
# operator's error for a parabola is O(dx^2 / H^2) = 0.25 % here, and the no-slip wall's
# placement adds as much again, so 1 % leaves a factor of 2.
# Also: the cross-channel velocity below 0.1 % of u_max, particles stay in the period
# box (they are wrapped back) and no particle is lost, and
# the test can fail: with viscous_operator = stress (000 Eq. 23 as printed) a velocity
# alternating row by row survives the nested gradients (measured error 28 %), so that
# run must miss the 1 % bound.
source "$(dirname "$0")/lib.sh"
PY=/usr/bin/python3
CASE="$FSI_SOURCE_DIR/cases/fp_poiseuille_channel.ini"

"$FSI_RUN" "$CASE" --out fp --threads 1 >fp.txt 2>&1 || { cat fp.txt; fail "FP run failed"; }
"$FSI_RUN" "$CASE" --out fp_stress --threads 1 --set fluid.ulph.viscous_operator=stress \
  --set run.end_time=0.2 >fp_stress.txt 2>&1 || { cat fp_stress.txt; fail "FP stress run failed"; }

check() {
"$PY" - "$1" "$2" <<'PY'
import math, sys
import h5py, numpy as np
out, bound = sys.argv[1], float(sys.argv[2])
g, nu, H, L = 0.2, 1e-3, 0.02, 0.012
umax = g * H * H / (8 * nu)
def exact(y, t):
    u = g / (2 * nu) * y * (H - y)
    for n in range(1, 200, 2):
        u -= 4 * g * H * H / (nu * math.pi ** 3 * n ** 3) * np.sin(n * math.pi * y / H) * \
             math.exp(-n * n * math.pi ** 2 * nu * t / (H * H))
    return u
worst = worst_v = 0.0
n0 = None
with h5py.File(out + "/fluid.h5", "r") as f:
    for k in sorted(f["frames"].keys()):
        fr = f["frames"][k]
        t = float(fr.attrs["time"])
        fluid = (fr["flags"][()].ravel() & 1) > 0
        x, v = fr["position"][()][fluid], fr["velocity"][()][fluid]
        n0 = n0 or len(x)
        assert len(x) == n0, "fluid particles lost"
        assert (x[:, 0] >= 0).all() and (x[:, 0] < L).all(), "a particle outside the period"
        if t < 0.1 - 1e-9:
            continue
        worst = max(worst, float(np.abs(v[:, 0] - exact(x[:, 1], t)).max()) / umax)
        worst_v = max(worst_v, float(np.abs(v[:, 1]).max()) / umax)
print("%s: largest |u - u_exact| = %.3f %% of u_max, largest |v| = %.4f %% of u_max"
      % (out, 100 * worst, 100 * worst_v))
sys.exit(0 if worst < bound and worst_v < 1e-3 else 1)
PY
}
check fp 0.01 || fail "FP: velocity profile off the analytical solution"
if check fp_stress 0.01; then
  fail "FP: the printed stress form passed, so the bound cannot tell the row-alternating mode"
fi
pass "FP plane Poiseuille flow within 1 % of u_max at every frame from t = 0.1 s"
