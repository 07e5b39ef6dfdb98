#!/usr/bin/env bash
# fsi bench: C1 plate corner displacement against the published curves, per spacing
# C1 dam break against an elastic plate (docs/validation.md C1):
# cases/c1_elastic_plate.ini at each spacing, and the plate's upper-left corner against
# the published numerical curves (data/elastic_obstacle_xdisp_num_*.csv).
#
#   bench/c1_elastic_plate.sh [OUT] [--dx "0.004 0.002"] [--resume | --report] [--threads T] [--set k=v ...]
#
# Each spacing must divide the plate (0.012 x 0.08 m), the walls and the clamp (0.012
# m); the water column is the nearest whole number of spacings to 0.146 m. Each run's
# output is OUT/dxMM (log OUT/dxMM.txt); writes OUT/c1_elastic_plate.md (first peak of
# every curve, its NRMSE against the published curves' mean, wall time),
# OUT/c1_elastic_plate.png (bench/c1_elastic_plate.py), and the accuracy against wall
# time of the runs that reached 0.4 s: OUT/accuracy_speed.csv, OUT/c1_accuracy_speed.png
# (bench/accuracy_speed.py).
set -euo pipefail
. "$(dirname "${BASH_SOURCE[0]}")/sweep.bash"
sweep_parse c1_elastic_plate --dx "0.004 0.002" "$@"

DIRS=()
for dx in $LIST; do
  dir="$OUT/dx$("$PY" -c "print('%g' % (1e3 * $dx))")mm"
  width=$("$PY" -c "print(repr(round(0.146 / $dx) * $dx))")
  DIRS+=("$dir")
  log "$(basename "$dir"): dx = $dx m, water column $width m wide"
  sweep_run "$dir" "$ROOT/cases/c1_elastic_plate.ini" \
    --set "fluid.spacing=$dx" --set "solid.spacing=$dx" --set "fluid.block water.max=$width,0.292"
done

"$PY" "$ROOT/bench/c1_elastic_plate.py" --png "$OUT/c1_elastic_plate.png" \
  --md "$OUT/c1_elastic_plate.md" --csv-out "$OUT/accuracy_speed.csv" "${DIRS[@]}"
cat "$OUT/c1_elastic_plate.md"
"$PY" "$ROOT/bench/accuracy_speed.py" --title "C1 elastic plate: NRMSE of the corner's u_x against run time" \
  --error-label "NRMSE of u_x against the published curves' mean" --goal 0.075 \
  --goal-label "closest published curve to the other three" --png "$OUT/c1_accuracy_speed.png" \
  "$OUT/accuracy_speed.csv"
log "report: $OUT/c1_elastic_plate.md, plots: $OUT/c1_elastic_plate.png, $OUT/c1_accuracy_speed.png"
