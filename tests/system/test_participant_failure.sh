#!/usr/bin/env bash
# A participant killed (SIGKILL) or hung (SIGSTOP) stops the whole run within 10 s,
# with a message naming it and a non-zero exit, and the output written so far stays
# readable by h5dump. The watchdog is set to 3 s (default 10 s) so that a hang is
# found well inside the limit.
source "$(dirname "$0")/lib.sh"
small_case case.ini 60

program_of() { case "$1" in solid) echo fsi-spring-solid ;; fluid) echo fsi-dashpot-fluid ;; esac; }

for who in solid fluid; do
  for sig in KILL STOP; do
    out="run_${who}_$sig"
    "$FSI_RUN" case.ini --out "$out" --set run.watchdog_timeout=3 >"$out.txt" 2>&1 &
    launcher=$!
    # Wait until the run is under way: a few probe rows and the first frame exist.
    for _ in $(seq 100); do
      rows=$(wc -l <"$out/probes.csv" 2>/dev/null || echo 0)
      [ "$rows" -gt 3 ] && break
      sleep 0.1
    done
    [ "$rows" -gt 3 ] || { cat "$out.txt"; fail "$who/$sig: run did not start"; }
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
