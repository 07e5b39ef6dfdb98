#!/usr/bin/env bash
# Fluid that leaves its walls, or outruns its sound speed, stops the run. The F1 dam
# break at a coarse spacing (a / 10, 200 fluid particles; walls two spacings thick):
#   c0 = 1 m/s: the collapse reaches Mach 1 (the issue's F1 at c0 = 1 went on with 34-47
#     particles through the floor, exit 0): exit 1 naming the particle, Mach, time, window;
#   c0 = 2 m/s: the water falls through the floor below Mach 1: exit 1 naming the
#     particle, the wall, its position, time and window; and the Mach warning (past 0.3)
#     is in fluid.log;
#   the case's c0 = 40 m/s: exit 0, no warning.
# A few seconds.
source "$(dirname "$0")/lib.sh"
CASE="$FSI_SOURCE_DIR/cases/f1_dam_break.ini"
COARSE=(--threads 1 --set fluid.spacing=0.005715 --set run.end_time=0.3)

run_expect() {   # run_expect STATUS DIR --set ...
  local want="$1" dir="$2"; shift 2
  set +e
  "$FSI_RUN" "$CASE" --out "$dir" "${COARSE[@]}" "$@" >"$dir.txt" 2>&1
  local status=$?
  set -e
  [ "$status" -eq "$want" ] || { cat "$dir.txt"; fail "$* : exit $status, expected $want"; }
}

run_expect 1 supersonic --set fluid.sound_speed=1
grep -E "error: particle [0-9]+ at \(.*\) moves at .* m/s, Mach 1(\.[0-9]*)? against c0 = 1 m/s, at t = .* s \(window [0-9]+\)" \
  supersonic/fluid.log >/dev/null || { cat supersonic.txt; fail "c0 = 1: no Mach stop naming particle, time, window"; }
pass "c0 = 1 m/s stopped: $(grep error: supersonic/fluid.log | grep -o "particle [0-9]* at .*(window [0-9]*)" | head -n 1)"

run_expect 1 leak --set fluid.sound_speed=2
grep -E "error: particle [0-9]+ leaked through \[fluid.wall bottom\]: it went from above the wall to below it along y, now at \(.*\), .* past its face y = -0.01143 m .* at t = .* s \(window [0-9]+, step [0-9]+\)" \
  leak/fluid.log >/dev/null || { cat leak.txt; fail "c0 = 2: no leak naming particle, wall, where, when"; }
grep -q "leaked through \[fluid.wall bottom\]" leak.txt || fail "c0 = 2: the leak is not on the terminal"
grep -qE "warning: particle [0-9]+ .* Mach 0\.[3-9]" leak/fluid.log || fail "c0 = 2: no Mach warning"
[ "$(grep -c 'warning: particle .* Mach' leak/fluid.log)" -eq 1 ] || fail "c0 = 2: the Mach warning is not once"
pass "c0 = 2 m/s stopped: $(grep -o 'particle [0-9]* leaked.*m past' leak/fluid.log | head -n 1)"

run_expect 0 normal --set run.end_time=0.05
! grep -q "warning" normal/fluid.log normal.txt || { grep warning normal/fluid.log; fail "c0 = 40: a warning"; }
pass "c0 = 40 m/s: no warning, exit 0"
