#!/usr/bin/env bash
# fsi bench: C6's obstacle loaded alone: does it break at the foot or the notch, per spacing
# Where C6's obstacle (cases/c6_notched_obstacle.ini) starts to break when it is loaded
# alone, as the spacing shrinks: the foot, where the bending moment is largest, or the
# notch tip, where the crack concentrates the stress over about one horizon (3 dx). The
# obstacle, its mirror clamp and the notch crack of the C6 case; a uniform load on the
# loaded face ramped from 0 to 1500 N/m over 0.2 s (mass damping 100 1/s, so the
# response is nearly quasi-static). Reports, per spacing, the largest damage growth of
# the material points at the foot (y < 10 mm) and at the notch (|y - 25 mm| < 5 mm)
# in every 1 ms frame until a point has lost 0.3 of its family.
#
#   bench/c6_notch_or_foot.sh [OUT] [--dx "0.0025 0.00125 0.000625"] [--zone H]
#
# --zone H adds the case's no-failure zone at the foot, H metres tall (C6 uses 0.0075):
# no bond with an end point in y 0 .. H breaks (docs/nosbpd.md, "No-failure zones").
#
# About 2 minutes in all (the finest spacing takes most of it).
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
OUT="$ROOT/out/bench/c6_notch_or_foot"
case "${1:-}" in "" | --*) ;; *) OUT="$1"; shift ;; esac
LIST="0.0025 0.00125 0.000625"
ZONE=""
while [ $# -gt 0 ]; do
  case "$1" in
    --dx) LIST="$2"; shift ;;
    --zone) ZONE="$2"; shift ;;
    *) echo "c6_notch_or_foot: unknown option $1" >&2; exit 2 ;;
  esac
  shift
done
mkdir -p "$OUT"
cat > "$OUT/case.ini" <<'CASE'
[run]
title = C6 obstacle alone under a growing uniform load on its loaded face
end_time = 0.045
max_window = 1e-4
output_interval = 0.001
probe_interval = 1e-3

[solid]
solver = nosbpd
spacing = 0.0025
density = 2500
youngs_modulus = 1e6
poisson_ratio = 0
plane = strain
damping = 100

[solid.nosbpd]
failure = true
critical_stretch = 0.05

[solid.block obstacle]
min = 0.3, 0
max = 0.33, 0.09
[solid.block clamp]
min = 0.3, -0.0075
max = 0.33, 0
[solid.region foot]
min = 0.3, -0.0075
max = 0.33, 0
action = clamp
clamp_face = y_max
[solid.region face]
min = 0.3, 0
max = 0.3025, 0.09
action = load
force = 1500, 0
ramp_time = 0.2

[solid.crack notch]
from = 0.299, 0.025
to = 0.308, 0.025

[solid.probe corner]
point = 0.3, 0.09
CASE
if [ -n "$ZONE" ]; then
  printf '[solid.region foot_no_failure]\nmin = 0.3, 0\nmax = 0.33, %s\naction = no_failure\n' \
    "$ZONE" >> "$OUT/case.ini"
fi
for dx in $LIST; do
  face=$(/usr/bin/python3 -c "print(0.3 + $dx)")
  "$ROOT/build/bin/fsi-run" "$OUT/case.ini" --out "$OUT/dx$dx" --force --threads 1 \
    --set "solid.spacing=$dx" --set "solid.region face.max=$face,0.09" > "$OUT/dx$dx.txt" 2>&1
  echo "dx = $dx m:"
  /usr/bin/python3 - "$ROOT/bench" "$OUT/dx$dx/solid.h5" <<'PY'
import sys
import numpy as np
sys.path.insert(0, sys.argv[1])
from fracture_scene import damage_growth
x0, body, growth = damage_growth(sys.argv[2])
foot = body & (x0[:, 1] < 0.01)
notch = body & (np.abs(x0[:, 1] - 0.025) < 0.005)
for t, g in growth:
    if g.max() > 0.02:
        print("  t = %.3f s: damage growth foot %.2f, notch %.2f" % (t, g[foot].max(), g[notch].max()))
    if g.max() > 0.3:
        break
PY
done
