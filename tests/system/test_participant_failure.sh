#!/usr/bin/env bash
# A participant killed (SIGKILL) or hung (SIGSTOP) stops the whole run within 10 s,
# with a message naming it and a non-zero exit, and the output written so far stays
# readable by h5dump. So does a stopped coupler, and the message names the coupler,
# not the participant that left first because it heard nothing from it. The watchdog is set to 3 s (default 10 s) so that a hang is
# found well inside the limit.
source "$(dirname "$0")/lib.sh"
small_case case.ini 60

program_of() { case "$1" in solid) echo fsi-spring-solid ;; fluid) echo fsi-dashpot-fluid ;; esac; }

for who in solid fluid; do
  for sig in KILL STOP; do
    out="run_${who}_$sig"
    "$FSI_RUN" case.ini --out "$out" --set run.watchdog_timeout=3 >"$out.txt" 2>&1 &
    launcher=$!
    wait_under_way "$out"
    pid=$(pgrep -P "$launcher" -f "$(program_of "$who")" | head -n 1)
    [ -n "$pid" ] || fail "$who/$sig: no $who process under launcher $launcher"
    start=$(date +%s.%N)
    kill -"$sig" "$pid"
    set +e
    wait "$launcher"
    status=$?
    set -e
    took=$(echo "$(date +%s.%N) - $start" | bc)
    kill -KILL "$pid" 2>/dev/null || true
    [ "$status" -ne 0 ] || fail "$who/$sig: exit status 0"
    [ "$status" -eq 1 ] || fail "$who/$sig: exit status $status, expected 1 (run failure)"
    awk -v t="$took" 'BEGIN {exit !(t < 10)}' || fail "$who/$sig: took $took s to stop (limit 10 s)"
    grep -q "'$who'" "$out.txt" || { cat "$out.txt"; fail "$who/$sig: message does not name '$who'"; }
    for f in solid.h5 fluid.h5; do
      h5dump -H "$out/$f" >/dev/null || fail "$who/$sig: h5dump cannot read $f"
    done
    output_readable "$out" solid fluid || fail "$who/$sig: a frame listed is not readable"
    grep -q "^exit = failure" "$out/run.log" || fail "$who/$sig: run.log has no exit reason"
    pass "$who/SIG$sig: stopped in $(printf %.1f "$took") s, exit $status, named: $(grep -m1 -o "participant '$who'[^;]*" "$out.txt" | head -c 120)"
  done
done

# The coupler stopped (SIGSTOP: alive but silent). The participants leave after the
# watchdog timeout; the verdict names the coupler and its state, and the stopped
# coupler does not outlive the run.
out=run_coupler_STOP
"$FSI_RUN" case.ini --out "$out" --set run.watchdog_timeout=3 >"$out.txt" 2>&1 &
launcher=$!
wait_under_way "$out"
pid=$(pgrep -P "$launcher" -x fsi-coupler | head -n 1)
[ -n "$pid" ] || fail "coupler/STOP: no coupler under launcher $launcher"
start=$(date +%s.%N)
kill -STOP "$pid"
set +e
wait "$launcher"
status=$?
set -e
took=$(echo "$(date +%s.%N) - $start" | bc)
left=$(run_pids "$out")
kill -CONT "$pid" 2>/dev/null || true
kill -KILL "$pid" $left 2>/dev/null || true
[ "$status" -eq 1 ] || { cat "$out.txt"; fail "coupler/STOP: exit status $status, expected 1"; }
awk -v t="$took" 'BEGIN {exit !(t < 10)}' || fail "coupler/STOP: took $took s to stop (watchdog 3 s, limit 10 s)"
grep -q "run failed: the coupler (pid $pid) stopped answering (state T: stopped)" "$out.txt" ||
  { cat "$out.txt"; fail "coupler/STOP: the verdict does not name the stopped coupler"; }
grep -q "^exit = failure: the coupler (pid $pid) stopped answering" "$out/run.log" ||
  fail "coupler/STOP: run.log's exit line does not name the coupler"
[ -z "$left" ] || fail "coupler/STOP: processes $left of the run still alive after it ended"
for f in solid.h5 fluid.h5; do
  h5dump -H "$out/$f" >/dev/null || fail "coupler/STOP: h5dump cannot read $f"
done
pass "coupler/SIGSTOP: stopped in $(printf %.1f "$took") s, exit $status, named: $(grep -m1 -o "the coupler (pid [0-9]*) stopped answering[^;]*" "$out.txt" | head -c 140)"
