#!/usr/bin/env bash
# fsi bench: C4's plate alone under the water's weight: the solid against 2D elasticity
# C4's plate alone (cases/c4_plate_under_water.ini's [solid] sections, no fluid) under
# the water column's hydrostatic load, rho_w g H = 19620 N/m spread over its top row of
# points, and its own weight, with mass damping so that it settles: how far the PD
# solid itself is from 2D elasticity (bench/fe_clamped_plate.py), without the coupling.
# Measured: T / dx = 8: 71.95 um, T / dx = 12: 71.25 um at 0.06 s, against the finite
# elements' 70.66 um (+1.83 %, +0.84 %: second order) and plate theory's 68.60 um.
#
#   bench/c4_plate_alone.sh [OUT] [--n "8 12"] [--solver NAME] [--set section.key=value ...]
#
# --solver picks the solid model (default nosbpd); --set passes keys to every run.
# About 1 min (T / dx = 8) and 8 min (12) on one core.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
OUT="$ROOT/out/bench/c4_plate_alone"
case "${1:-}" in "" | --*) ;; *) OUT="$1"; shift ;; esac
LIST="8 12"
SOLVER=nosbpd
SETS=()
while [ $# -gt 0 ]; do
  case "$1" in
    --n) LIST="${2:?--n needs a list}"; shift ;;
    --solver) SOLVER="${2:?--solver needs a name}"; shift ;;
    --set) SETS+=(--set "${2:?--set needs section.key=value}"); shift ;;
    *) echo "c4_plate_alone: unknown option $1" >&2; exit 2 ;;
  esac
  shift
done
mkdir -p "$OUT"
PY=/usr/bin/python3
for n in $LIST; do
  dx=$("$PY" -c "print(0.05 / $n)")
  cat > "$OUT/t$n.ini" <<CASE
[run]
title = C4 plate alone under the water column's hydrostatic load, T / dx = $n
end_time = 0.06
max_window = 1e-4
output_interval = 0.01
probe_interval = 1e-4

[solid]
solver = $SOLVER
spacing = $dx
density = 2700
youngs_modulus = 67.5e9
poisson_ratio = 0.34
plane = strain
gravity = 0, -9.81
damping = 300

[solid.block clamp_left]
min = -0.05, -0.05
max = 0, 0
[solid.block plate]
min = 0, -0.05
max = 1, 0
[solid.block clamp_right]
min = 1, -0.05
max = 1.05, 0
[solid.region left]
min = -0.05, -0.05
max = 0, 0
action = clamp
clamp_face = x_max
[solid.region right]
min = 1, -0.05
max = 1.05, 0
action = clamp
clamp_face = x_min
[solid.region top]
min = 0, -$dx
max = 1, 0
action = load
force = 0, -19620
[solid.probe mid]
point = 0.5, -0.025
CASE
  "$ROOT/build/bin/fsi-run" "$OUT/t$n.ini" --out "$OUT/t$n" --force --threads 1 "${SETS[@]}" > "$OUT/t$n.txt" 2>&1
done
(cd "$ROOT/bench" && "$PY" - "$OUT" $LIST <<'PY'
import sys
import fe_clamped_plate
import fsi_results
out, ns = sys.argv[1], sys.argv[2:]
fe = fe_clamped_plate.midspan_deflection(**fe_clamped_plate.C4)
plate = fe_clamped_plate.plate_formulas(**fe_clamped_plate.C4)[0]
print("2D elasticity (finite elements): %.2f um; plate theory %.2f um" % (1e6 * fe, 1e6 * plate))
for n in ns:
    pr = fsi_results.read_probes("%s/t%s" % (out, n))
    v = -pr["mid_uy"][-1]
    print("T / dx = %s: %.2f um at t = %.3f s (%+.2f %% from 2D elasticity, %+.2f %% from "
          "plate theory), still moving at %.1e m/s" % (n, 1e6 * v, pr["time"][-1],
          100 * (v / fe - 1), 100 * (v / plate - 1), abs(pr["mid_vy"][-1])))
PY
) | tee "$OUT/c4_plate_alone.txt"
