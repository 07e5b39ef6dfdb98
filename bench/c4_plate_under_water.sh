#!/usr/bin/env bash
# C4 water column on an aluminium plate (docs/benchmarks.md C4, docs/validation.md C4):
# cases/c4_plate_under_water.ini at T / dx = N for each N, and the settled mid-span
# deflection against plate theory (68.6 micrometres, 003 Eq. 53).
#
#   bench/c4_plate_under_water.sh [OUT] [--n "8 10 12"] [--resume | --report] [--threads T] [--set k=v ...]
#
# Each run's output is OUT/nN (log OUT/nN.txt); writes OUT/c4_plate_under_water.md (dx,
# particles, windows and the solid's sub-steps per window, settled deflection and its
# error, wall time) and OUT/c4_plate_under_water.png (bench/c4_plate_under_water.py).
# --resume keeps the runs of OUT that finished; --report runs nothing. Default on 2
# threads: T / dx = 8 about 14 min, 12 about 45 min.
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
RUN="$ROOT/build/bin/fsi-run"
PY=/usr/bin/python3
CASE="$ROOT/cases/c4_plate_under_water.ini"
OUT="$ROOT/out/bench/c4_plate_under_water"
NS="8 10 12"
RESUME=0
THREADS=2
EXTRA=()
while [ $# -gt 0 ]; do
  case "$1" in
    --n) NS="$2"; shift ;;
    --resume) RESUME=1 ;;
    --report) RESUME=2 ;;
    --threads) THREADS="$2"; shift ;;
    --set) EXTRA+=(--set "$2"); shift ;;
    -*) echo "c4_plate_under_water: unknown option $1" >&2; exit 2 ;;
    *) OUT="$1" ;;
  esac
  shift
done
mkdir -p "$OUT"
log() { echo "[c4_plate_under_water] $*" >&2; }
T=0.05      # plate thickness (m)

DIRS=()
for n in $NS; do
  name="n$n"
  DIRS+=("$OUT/$name")
  if { [ "$RESUME" = 1 ] && grep -q "^fsi run: finished" "$OUT/$name.txt" 2>/dev/null; } ||
     { [ "$RESUME" = 2 ] && [ -f "$OUT/$name/probes.csv" ]; }; then
    log "$name: kept from an earlier run"
    continue
  fi
  dx=$("$PY" -c "print(repr($T / $n))")
  log "$name: dx = T / $n = $dx m ..."
  set +e
  "$RUN" "$CASE" --out "$OUT/$name" --force --threads "$THREADS" \
    --set "fluid.spacing=$dx" --set "solid.spacing=$dx" "${EXTRA[@]}" > "$OUT/$name.txt" 2>&1
  rc=$?
  set -e
  [ $rc = 0 ] || log "$name: run failed (exit $rc), see $OUT/$name.txt; its probes are still compared"
done

"$PY" "$ROOT/bench/c4_plate_under_water.py" --png "$OUT/c4_plate_under_water.png" \
  --md "$OUT/c4_plate_under_water.md" "${DIRS[@]}"
cat "$OUT/c4_plate_under_water.md"
log "report: $OUT/c4_plate_under_water.md, plot: $OUT/c4_plate_under_water.png"
