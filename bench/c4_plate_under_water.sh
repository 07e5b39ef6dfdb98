#!/usr/bin/env bash
# fsi bench: C4 settled mid-span deflection against plate theory and FE, per T/dx
# C4 water column on an aluminium plate (docs/validation.md C4):
# cases/c4_plate_under_water.ini at T / dx = N for each N, and the settled mid-span
# deflection against plate theory (68.6 micrometres, 003 Eq. 53) and against the same
# with the shear deflection of a Timoshenko beam.
#
#   bench/c4_plate_under_water.sh [OUT] [--n "4 8 12"] [--resume | --report] [--threads T] [--set k=v ...]
#
# Each run's output is OUT/nN (log OUT/nN.txt); writes OUT/c4_plate_under_water.md (dx,
# particles, windows and the solid's sub-steps per window, settled deflection and its
# errors, wall time) and OUT/c4_plate_under_water.png (bench/c4_plate_under_water.py).
# Default on 2 threads, on a quiet machine: T / dx = 4 about 3 min, 8 about 14 min, 12
# about 45 min.
set -euo pipefail
. "$(dirname "${BASH_SOURCE[0]}")/sweep.bash"
sweep_parse c4_plate_under_water --n "4 8 12" "$@"
T=0.05      # plate thickness (m)

DIRS=()
for n in $LIST; do
  dx=$("$PY" -c "print(repr($T / $n))")
  DIRS+=("$OUT/n$n")
  log "n$n: dx = T / $n = $dx m"
  sweep_run "$OUT/n$n" "$ROOT/cases/c4_plate_under_water.ini" \
    --set "fluid.spacing=$dx" --set "solid.spacing=$dx"
done

"$PY" "$ROOT/bench/c4_plate_under_water.py" --png "$OUT/c4_plate_under_water.png" \
  --md "$OUT/c4_plate_under_water.md" "${DIRS[@]}"
cat "$OUT/c4_plate_under_water.md"
log "report: $OUT/c4_plate_under_water.md, plot: $OUT/c4_plate_under_water.png"
