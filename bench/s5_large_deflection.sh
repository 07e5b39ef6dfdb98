#!/usr/bin/env bash
# fsi bench: S5 large-deflection cantilever tip against the elastica, per N_y
# S5: 003 §3.1's cantilever under the large tip load (alpha = P L^2 / (E I) = 1),
# quasi-static, against the elastica (bench/elastica.py): TLSPH with Saint Venant-Kirchhoff
# at N_y = T / dx = 5, 10, 20, the other total-form laws (linear_elastic, i.e. 003's
# Almansi-Hooke form, and neo_hookean) and NOSB-PD at N_y = 10, and, for comparison with
# what 003 did, TLSPH at N_y = 10 run the way 003 ran it (load ramped over 1.5 ms, no
# damping, deflection read at 3 ms). Writes OUT/s5_large_deflection.md and keeps every
# run's output folder under OUT.
#
#   bench/s5_large_deflection.sh [OUT] [--n "5 10 20"] [--resume] [--threads T]
#
# One run at a time, 1 thread by default (the runs are short: about 5 s, 20 s and
# 160 s for N_y = 5, 10, 20 on one core of this machine).
#
# The reference of a run is the elastica with the load at the loaded column, x = L - dx/2
# (the lever arm changes with dx: the same convention as S1 in bench/solid_validation.sh),
# and the tip is the mid-thickness point of that column: the mean of the probes
# tip_above and tip_below (for odd N_y both sit on the point at y = T/2).
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
RUN="$ROOT/build/bin/fsi-run"
CASE="$ROOT/cases/s5_large_deflection_cantilever.ini"
PY=/usr/bin/python3
OUT="$ROOT/out/bench/s5_large_deflection"
LIST="5 10 20"
RESUME=0
THREADS=1
while [ $# -gt 0 ]; do
  case "$1" in
    --n) LIST="${2:?--n needs a list}"; shift ;;
    --resume) RESUME=1 ;;
    --threads) THREADS="${2:?--threads needs a number}"; shift ;;
    -*) echo "s5_large_deflection: unknown option $1" >&2; exit 2 ;;
    *) OUT="$1" ;;
  esac
  shift
done
mkdir -p "$OUT"
REPORT="$OUT/s5_large_deflection.md"
L=0.1
T=0.01
calc() { "$PY" -c "print($1)"; }
log() { echo "[s5_large_deflection] $*" >&2; }

geometry() {  # geometry N: GEOM = the --set options that put the case on dx = T / N
  local n="$1" dx ya yb
  dx=$(calc "$T/$n")
  # Even N: the two rows next to y = T/2; odd N: the row on it (a probe point halfway
  # between two rows would pick either).
  if [ $((n % 2)) = 0 ]; then ya=$(calc "$T/2+$dx/2"); yb=$(calc "$T/2-$dx/2")
  else ya=$(calc "$T/2"); yb=$ya; fi
  GEOM=(--set solid.spacing="$dx"
    --set "solid.block clamp.min=$(calc "-3*$dx"),0"
    --set "solid.region fixed.min=$(calc "-3*$dx"),0"
    --set "solid.region tip_load.min=$(calc "$L-$dx"),0"
    --set "solid.probe tip_above.point=$(calc "$L-$dx/2"),$ya"
    --set "solid.probe tip_below.point=$(calc "$L-$dx/2"),$yb")
}

run_case() {   # run_case NAME [--set ...]: output in OUT/NAME, log in OUT/NAME.txt
  local name="$1"; shift
  if [ "$RESUME" = 1 ] && grep -q "^fsi run: finished" "$OUT/$name.txt" 2>/dev/null; then
    log "$name: kept from an earlier run"
    return
  fi
  log "$name ..."
  local t0=$SECONDS
  "$RUN" "$CASE" --out "$OUT/$name" --force --threads "$THREADS" "$@" \
    >"$OUT/$name.txt" 2>&1 || { echo "run $name failed, see $OUT/$name.txt" >&2; return 1; }
  log "$name done in $((SECONDS - t0)) s"
}

row() {  # row NAME SOLVER LAW N NOTE: one table row from the run's probes and logs
  local name="$1" solver="$2" law="$3" n="$4" note="$5" wall points ref
  wall=$(sed -n 's/^fsi run: finished in \([0-9.]*\) s.*/\1/p' "$OUT/$name.txt")
  points=$(grep -o '^\[solid\] [0-9]* particles' "$OUT/$name/solid.log" | grep -o '[0-9]*')
  read -r -a ref < <("$PY" "$ROOT/bench/elastica.py" --quiet --length "$(calc "$L-$T/$n/2")")
  "$PY" - "$OUT/$name/probes.csv" "$solver" "$law" "$n" "$points" "$wall" "$note" "${ref[@]}" <<'PY'
import csv, math, sys
path, solver, law, n, points, wall, note = sys.argv[1:8]
dv_ref, dh_ref, rv_ref, rh_ref = (float(v) for v in sys.argv[8:12])
rows = list(csv.DictReader(open(path)))
last = rows[-1]
mean = lambda q: 0.5 * (float(last["tip_above_" + q]) + float(last["tip_below_" + q]))
# The load points down and the tip moves back (-x): deflections are the magnitudes.
dv, dh = -mean("uy"), -mean("ux")
speed = math.hypot(mean("vx"), mean("vy"))
print(f"| {solver} | {law}{note} | {n} | {points} | {1e3 * dv:.3f} | {1e3 * dh:.3f} | "
      f"{1e3 * dv_ref:.3f} / {1e3 * dh_ref:.3f} | {100 * (dv / dv_ref - 1):+.2f} % | "
      f"{100 * (dh / dh_ref - 1):+.2f} % | {100 * (dv / rv_ref - 1):+.2f} % / "
      f"{100 * (dh / rh_ref - 1):+.2f} % | {speed:.1e} | {wall} |")
PY
}

{
echo "# S5 large-deflection cantilever ($(date -u +%Y-%m-%d), $(git -C "$ROOT" rev-parse --short HEAD))"
echo
echo "cases/s5_large_deflection_cantilever.ini (003 §3.1's beam, alpha = 1, plane stress,"
echo "quasi-static: ramp 5 ms, mass damping 1e4 1/s, read at 10 ms), $THREADS thread(s), one run at a time."
echo "Tip = mid-thickness point of the loaded column x = L - dx/2; reference = the elastica"
echo "with the load at that lever arm (bench/elastica.py); Reissner = the elastica plus shear"
echo "and axial strain (information); deflections in mm, speed = the tip's remaining speed."
echo
echo "| solver | law | N_y | points | delta_v [mm] | delta_h [mm] | elastica v / h [mm] | error v | error h | against Reissner v / h | tip speed [m/s] | wall [s] |"
echo "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |"
for n in $LIST; do
  geometry "$n"
  run_case "tlsph_svk_n$n" --set solid.solver=tlsph "${GEOM[@]}" &&
    row "tlsph_svk_n$n" tlsph saint_venant_kirchhoff "$n" "" ||
    echo "| tlsph | saint_venant_kirchhoff | $n | failed: see $OUT/tlsph_svk_n$n.txt |"
done
geometry 10
for law in linear_elastic neo_hookean; do
  run_case "tlsph_${law}_n10" --set solid.solver=tlsph --set solid.constitutive=$law "${GEOM[@]}" &&
    row "tlsph_${law}_n10" tlsph "$law" 10 "" ||
    echo "| tlsph | $law | 10 | failed: see $OUT/tlsph_${law}_n10.txt |"
done
for law in saint_venant_kirchhoff linear_elastic; do
  run_case "nosbpd_${law}_n10" --set solid.solver=nosbpd --set solid.constitutive=$law "${GEOM[@]}" &&
    row "nosbpd_${law}_n10" nosbpd "$law" 10 "" ||
    echo "| nosbpd | $law | 10 | failed: see $OUT/nosbpd_${law}_n10.txt |"
done
# 003's protocol: dynamic, undamped, read at 3 ms (1.25 first periods after the ramp).
run_case tlsph_svk_n10_003dynamic --set solid.solver=tlsph "${GEOM[@]}" \
  --set solid.damping=0 --set "solid.region tip_load.ramp_time=0.0015" --set run.end_time=0.003 &&
  row tlsph_svk_n10_003dynamic tlsph saint_venant_kirchhoff 10 ", 003's dynamic run at 3 ms" ||
  echo "| tlsph | 003's dynamic run | 10 | failed: see $OUT/tlsph_svk_n10_003dynamic.txt |"
echo
echo "003's dynamic run: after the ramp (t >= 1.5 ms) the undamped tip oscillates with"
"$PY" - "$OUT/tlsph_svk_n10_003dynamic/probes.csv" <<'PY'
import csv, sys
rows = [r for r in csv.DictReader(open(sys.argv[1])) if float(r["time"]) >= 0.0015]
dv = [(-0.5e3 * (float(r["tip_above_uy"]) + float(r["tip_below_uy"])), 1e3 * float(r["time"]))
      for r in rows]
(lo, tlo), (hi, thi) = min(dv), max(dv)
print(f"delta_v between {lo:.2f} mm (t = {tlo:.2f} ms) and {hi:.2f} mm (t = {thi:.2f} ms), "
      f"mean of the two {0.5 * (lo + hi):.2f} mm; at 3 ms {dv[-1][0]:.2f} mm.")
PY
echo
echo "Linear theory at the lever arm L - dx/2 = 0.0995 m (N_y = 10): P a^3 / (3 E I) ="
echo "$("$PY" -c "print('%.3f' % (1e3 * 1.75e6 * 0.0995**3 / (3 * 210e9 * 0.01**3 / 12)))") mm; with 003 Eq. 50's shear term $("$PY" -c "print('%.3f' % (1e3 * (1.75e6 * 0.0995**3 / (3 * 210e9 * 0.01**3 / 12) + 1.75e6 * 0.0995 / (5/6 * 210e9 / 2.6 * 0.01))))") mm"
echo "(at L = 0.1 m: 33.593 mm, 003's 33.59 mm)."
} | tee "$REPORT"
log "report: $REPORT"
