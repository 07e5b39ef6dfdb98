#!/usr/bin/env bash
# fsi bench: C2 gate free end against Antoci et al. 2007's experiment, per T/dx
# C2 dam break through an elastic rubber gate (docs/validation.md
# C2): cases/c2_elastic_gate.ini at several resolutions T / dx (T = 5 mm the gate's
# thickness), and the gate's free end against Antoci et al. 2007's experiment.
#
#   bench/c2_elastic_gate.sh [OUT] [--n "2 3 4"] [--resume | --report] [--threads T] [--set k=v ...]
#
# Each run's output is OUT/tN (log OUT/tN.txt), N = T / dx. Every length that depends on
# the spacing follows it: the gate hangs from y = 0.08 m to one spacing above the floor
# (0.08 m - dx long: 0.079 m at dx = 1 mm), the fluid walls are four spacings thick, the
# probe sits on the middle point of the gate's lowest row (of the middle two, the
# downstream one). Writes
# OUT/c2_elastic_gate.md (dx, particles, NRMSE of x and y, wall time),
# OUT/c2_elastic_gate.png and OUT/c2_snapshots.png (bench/c2_elastic_gate.py), and the
# accuracy against speed of the finished runs: OUT/accuracy_speed.csv and
# OUT/c2_accuracy_speed.png (bench/accuracy_speed.py).
# --resume keeps the runs of OUT that finished; --report runs nothing and compares the
# runs in OUT (finished or not). --set is passed to every run.
# Default N = 2 3 4 on 1 thread: the accuracy-against-speed chart of docs/validation.md
# (T / dx = 2 shows the lattice that is too coarse: its gate is 4 times too stiff, two
# points across; 5 takes about 1.5 h on one loaded core).
set -euo pipefail

THREADS=1
. "$(dirname "${BASH_SOURCE[0]}")/sweep.bash"
sweep_parse c2_elastic_gate --n "2 3 4" "$@"
calc() { "$PY" -c "print($1)"; }

DIRS=()
for n in $LIST; do
  dx=$(calc "0.005 / $n")
  w=$(calc "4 * $dx")
  DIRS+=("$OUT/t$n")
  log "t$n: dx = T / $n = $dx m"
  sweep_run "$OUT/t$n" "$ROOT/cases/c2_elastic_gate.ini" \
    --set "fluid.spacing=$dx" --set "solid.spacing=$dx" \
    --set "solid.block gate.min=0.1,$dx" \
    --set "solid.probe tip.point=$(calc "0.1 + ($n // 2 + 0.5) * $dx"),$(calc "1.5 * $dx")" \
    --set "fluid.wall floor.min=-$w,-$w" --set "fluid.wall left.min=-$w,0" \
    --set "fluid.wall above_gate.max=$(calc "0.1 + $w"),0.15"
done

"$PY" "$ROOT/bench/c2_elastic_gate.py" --png "$OUT/c2_elastic_gate.png" \
  --snapshots "$OUT/c2_snapshots.png" --csv-out "$OUT/c2_elastic_gate.csv" "${DIRS[@]}" |
  tee "$OUT/c2_elastic_gate.txt"

REPORT="$OUT/c2_elastic_gate.md"
echo "solvers,resolution,dx_m,particles,threads,wall_s,error" > "$OUT/accuracy_speed.csv"
{
  echo "| dx | T / dx | fluid particles | solid points (gate + clamp) | end | NRMSE x (points) | NRMSE y (points) | largest ux (t) | largest uy (t) | wall time | threads |"
  echo "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |"
  tail -n +2 "$OUT/c2_elastic_gate.csv" | while IFS=, read -r run dx ratio nf ns tend ex nx ey ny pux tux puy tuy; do
    txt="$run.txt"
    wt=$(sed -n 's/^fsi run: finished in \([0-9.]*\) s.*/\1/p' "$txt" | tail -1 || true)
    [ -n "$wt" ] || wt=$(awk '/^wall_time_s/ {print $2}' "$txt" | tail -1)
    thr=$(cat "$run/fluid.log" "$run/solid.log" 2>/dev/null | grep -o 'on [0-9]* thread(s)' | tail -1 | awk '{print $2}' || true)
    if grep -q "^fsi run: finished" "$txt"; then endst="t = $tend s"; else endst="unstable, last probe row t = $tend s"; fi
    if grep -q "^fsi run: finished" "$txt" && [ "$nx" = 9 ]; then
      echo "$(sweep_solvers "$run"),T/dx=$(calc "round($ratio)"),$dx,$nf,${thr:-?},$wt,$ex" >> "$OUT/accuracy_speed.csv"
    fi
    echo "| $dx m | $ratio | $nf | $ns | $endst | $(calc "'-' if $nx == 0 else '%.1f %%' % (100 * $ex)") ($nx / 9) | $(calc "'-' if $ny == 0 else '%.1f %%' % (100 * $ey)") ($ny / 9) | $pux m ($tux s) | $puy m ($tuy s) | ${wt} s | ${thr:-?} |"
  done
} > "$REPORT"
cat "$REPORT"
"$PY" "$ROOT/bench/accuracy_speed.py" --title "C2 elastic gate: NRMSE of the gate's x against run time" \
  --error-label "NRMSE of the free end's x" --goal 0.10 --png "$OUT/c2_accuracy_speed.png" \
  "$OUT/accuracy_speed.csv"
log "report: $REPORT, plots: $OUT/c2_elastic_gate.png, $OUT/c2_snapshots.png"
