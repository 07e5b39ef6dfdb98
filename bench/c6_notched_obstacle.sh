#!/usr/bin/env bash
# C6 water impact on a notched brittle obstacle (docs/benchmarks.md C6,
# docs/validation.md C6): cases/c6_notched_obstacle.ini with bond failure and the same
# run with --set solid.failure=false, side by side (one thread each), then the crack
# initiation time and place and the damage snapshots at 004 Fig. 14's times
# (bench/fracture_scene.py).
#
#   bench/c6_notched_obstacle.sh [OUT] [--report] [--set k=v ...]
#
# Writes OUT/failure, OUT/no_failure (logs OUT/*.txt), OUT/c6_notched_obstacle.md and
# OUT/c6_notched_obstacle.png.
set -euo pipefail
THREADS=1
. "$(dirname "${BASH_SOURCE[0]}")/sweep.bash"
sweep_parse c6_notched_obstacle --n "" "$@"

sweep_run_failure_pair "$ROOT/cases/c6_notched_obstacle.ini"

# Initiation: damage grown by 0.25 (the crack runs between rows: bench/fracture_scene.py).
"$PY" "$ROOT/bench/fracture_scene.py" --png "$OUT/c6_notched_obstacle.png" \
  --md "$OUT/c6_notched_obstacle.md" --threshold 0.25 --times 0.15,0.20,0.22,0.26 \
  --xlim=0.2,0.45 --ylim=-0.01,0.2 --pmax 6000 \
  --title "C6 water impact on a notched brittle obstacle (ULPH + NOSB-PD)" \
  "$OUT/failure" "$OUT/no_failure"
cat "$OUT/c6_notched_obstacle.md"
log "report: $OUT/c6_notched_obstacle.md, plot: $OUT/c6_notched_obstacle.png"
