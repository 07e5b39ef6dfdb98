# Sourced (not a benchmark of its own, hence not .sh) by the resolution sweeps of bench/:
# the options they share and the loop that runs, keeps or skips each resolution.
#
#   sweep_parse NAME LIST_OPTION DEFAULT_LIST "$@"
#       [OUT] [LIST_OPTION "a b c"] [--resume | --report] [--threads T] [--set k=v ...]
#     sets OUT (default out/bench/NAME), LIST, RESUME (0 run, 1 keep finished runs,
#     2 run nothing), THREADS (default 2), EXTRA (the --set options) and log().
#   sweep_run_failure_pair CASE
#     runs CASE as OUT/failure and with solid.nosbpd.failure=false as OUT/no_failure, together.
#   sweep_run DIR fsi-run-arguments...
#     runs DIR (log DIR.txt) unless RESUME keeps it; a failed run is logged, not fatal:
#     what it wrote is still compared.
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
RUN="$ROOT/build/bin/fsi-run"
PY=/usr/bin/python3

sweep_parse() {
  SWEEP_NAME="$1"; local list_option="$2"; LIST="$3"; shift 3
  OUT="$ROOT/out/bench/$SWEEP_NAME"
  RESUME=0
  THREADS="${THREADS:-2}"
  EXTRA=()
  while [ $# -gt 0 ]; do
    case "$1" in
      "$list_option") LIST="$2"; shift ;;
      --resume) RESUME=1 ;;
      --report) RESUME=2 ;;
      --threads) THREADS="$2"; shift ;;
      --set) EXTRA+=(--set "$2"); shift ;;
      -*) echo "$SWEEP_NAME: unknown option $1" >&2; exit 2 ;;
      *) OUT="$1" ;;
    esac
    shift
  done
  mkdir -p "$OUT"
}

log() { echo "[$SWEEP_NAME] $*" >&2; }

sweep_run() {
  local dir="$1"; shift
  local name; name="$(basename "$dir")"
  if [ "$RESUME" = 2 ] || { [ "$RESUME" = 1 ] && grep -q "^fsi run: finished" "$dir.txt" 2>/dev/null; }; then
    log "$name: not run (--report or --resume)"
    return 0
  fi
  local start end rc
  start=$(date +%s.%N)
  set +e
  "$RUN" "$@" --out "$dir" --force --threads "$THREADS" ${EXTRA[@]+"${EXTRA[@]}"} > "$dir.txt" 2>&1
  rc=$?
  set -e
  end=$(date +%s.%N)
  echo "wall_time_s $("$PY" -c "print(round($end - $start, 1))")" >> "$dir.txt"
  [ $rc = 0 ] || log "$name: run failed (exit $rc), see $dir.txt; what it wrote is still compared"
}

# The solid model a run of CASE uses: the last --set solid.solver=NAME of the sweep's
# options, else the case's [solid] solver.
sweep_solid_solver() {
  local name="" k
  for k in ${EXTRA[@]+"${EXTRA[@]}"}; do
    case "$k" in solid.solver=*) name="${k#solid.solver=}" ;; esac
  done
  [ -n "$name" ] || name=$(awk -F' *= *' '/^\[/ {s = $0; next} s == "[solid]" && $1 == "solver" {print $2; exit}' "$1")
  echo "$name"
}

# A fracture scene's two runs side by side: OUT/failure (the case) and OUT/no_failure
# (--set solid.MODEL.failure=false for the run's solid model), one thread each.
sweep_run_failure_pair() {
  local model; model=$(sweep_solid_solver "$1")
  sweep_run "$OUT/failure" "$1" &
  sweep_run "$OUT/no_failure" "$1" --set "solid.$model.failure=false" &
  wait
}

# The solver combination of a run, from its resolved case: "ULPH", "WCSPH + NOSB-PD", ...
# (the line of the accuracy-against-speed charts, bench/accuracy_speed.py).
sweep_solvers() {
  awk -F' *= *' '
    /^\[/ { section = $0; sub(/\].*/, "]", section); next }
    (section == "[fluid]" || section == "[solid]") && $1 == "solver" {
      name = $2; sub(/ *;.*/, "", name)
      if (name == "nosbpd") name = "NOSB-PD"; else if (name == "pseudo_spring") name = "pseudo-spring"; else name = toupper(name)
      if (section == "[fluid]") fluid = name; else solid = name
    }
    END { if (fluid != "" && solid != "") print fluid " + " solid; else print fluid solid }
  ' "$1/case.resolved.ini"
}
