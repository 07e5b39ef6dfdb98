#!/usr/bin/env bash
# fsi bench: every fluid x solid solver on C1 or C2: accuracy against wall time
# Every fluid x solid combination on one coupled scene (docs/validation.md, "Every fluid
# with every solid"): the scene's own sweep (bench/c1_elastic_plate.sh or
# bench/c2_elastic_gate.sh) once per combination, chosen only by --set fluid.solver and
# --set solid.solver on the scene's one case file, then one table of every run
# (bench/combinations.py) and one accuracy-against-wall-time chart with every
# combination on it (bench/accuracy_speed.py).
#
#   bench/combinations.sh c1|c2 [OUT] [--res "LIST"] [--fluids "LIST"] [--solids "LIST"] [--with CSV]
#                         [--resume | --report] [--threads T] [--set k=v ...]
#
# The combinations are the built solvers `fsi solvers` lists (the registry `fsi run`
# checks names against; examples left out), so a new solver joins without editing this
# script; --fluids and --solids keep only those named (e.g. one new fluid against every
# solid, its rows then added to the chart's earlier points: --with CSV). --res is
# the scene's resolution list (C1: spacings, default "0.004 0.002"; C2: T / dx, default
# "2 3"). Each combination's runs are in OUT/FLUID_SOLID (the scene script's layout);
# writes OUT/combinations.md, OUT/accuracy_speed.csv and OUT/accuracy_speed.png.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
PY=/usr/bin/python3
SCENE="${1:-}"
case "$SCENE" in
  c1) SCRIPT=c1_elastic_plate.sh; LIST_OPTION=--dx; RES="0.004 0.002"
      TITLE="C1 elastic plate: NRMSE of the corner's u_x against run time"
      LABEL="NRMSE of u_x against the published curves' mean"; GOAL=(--goal 0.075 --goal-label "closest published curve to the other three") ;;
  c2) SCRIPT=c2_elastic_gate.sh; LIST_OPTION=--n; RES="2 3"
      TITLE="C2 elastic gate: NRMSE of the free end's x against run time"
      LABEL="NRMSE of the free end's x against Antoci's experiment"; GOAL=(--goal 0.245 --goal-label "Khayyer 2018 (best published curve)") ;;
  *) echo "combinations: the first argument is the scene, c1 or c2" >&2; exit 2 ;;
esac
shift
OUT="$ROOT/out/bench/combinations_$SCENE"
PASS=()
ONLY_FLUIDS=""; ONLY_SOLIDS=""; WITH=()
while [ $# -gt 0 ]; do
  case "$1" in
    --res) RES="${2:?--res needs a list}"; shift ;;
    --fluids) ONLY_FLUIDS="${2:?--fluids needs a list}"; shift ;;
    --solids) ONLY_SOLIDS="${2:?--solids needs a list}"; shift ;;
    --with) WITH+=("${2:?--with needs a CSV of earlier points}"); shift ;;
    --resume | --report) PASS+=("$1") ;;
    --threads | --set) PASS+=("$1" "${2:?$1 needs a value}"); shift ;;
    -*) echo "combinations: unknown option $1" >&2; exit 2 ;;
    *) OUT="$1" ;;
  esac
  shift
done
mkdir -p "$OUT"
log() { echo "[combinations $SCENE] $*" >&2; }

solvers_of() {  # solvers_of fluid|solid: the built solvers of that role (fsi solvers)
  "$ROOT/build/bin/fsi-solvers" | awk -v r="$1" '!/^#/ && $1 == r && $3 == "solver" && $5 == "yes" {print $2}'
}
keep() {  # keep BUILT WANTED ROLE: the built solvers among those wanted (all when none)
  [ -z "$2" ] && { echo "$1"; return; }
  for w in $2; do
    case " $(echo $1) " in
      *" $w "*) echo "$w" ;;
      *) log "no built $3 solver $w (fsi solvers)"; exit 2 ;;
    esac
  done
}
FLUIDS=$(solvers_of fluid); SOLIDS=$(solvers_of solid)
[ -n "$FLUIDS" ] && [ -n "$SOLIDS" ] || { log "no built solvers (fsi solvers; build first)"; exit 1; }
FLUIDS=$(keep "$FLUIDS" "$ONLY_FLUIDS" fluid); SOLIDS=$(keep "$SOLIDS" "$ONLY_SOLIDS" solid)
log "fluids: $(echo $FLUIDS); solids: $(echo $SOLIDS); resolutions: $RES"

DIRS=()
for f in $FLUIDS; do
  for s in $SOLIDS; do
    log "$f + $s"
    "$ROOT/bench/$SCRIPT" "$OUT/${f}_$s" "$LIST_OPTION" "$RES" ${PASS[@]+"${PASS[@]}"} \
      --set "fluid.solver=$f" --set "solid.solver=$s" >"$OUT/${f}_$s.log" 2>&1 ||
      log "$f + $s: the sweep failed, see $OUT/${f}_$s.log"
    for d in "$OUT/${f}_$s"/*/; do
      [ -f "$d/case.resolved.ini" ] && DIRS+=("${d%/}")
    done
  done
done
"$PY" "$ROOT/bench/combinations.py" --scene "$SCENE" --md "$OUT/combinations.md" \
  --csv-out "$OUT/accuracy_speed.csv" "${DIRS[@]}"
cat "$OUT/combinations.md"
"$PY" "$ROOT/bench/accuracy_speed.py" --title "$TITLE" --error-label "$LABEL" "${GOAL[@]}" \
  --png "$OUT/accuracy_speed.png" ${WITH[@]+"${WITH[@]}"} "$OUT/accuracy_speed.csv"
log "report: $OUT/combinations.md, chart: $OUT/accuracy_speed.png"
