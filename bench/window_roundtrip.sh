#!/usr/bin/env bash
# fsi bench: wall time of one coupling window's message round trip on loopback
# Round-trip cost of one coupling window on loopback: grant -> solid state -> fluid
# loads -> both done, measured by the coupler for every window of the example
# participants (whose own work is negligible), reported as the median over windows
# of each run and the median over REPEATS runs.
#   usage: fsi bench window_roundtrip [REPEATS] [PARTICLES...]   (default 5 runs; 100 1000 10000)
set -euo pipefail
ROOT="$(cd "$(dirname "$0")/.." && pwd)"
RUN="$ROOT/build/bin/fsi-run"
repeats="${1:-5}"
shift || true
sizes=("${@:-100 1000 10000}")
read -r -a sizes <<<"${sizes[*]}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

median() { sort -g | awk '{a[NR] = $1} END {print (NR % 2) ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2}'; }

printf "%10s %8s %14s %14s %14s\n" particles windows "median [us]" "p90 [us]" "runs (median us)"
for n in "${sizes[@]}"; do
  medians=()
  p90s=()
  for r in $(seq "$repeats"); do
    out="$work/n${n}_$r"
    # 2000 windows of 1 ms; one sub-step per window; no frames or probes in between.
    "$RUN" "$ROOT/cases/demo_spring_dashpot.ini" --out "$out" --set run.end_time=2 \
      --set solid.particles="$n" --set solid.time_step=1e-3 --set run.output_interval=100 \
      --set run.probe_interval=100 >"$out.txt" 2>&1 || { cat "$out.txt"; exit 1; }
    medians+=("$(awk '$1 == "window_round_trip_median" {print $3}' "$out/run.log")")
    p90s+=("$(awk '$1 == "window_round_trip_p90" {print $3}' "$out/run.log")")
    windows=$(awk '$1 == "windows" {print $3}' "$out/run.log")
  done
  m=$(printf "%s\n" "${medians[@]}" | median)
  p=$(printf "%s\n" "${p90s[@]}" | median)
  printf "%10d %8d %14.1f %14.1f   %s\n" "$n" "$windows" "$m" "$p" "${medians[*]}"
done
