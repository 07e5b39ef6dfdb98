#!/usr/bin/env bash
# fsi bench: F2 free-surface elevation, and its error against Faltinsen et al. 2000's data
# F2 sloshing (docs/validation.md F2): runs cases/f2_sloshing.ini
# (000 §4.3: H = 0.5 m, T = 1.875 s, 6 s) and cases/f2_sloshing_faltinsen.ini (Faltinsen
# et al. 2000: H = 0.6 m, T = 1.3 s, 10 s) side by side, one thread each, then
# bench/f2_sloshing.py plots FS1 and compares the second with the measured elevation.
#
#   bench/f2_sloshing.sh [OUT] [--threads T] [--report] [--set k=v ...]
#
# Outputs: OUT/seed and OUT/faltinsen (runs, logs OUT/*.txt), OUT/f2_sloshing.png (FS1
# of the seed's scene), OUT/f2_sloshing_faltinsen.png (against the experiment) and
# OUT/f2_sloshing.md (the table of docs/validation.md). --report runs nothing and
# compares what OUT holds. A run that stops (unstable) is reported with its last time.
# About 5 min (seed) and 8 min (Faltinsen) on a shared 2-core machine.
set -euo pipefail

THREADS=1
. "$(dirname "${BASH_SOURCE[0]}")/sweep.bash"
sweep_parse f2_sloshing --n "" "$@"

if [ "$RESUME" != 2 ]; then
  pids=()
  for name in seed faltinsen; do
    case_file="$ROOT/cases/f2_sloshing.ini"
    [ "$name" = faltinsen ] && case_file="$ROOT/cases/f2_sloshing_faltinsen.ini"
    log "$name: $(basename "$case_file") -> $OUT/$name"
    # A failed run (exit 1: unstable) is reported, not fatal: the table says where it
    # stopped.
    ( "$RUN" "$case_file" --out "$OUT/$name" --force --threads "$THREADS" \
        ${EXTRA[@]+"${EXTRA[@]}"} >"$OUT/$name.txt" 2>&1; echo "exit $?" >>"$OUT/$name.txt" ) &
    pids+=($!)
  done
  for pid in "${pids[@]}"; do wait "$pid"; done
fi
"$PY" "$ROOT/bench/f2_sloshing.py" "$OUT" \
  --data "$ROOT"/data/faltinsen2000_sloshing_h0p6_T1p3_probe0p05m_exp.csv
log "wrote $OUT/f2_sloshing.md, $OUT/f2_sloshing.png, $OUT/f2_sloshing_faltinsen.png"
