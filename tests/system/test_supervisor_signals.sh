#!/usr/bin/env bash
# When `fsi run` itself goes away, so does its run:
#  (a) kill -9 of fsi-run: its coupler, participants and traffic recorder are gone
#      within 10 s (none runs on to the end orphaned);
#  (b) SIGHUP (the terminal closed) stops the run as SIGINT does: exit 1, an exit
#      line in run.log, nothing left running.
# The processes of a run are found by the FSI_OUT of their environment (run_pids),
# so processes of other runs on this machine are never looked at or killed.
source "$(dirname "$0")/lib.sh"
small_case long.ini 60

# Whatever a failed check leaves running is killed: only processes of these runs.
cleanup() {
  local d pids
  for d in killed hangup; do
    [ -d "$d" ] || continue
    pids=$(run_pids "$d")
    [ -z "$pids" ] || kill -KILL $pids 2>/dev/null || true
  done
}
trap cleanup EXIT

# Waits up to LIMIT s for the processes of the run into DIR to end; prints how long.
gone_within() {   # gone_within DIR LIMIT
  local dir="$1" limit="$2" start left
  start=$(date +%s.%N)
  for _ in $(seq $((limit * 10))); do
    left=$(run_pids "$dir")
    [ -z "$left" ] && { echo "$(date +%s.%N) - $start" | bc; return 0; }
    sleep 0.1
  done
  ps -o pid,stat,args -p "$(echo $left | tr ' ' ,)" >&2 || true
  return 1
}

# (a)
"$FSI_RUN" long.ini --out killed --log-traffic >killed.txt 2>&1 &
launcher=$!
wait_under_way killed
before=$(run_pids killed | wc -l)
[ "$before" -eq 4 ] || fail "expected 4 processes of the run (coupler, 2 participants, recorder), found $before"
kill -KILL "$launcher"
wait "$launcher" 2>/dev/null || true
took=$(gone_within killed 10) || fail "kill -9 of fsi-run left processes of its run alive after 10 s"
h5dump -H killed/solid.h5 >/dev/null || fail "solid.h5 unreadable after kill -9 of fsi-run"
pass "kill -9 of fsi-run: its $before processes gone in $(printf %.1f "$took") s"

# The folder is free again: no process of the killed run holds its lock.
"$FSI_RUN" long.ini --out killed --force --set run.end_time=0.05 >again.txt 2>&1 ||
  { cat again.txt; fail "a run into the folder of the killed run was refused"; }

# (b)
"$FSI_RUN" long.ini --out hangup >hangup.txt 2>&1 &
launcher=$!
wait_under_way hangup
kill -HUP "$launcher"
set +e
wait "$launcher"
status=$?
set -e
[ "$status" -eq 1 ] || { cat hangup.txt; fail "SIGHUP: exit status $status, expected 1"; }
grep -q "^exit = failure: stopped by SIGHUP" hangup/run.log ||
  { tail -n 5 hangup/run.log; fail "SIGHUP: run.log has no exit line naming the signal"; }
took=$(gone_within hangup 5) || fail "SIGHUP: processes of the run still alive"
h5dump -H hangup/fluid.h5 >/dev/null || fail "fluid.h5 unreadable after SIGHUP"
pass "SIGHUP: exit 1, run.log says '$(grep -m1 '^exit = ' hangup/run.log | cut -c1-60)'"
