# Sourced (not a benchmark of its own, hence not .sh: `fsi bench` lists bench/*.sh) by
# the resolution sweeps f1_dam_break.sh and c2_elastic_gate.sh (and for its options by
# f2_sloshing.sh): their common options and the loop over the resolutions.
#
#   NS="DEFAULT" THREADS=DEFAULT; sweep_args NAME "$@"
#       parses [OUT] [--n "N ..."] [--resume | --report] [--threads T] [--set k=v ...]
#       into OUT (default out/bench/NAME; created), NS, RESUME (0 run all, 1 keep the
#       finished runs, 2 run nothing), THREADS and EXTRA (the --set options, passed to
#       every run); f2_sloshing.sh uses only OUT, --report, --threads and --set
#   sweep_runs PREFIX FILE RUN_FN
#       for every N of NS the run OUT/PREFIX$N (log OUT/PREFIX$N.txt): kept with --resume
#       when its log says it finished, with --report when it has written FILE; otherwise
#       `RUN_FN N DIR --set ...` runs it (and writes DIR.txt), and the wall time is
#       appended to the log. A failed run is reported, not fatal. Sets DIRS.
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
RUN="$ROOT/build/bin/fsi-run"
PY=/usr/bin/python3
RESUME=0
EXTRA=()

sweep_args() {
  SWEEP_NAME="$1"
  OUT="$ROOT/out/bench/$1"
  shift
  while [ $# -gt 0 ]; do
    case "$1" in
      --n) NS="$2"; shift ;;
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

sweep_runs() {
  local prefix="$1" file="$2" run_fn="$3" n name start end rc
  DIRS=()
  for n in $NS; do
    name="$prefix$n"
    DIRS+=("$OUT/$name")
    if { [ "$RESUME" = 1 ] && grep -q "^fsi run: finished" "$OUT/$name.txt" 2>/dev/null; } ||
       { [ "$RESUME" = 2 ] && [ -f "$OUT/$name/$file" ]; }; then
      log "$name: kept from an earlier run"
      continue
    fi
    log "$name: ..."
    start=$(date +%s.%N)
    set +e
    "$run_fn" "$n" "$OUT/$name" ${EXTRA[@]+"${EXTRA[@]}"}
    rc=$?
    set -e
    end=$(date +%s.%N)
    echo "wall_time_s $("$PY" -c "print(round($end - $start, 1))")" >> "$OUT/$name.txt"
    [ $rc = 0 ] || log "$name: run failed (exit $rc), see $OUT/$name.txt; its output is still compared"
  done
}
