#!/usr/bin/env bash
# Two failures that heartbeats alone do not reveal, each named correctly:
#  (a) a participant alive but stuck (a deadlock) stops the run after
#      [run] window_timeout, naming it;
#  (b) a participant that goes numerically unstable aborts with where and when, and
#      `fsi run` names it — not the processes that stopped because of its abort.
source "$(dirname "$0")/lib.sh"
small_case case.ini 0.3

# (a) the solid never reports window 50; window_timeout 2 s. timeout(1) at 30 s: a
# coupler that ignored window_timeout would otherwise hang the test until ctest's 600 s.
set +e
start=$(date +%s.%N)
FSI_TEST_STALL="solid:50" timeout -k 5 30 "$FSI_RUN" case.ini --out stuck \
  --set run.window_timeout=2 >stuck.txt 2>&1
status=$?
set -e
took=$(echo "$(date +%s.%N) - $start" | bc)
[ "$status" -ne 124 ] && [ "$status" -ne 137 ] ||
  { cat stuck.txt; fail "stuck run not stopped after 30 s: the coupler's window_timeout (2 s) never fired"; }
[ "$status" -eq 1 ] || { cat stuck.txt; fail "stuck run: exit $status, expected 1"; }
grep -q "participant 'solid' alive but window 50 .* not done after 2 s" stuck.txt ||
  { cat stuck.txt; fail "stuck run: message does not name the stuck solid and its window"; }
awk -v t="$took" 'BEGIN {exit !(t < 10)}' || fail "stuck run took $took s (window_timeout 2 s)"
h5dump -H stuck/solid.h5 >/dev/null || fail "stuck run: solid.h5 unreadable"
pass "stuck solid named after window_timeout, run stopped in $(printf %.1f "$took") s"

# (b) omega = sqrt(k/m) = 1e5 rad/s with sub-steps of 1e-4 s: velocity Verlet is
# unstable (omega h = 10 > 2) and overflows within a few hundred sub-steps.
set +e
"$FSI_RUN" case.ini --out unstable --set solid.stiffness=1e10 >unstable.txt 2>&1
status=$?
set -e
[ "$status" -eq 1 ] || { cat unstable.txt; fail "unstable run: exit $status, expected 1"; }
line=$(grep "run failed:" unstable.txt) || { cat unstable.txt; fail "no 'run failed' line"; }
echo "$line" | grep -q "participant 'solid'" || fail "the failure names the wrong process: $line"
grep -q "not finite at t = " unstable/solid.log || fail "solid.log does not say when it blew up"
h5dump -H unstable/fluid.h5 >/dev/null || fail "unstable run: fluid.h5 unreadable"
pass "unstable solid named: $line"

# (c) not a failure: one window of the solid takes 2.5 s, longer than the 1 s watchdog
# timeout, while its heartbeat thread keeps the coupler informed; the coupler's own
# heartbeats pile up unread meanwhile. The run must finish (before the participant
# library handled queued messages first, the solid stopped itself with "coupler not
# heard", as a 16 000-point S2 run did on a loaded machine).
set +e
FSI_TEST_SLOW="solid:20:2.5" "$FSI_RUN" case.ini --out slow --set run.watchdog_timeout=1 \
  --set run.heartbeat_interval=0.2 >slow.txt 2>&1
status=$?
set -e
[ "$status" -eq 0 ] || { cat slow.txt; fail "a 2.5 s window with a 1 s watchdog failed the run (exit $status)"; }
grep -q "FSI_TEST_SLOW" slow/solid.log || fail "the slow-window switch did not act"
pass "a window longer than the watchdog timeout is not taken for a dead coupler"
