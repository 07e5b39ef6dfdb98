#!/usr/bin/env bash
# fsi bench: wall time and bit-identical results of a run under 0-80 % message loss
# Cost of message loss: one case run at several loss fractions of the bus's test switch
# (FSI_TEST_DROP_FRACTION: every process withholds that fraction of the messages it
# publishes, copies and resends included; receivers lose nothing more), REPEATS runs
# per fraction, interleaved (0, 20, 50, 80 %, 0, 20, ...) so that a change in the
# machine's load hits every fraction alike. Prints per fraction: the median wall time
# of `fsi run`, its ratio to the loss-free median, whether every run's results are
# bit-identical to the first loss-free run's (h5diff, probes.csv), and per window the
# median resend requests (all processes) and extra copies sent under measured loss.
#   usage: bench/loss_table.sh CASE [REPEATS] [--set key=value ...]   (default 3 runs)
set -euo pipefail
ROOT="$(cd "$(dirname "$0")/.." && pwd)"
RUN="$ROOT/build/bin/fsi-run"
case_file="$1"
shift
repeats=3
if [ $# -gt 0 ] && [[ "$1" =~ ^[0-9]+$ ]]; then repeats="$1"; shift; fi
fractions=(0 0.2 0.5 0.8)
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
failed="$(mktemp -d /tmp/loss_table_failed.XXXXXX)"   # failed runs are kept here

median() { sort -g | awk '{a[NR] = $1} END {print (NR % 2) ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2}'; }
identical() {
  local f
  for f in solid.h5 fluid.h5; do
    [ -e "$1/$f" ] || continue
    h5diff -q "$1/$f" "$2/$f" >/dev/null 2>&1 || return 1
  done
  cmp -s "$1/probes.csv" "$2/probes.csv"
}
# "NAME N" of the coupler's bus line plus "KEY = N" of the participants' blocks in
# run.log, per window.
per_window() {
  awk -v name="$2" -v key="$3" '
    $1 == "windows" {w = $3}
    $1 == "bus" && $2 == "coupler:" && match($0, name " [0-9]+") {
      s += substr($0, RSTART + length(name) + 1, RLENGTH - length(name) - 1) }
    $1 == key {s += $3}
    END {printf "%.2f\n", (w > 0 ? s / w : -1)}' "$1"
}

echo "# $(basename "$case_file") $* : $repeats interleaved runs per loss, load average at start: $(cut -d' ' -f1-3 /proc/loadavg)"
for r in $(seq "$repeats"); do
  for f in "${fractions[@]}"; do
    out="$work/f${f}_$r"
    t0=$(date +%s.%N)
    status=0
    FSI_TEST_DROP_FRACTION=$f FSI_TEST_DROP_SEED=$r "$RUN" "$case_file" --out "$out" "$@" \
      >"$out.txt" 2>&1 || status=$?
    t1=$(date +%s.%N)
    awk -v a="$t0" -v b="$t1" 'BEGIN {printf "%.2f\n", b - a}' >>"$work/wall_$f"
    if [ "$status" -eq 0 ] && identical "$work/f0_1" "$out"; then
      echo yes
    else
      echo "no (status $status)"
      cp -r "$out" "$out.txt" "$failed/"
    fi >>"$work/same_$f"
    per_window "$out/run.log" "resend requests" bus_resend_requests >>"$work/req_$f"
    per_window "$out/run.log" "extra copies" bus_extra_copies >>"$work/copies_$f"
  done
done
loss_free=$(median <"$work/wall_0")
rmdir "$failed" 2>/dev/null || echo "# failed runs kept in $failed"
printf "| loss | wall time median [s] | ratio to 0 %% | bit-identical | resend requests per window | extra copies per window | runs [s] |\n|---|---|---|---|---|---|---|\n"
for f in "${fractions[@]}"; do
  wall=$(median <"$work/wall_$f")
  same=$(sort -u "$work/same_$f" | paste -sd, -)
  [ "$same" = yes ] && same="yes ($repeats of $repeats)"
  printf "| %s %% | %s | %.1f | %s | %s | %s | %s |\n" "$(awk -v f="$f" 'BEGIN {print 100 * f}')" "$wall" \
    "$(awk -v a="$wall" -v b="$loss_free" 'BEGIN {print a / b}')" "$same" \
    "$(median <"$work/req_$f")" "$(median <"$work/copies_$f")" "$(paste -sd' ' "$work/wall_$f")"
done
