#!/usr/bin/env bash
# fsi bench: F1 surge front against Martin & Moyce 1952, per resolution
# F1 dam break (docs/validation.md F1): cases/f1_dam_break.ini, the
# column a = 0.05715 m wide, 2a high of Martin & Moyce 1952 (n^2 = 2, a = 2.25 in), at
# several resolutions dx = a / N, and the surge front against the data.
#
#   bench/f1_dam_break.sh [OUT] [--n "15 20 30"] [--resume | --report] [--threads T] [--set k=v ...]
#
# Each run's output is OUT/nN (log OUT/nN.txt); writes OUT/f1_dam_break.md (dx, fluid
# particles, RMS of (Z_sim - Z_exp) / Z_exp, wall time, particle-steps/s from the fluid's
# performance line) and OUT/f1_dam_break.png (bench/f1_dam_break.py), and the accuracy
# against speed of the runs that reached every data point: OUT/accuracy_speed.csv and
# OUT/f1_accuracy_speed.png (bench/accuracy_speed.py). --resume keeps the
# runs of OUT that finished; --report runs nothing and compares the runs in OUT (finished
# or not). --set is passed to every run (e.g. fluid.sound_speed=...).
# Default N = 15 20 30 on 2 threads (ULPH at the case's settings, 1 thread on an idle
# machine: a / 20 about 22 s, a / 30 about 70 s).
set -euo pipefail
. "$(dirname "${BASH_SOURCE[0]}")/sweep.bash"
sweep_parse f1_dam_break --n "15 20 30" "$@"

. "$ROOT/bench/f1_run.bash"
A=$F1_A
calc() { f1_calc "$1"; }

DIRS=()
for n in $LIST; do
  DIRS+=("$OUT/n$n")
  log "n$n: dx = a / $n = $(calc "$A / $n") m"
  f1_args "$n"
  sweep_run "$OUT/n$n" "${F1_ARGS[@]}"
done

"$PY" "$ROOT/bench/f1_dam_break.py" --png "$OUT/f1_dam_break.png" \
  --csv-out "$OUT/f1_dam_break.csv" "${DIRS[@]}" | tee "$OUT/f1_dam_break.txt"

REPORT="$OUT/f1_dam_break.md"
echo "solvers,resolution,dx_m,particles,threads,wall_s,error" > "$OUT/accuracy_speed.csv"
{
  echo "| dx | a / dx | fluid particles | points | RMS (Z_sim - Z_exp) / Z_exp | end | fluid in walls (most, end) | wall time | threads | particle-steps/s |"
  echo "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |"
  tail -n +2 "$OUT/f1_dam_break.csv" | while IFS=, read -r run dx ratio n pts rms inmax inend; do
    txt="$run.txt"
    wt=$(sed -n 's/^fsi run: finished in \([0-9.]*\) s.*/\1/p' "$txt" | tail -1)
    [ -n "$wt" ] || wt=$(awk '/^wall_time_s/ {print $2}' "$txt" | tail -1)
    [ -n "$wt" ] || wt=$(sed -n 's/^fsi run: run failed.* after \([0-9.]*\) s.*/\1/p' "$txt" | tail -1)
    thr=$(grep -o 'on [0-9]* thread(s)' "$run/fluid.log" | tail -1 | awk '{print $2}')
    pss=$(grep -o '([0-9.e+]* particle-steps/s)' "$run/fluid.log" | tail -1 | tr -d '()' | awk '{print $1}')
    tend=$(grep "^$run " "$OUT/f1_dam_break.txt" | grep -o "t_end=[0-9.]*" | cut -d= -f2)
    if grep -q "^fsi run: finished" "$txt"; then endst="t = $tend s"; else endst="unstable, last frame t = $tend s"; fi
    echo "| $dx m | $ratio | $n | $pts / 15 | $(calc "'%.1f %%' % (100 * $rms)") | $endst | $inmax, $inend | ${wt} s | ${thr:-?} | ${pss:-?} |"
    if [ "$pts" = 15 ]; then
      echo "$(sweep_solvers "$run"),a/$(calc "round($ratio)"),$dx,$n,${thr:-?},$wt,$rms" >> "$OUT/accuracy_speed.csv"
    fi
  done
} > "$REPORT"
cat "$REPORT"
"$PY" "$ROOT/bench/accuracy_speed.py" --title "F1 dam break: surge-front error against run time" \
  --error-label "RMS (Z_sim - Z_exp) / Z_exp" --goal 0.05 --png "$OUT/f1_accuracy_speed.png" \
  "$OUT/accuracy_speed.csv"
log "report: $REPORT, plot: $OUT/f1_dam_break.png"
