#!/usr/bin/env bash
# fsi bench: C5 baffle crack initiation time and place, with and without bond failure
# C5 dam break against a soil-like baffle that fails (docs/validation.md
# C5): cases/c5_soil_baffle.ini with bond failure and the same run
# with --set solid.nosbpd.failure=false, side by side (one thread each), then the crack
# initiation time and place and the damage snapshots (bench/fracture_scene.py).
#
#   bench/c5_soil_baffle.sh [OUT] [--report] [--set k=v ...]
#
# Writes OUT/failure, OUT/no_failure (logs OUT/*.txt), OUT/c5_soil_baffle.md and
# OUT/c5_soil_baffle.png. About 6 minutes on a quiet machine.
set -euo pipefail
THREADS=1
. "$(dirname "${BASH_SOURCE[0]}")/sweep.bash"
sweep_parse c5_soil_baffle --n "" "$@"

sweep_run_failure_pair "$ROOT/cases/c5_soil_baffle.ini"

"$PY" "$ROOT/bench/fracture_scene.py" --png "$OUT/c5_soil_baffle.png" --md "$OUT/c5_soil_baffle.md" \
  "$OUT/failure" "$OUT/no_failure"
cat "$OUT/c5_soil_baffle.md"
log "report: $OUT/c5_soil_baffle.md, plot: $OUT/c5_soil_baffle.png"
