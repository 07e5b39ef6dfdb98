#!/usr/bin/env bash
# fsi bench: C6 crack start and path from the notch, with and without failure
# C6 water impact on a notched brittle obstacle (docs/validation.md
# C6): cases/c6_notched_obstacle.ini with bond failure, the same
# run with --set solid.MODEL.failure=false (MODEL the run's solid model, so --set
# solid.solver=pseudo_spring swaps the pair), and the run with failure but without the case's
# no-failure zone at the foot (the case with its [solid.region foot_no_failure]
# section left out: docs/nosbpd.md, "No-failure zones"), one thread each; then the
# crack initiation time and place and the damage snapshots at 004 Fig. 14's times
# (bench/fracture_scene.py).
#
#   bench/c6_notched_obstacle.sh [OUT] [--report] [--set k=v ...]
#
# Writes OUT/failure, OUT/no_failure, OUT/failure_without_zone (logs OUT/*.txt),
# OUT/c6_notched_obstacle.md and OUT/c6_notched_obstacle.png. About 20 min per run
# on one core; the third starts when the first two have ended.
set -euo pipefail
THREADS=1
. "$(dirname "${BASH_SOURCE[0]}")/sweep.bash"
sweep_parse c6_notched_obstacle --n "" "$@"

CASE="$ROOT/cases/c6_notched_obstacle.ini"
# The case without its no-failure zone: every line from the zone's section header to
# the next blank line or section left out.
awk '/^\[solid.region foot_no_failure\]/ {skip = 1; next}
     skip && (/^\[/ || /^$/) {skip = 0}
     !skip' "$CASE" > "$OUT/case_without_zone.ini"
if grep -q "^\[solid.region foot_no_failure\]" "$OUT/case_without_zone.ini" ||
   ! grep -q "^\[solid.region foot_no_failure\]" "$CASE"; then
  log "cannot leave the zone out of $CASE: no section [solid.region foot_no_failure] found"
  exit 1
fi
sweep_run_failure_pair "$CASE"
sweep_run "$OUT/failure_without_zone" "$OUT/case_without_zone.ini"

# Initiation: damage grown by 0.25 (the crack runs between rows: bench/fracture_scene.py).
"$PY" "$ROOT/bench/fracture_scene.py" --png "$OUT/c6_notched_obstacle.png" \
  --md "$OUT/c6_notched_obstacle.md" --threshold 0.25 --times 0.15,0.20,0.22,0.26 \
  --xlim=0.2,0.45 --ylim=-0.01,0.2 --pmax 6000 \
  --title "C6 water impact on a notched brittle obstacle ($(sweep_solvers "$OUT/failure"))" \
  --also "failure, no foot zone=$OUT/failure_without_zone" \
  "$OUT/failure" "$OUT/no_failure"
cat "$OUT/c6_notched_obstacle.md"
log "report: $OUT/c6_notched_obstacle.md, plot: $OUT/c6_notched_obstacle.png"
