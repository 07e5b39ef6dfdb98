# Sourced (not a benchmark of its own, hence not .sh: `fsi bench` lists bench/*.sh) by
# the F1 benchmarks (f1_dam_break.sh, fluid_performance.sh): one run of
# cases/f1_dam_break.ini at dx = a / N with the walls four layers thick and the tank
# 16 a long, every length scaled with the spacing.
#
#   f1_args N                                        sets F1_ARGS (case and --set options)
#   f1_run RUN N THREADS DIR [fsi-run options ...]   (output DIR, log DIR.txt)
F1_A=0.05715          # column width a (m); the case's lengths are multiples of a
f1_calc() { /usr/bin/python3 -c "print($1)"; }
# F1_ARGS=(the case and its --set options at dx = a / N).
f1_args() {
  local n="$1" w xr
  w=$(f1_calc "4 * $F1_A / $n")
  xr=$(f1_calc "16 * $F1_A")
  F1_ARGS=("$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)/cases/f1_dam_break.ini"
    --set "fluid.spacing=$(f1_calc "$F1_A / $n")"
    --set "fluid.wall bottom.min=-$w,-$w" --set "fluid.wall bottom.max=$(f1_calc "$xr + $w"),0"
    --set "fluid.wall left.min=-$w,0"
    --set "fluid.wall right.max=$(f1_calc "$xr + $w"),$(f1_calc "4 * $F1_A")")
}
f1_run() {
  local run="$1" n="$2" threads="$3" dir="$4"
  shift 4
  f1_args "$n"
  "$run" "${F1_ARGS[@]}" --out "$dir" --force --threads "$threads" "$@" > "$dir.txt" 2>&1
}
