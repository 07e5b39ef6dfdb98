#!/usr/bin/env bash
# fsi bench: S1-S3 solid accuracy per resolution and interaction updates per second
# Validation and performance of a solid model (NOSB-PD by default): S1, S2, S3 of
# docs/validation.md at several resolutions, and interaction updates per second at 1
# and 2 threads on S2 at T/dx = 40. Writes OUT/solid_validation.md (the tables of
# docs/validation.md, docs/pseudo_spring.md) and keeps every run's output folder under OUT.
#
#   fsi bench solid_validation [OUT] [--quick] [--resume] [--solver NAME] [--threads T]
#                              [--no-perf]
#
# --solver runs every case with --set solid.solver=NAME (nosbpd, pseudo_spring, ...).
# --threads sets the validation runs' thread count (default 2); --no-perf skips the
# performance runs (for a sweep that shares the machine with other runs).
#
# --quick skips the finest resolutions (S1 dx = 0.005 m, S2 T/dx = 40): about 6 min
# instead of about 25 min on this 2-core machine. --resume keeps the validation runs
# that already finished in OUT (the performance runs are always repeated). Runs use 2 threads except the
# performance runs, which use 1 and 2 threads in turn, three times each (medians).
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
RUN="$ROOT/build/bin/fsi-run"
PY=/usr/bin/python3
OUT="$ROOT/out/bench/solid_validation"
QUICK=0
RESUME=0
SOLVER=nosbpd
THREADS=2
PERF=1
while [ $# -gt 0 ]; do
  case "$1" in
    --quick) QUICK=1 ;;
    --resume) RESUME=1 ;;
    --no-perf) PERF=0 ;;
    --solver) SOLVER="${2:?--solver needs a name}"; shift ;;
    --threads) THREADS="${2:?--threads needs a number}"; shift ;;
    -*) echo "solid_validation: unknown option $1" >&2; exit 2 ;;
    *) OUT="$1" ;;
  esac
  shift
done
mkdir -p "$OUT"
REPORT="$OUT/solid_validation.md"
calc() { "$PY" -c "print($1)"; }
log() { echo "[solid_validation] $*" >&2; }

run_case() {   # run_case NAME CASE [--set ...]: output in OUT/NAME, log in OUT/NAME.txt
  local name="$1" case_file="$2"; shift 2
  if [ "$RESUME" = 1 ] && grep -q "^fsi run: finished" "$OUT/$name.txt" 2>/dev/null; then
    log "$name: kept from an earlier run"
    return
  fi
  log "$name ..."
  local t0=$SECONDS
  "$RUN" "$ROOT/cases/$case_file" --out "$OUT/$name" --force --threads "$THREADS" \
    --set solid.solver="$SOLVER" "$@" \
    >"$OUT/$name.txt" 2>&1 || { echo "run $name failed, see $OUT/$name.txt" >&2; exit 1; }
  log "$name done in $((SECONDS - t0)) s"
}

wall_of() {  # wall_of NAME: the run's wall time as fsi run reported it [s]
  sed -n 's/^fsi run: finished in \([0-9.]*\) s.*/\1/p' "$OUT/$1.txt"
}

last_probe() {  # last_probe DIR COLUMN: the probe's last value
  "$PY" - "$1" "$2" <<'PY'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1] + "/probes.csv")))
print(rows[-1][sys.argv[2]])
PY
}

energy_drift() {  # energy_drift DIR: (E_end - E0) / E0 in % from the solid's log
  "$PY" - "$1" <<'PY'
import re, sys
text = open(sys.argv[1] + "/solid.log").read()
m = re.search(r"energy at the end: kinetic (\S+) J, strain (\S+) J; initial (\S+) J", text)
k, s, e0 = (float(v) for v in m.groups())
print("%+.3f" % (100.0 * (k + s - e0) / e0))
PY
}

{
echo "# Solid validation, solver = $SOLVER ($(date -u +%Y-%m-%d), $(git -C "$ROOT" rev-parse --short HEAD))"
echo
echo "The model's default keys (docs/cases.md), mirror clamps (clamp_face = x_max);"
echo "validation runs on $THREADS thread(s)."
echo

# ---- S1: cantilever, tip deflection against Timoshenko at the loaded column.
echo "## S1 cantilever (tip load, quasi-static)"
echo
echo "| dx [m] | points | tip uy [m] | Timoshenko at x = L - dx/2 [m] | error | wall [s] |"
echo "| --- | --- | --- | --- | --- | --- |"
S1_DX="0.02 0.01"; [ "$QUICK" = 1 ] || S1_DX="$S1_DX 0.005"
for dx in $S1_DX; do
  run_case "s1_dx$dx" s1_cantilever.ini --set solid.spacing="$dx" \
    --set "solid.block clamp.min=$(calc "-3*$dx"),0" --set "solid.region fixed.min=$(calc "-3*$dx"),0" \
    --set "solid.region tip_load.min=$(calc "1-$dx"),0" \
    --set "solid.probe tip.point=$(calc "1-$dx/2"),$(calc "0.1-$dx/2")"
  wall=$(wall_of "s1_dx$dx")
  uy=$(last_probe "$OUT/s1_dx$dx" tip_uy)
  # Timoshenko (003 Eq. 50 form, kappa = 5/6) with the lever arm of the loaded column.
  ref=$(calc "(lambda a: 85000*a**3/(3*22e9*0.2**3/12) + 85000*a/(5/6*22e9/2.6*0.2))(1-$dx/2)")
  n=$(grep -o '^\[solid\] [0-9]* particles' "$OUT/s1_dx$dx/solid.log" | grep -o '[0-9]*')
  echo "| $dx | $n | $uy | $(calc "'%.5e' % $ref") | $(calc "'%+.2f %%' % (100*(-$uy/$ref-1))") | $wall |"
done
echo
echo "2D finite elements with a fully clamped face (bench/fe_cantilever.py): $("$PY" "$ROOT/bench/fe_cantilever.py" | sed 's/.*ratio/ratio to Timoshenko at x = L:/')."
echo

# ---- S2: free oscillation of a clamped plate.
echo "## S2 clamped plate, free oscillation (reference t c0 / L = 72.39, A / L = 0.115)"
echo
echo "| T/dx | points | period [s] | error | amplitude [m] | error | energy drift over 0.7 s | wall [s] |"
echo "| --- | --- | --- | --- | --- | --- | --- | --- |"
S2_RES="10 20"; [ "$QUICK" = 1 ] || S2_RES="$S2_RES 40"
for r in $S2_RES; do
  dx=$(calc "0.02/$r")
  run_case "s2_T${r}" s2_plate_oscillation.ini --set solid.spacing="$dx" \
    --set "solid.block clamp.min=$(calc "-3*$dx"),-0.01" --set "solid.region fixed.min=$(calc "-3*$dx"),-0.01" \
    --set "solid.probe tip.point=$(calc "0.2-$dx/2"),$(calc "$dx/2")"
  wall=$(wall_of "s2_T${r}")
  read -r period amp < <("$PY" "$ROOT/bench/oscillation.py" "$OUT/s2_T${r}" tip_uy | tail -1 | awk '{print $2, $4}')
  n=$(grep -o '^\[solid\] [0-9]* particles' "$OUT/s2_T${r}/solid.log" | grep -o '[0-9]*')
  ref_t=$(calc "72.39*0.2/(3.25e6/1000)**0.5")
  echo "| $r | $n | $period | $(calc "'%+.2f %%' % (100*($period/$ref_t-1))") | $amp | $(calc "'%+.2f %%' % (100*($amp/0.023-1))") | $(energy_drift "$OUT/s2_T${r}") % | $wall |"
done
echo
echo "Published (003 Table 3, TLSPH): T/dx = 10: 5.68 % / 6.96 %; 20: 3.33 % / 4.35 %; 40: 2.36 % / 3.48 %."
echo

# ---- S3: steel beam period.
echo "## S3 steel beam, first-mode period (reference 0.114 s)"
echo
run_case s3 s3_steel_beam.ini
read -r period amp < <("$PY" "$ROOT/bench/oscillation.py" "$OUT/s3" tip_uy | tail -1 | awk '{print $2, $4}')
echo "period $period s, error $(calc "'%+.2f %%' % (100*($period/0.114-1))") (wall $(wall_of s3) s; 004's pseudo-spring SPH: 7.2 %)."
echo

# ---- Performance: S2 at T/dx = 40, a short run, 1 and 2 threads, medians of 3.
if [ "$PERF" = 1 ]; then
echo "## Performance (S2 at T/dx = 40, 16 120 points, 5 ms of simulated time)"
echo
echo "| threads | interaction (bond) updates/s | particle-steps/s | internal force [s] |"
echo "| --- | --- | --- | --- |"
for th in 1 2; do
  rates=""
  for rep in 1 2 3; do
    log "performance, $th thread(s), run $rep"
    "$RUN" "$ROOT/cases/s2_plate_oscillation.ini" --out "$OUT/perf_t${th}_$rep" --force \
      --threads "$th" --set solid.solver="$SOLVER" --set solid.spacing=0.0005 --set "solid.block clamp.min=-0.0015,-0.01" \
      --set "solid.region fixed.min=-0.0015,-0.01" --set run.end_time=0.005 \
      >"$OUT/perf_t${th}_$rep.txt" 2>&1
    rates="$rates $(sed -n 's/.*internal force \([0-9.]*\) s (\([0-9.e+]*\) interaction updates\/s, \([0-9.e+]*\) particle-steps.*/\2,\3,\1/p' "$OUT/perf_t${th}_$rep/solid.log")"
  done
  echo "| $th | $("$PY" -c "
import statistics, sys
r = [tuple(float(v) for v in x.split(',')) for x in sys.argv[1:]]
print('%.3g | %.3g | %.2f' % tuple(statistics.median(c) for c in zip(*r)))" $rates) |"
done
fi
} | tee "$REPORT"
log "report: $REPORT"
