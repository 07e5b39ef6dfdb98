#!/usr/bin/env bash
# --log-traffic records every bus message in LCM's event-log format; `fsi inspect`
# reads it back with one line per window and channel, and what it reports matches
# the run (window count, particle counts, resend requests under message loss).
source "$(dirname "$0")/lib.sh"
small_case case.ini 0.1

FSI_TEST_DROP_FRACTION=0.1 FSI_TEST_DROP_SEED=3 \
  "$FSI_RUN" case.ini --out run --log-traffic >run.txt 2>&1 || { cat run.txt; fail "run failed"; }
[ -s run/traffic.lcmlog ] || fail "no traffic.lcmlog"
"$FSI_BIN_DIR/fsi-inspect" run/traffic.lcmlog >inspect.txt || fail "fsi inspect failed"

windows=$(awk '$1 == "windows" {print $3}' run/run.log)
# Windows 0..windows all have a grant; the last (finishing) one has no interface data.
steps=$(awk '$3 == "FSI_STEP"' inspect.txt | wc -l)
[ "$steps" -eq $((windows + 1)) ] || fail "inspect shows $steps FSI_STEP lines, run.log says $windows windows"
bad_n=$(awk '($3 == "FSI_SOLID_STATE" || $3 == "FSI_FLUID_LOAD") && $7 != 50' inspect.txt | wc -l)
[ "$bad_n" -eq 0 ] || fail "$bad_n interface lines without 50 particles"
states=$(awk '$3 == "FSI_SOLID_STATE"' inspect.txt | wc -l)
[ "$states" -eq "$windows" ] || fail "$states FSI_SOLID_STATE lines for $windows windows"
requests=$(awk '$1 ~ /^[0-9]+$/ {s += $6} END {print s + 0}' inspect.txt)
[ "$requests" -gt 0 ] || fail "no resend requests seen although 10 % of messages were dropped"
grep -q "^# [0-9]* events: [0-9]* heartbeats, 0 undecodable" inspect.txt || fail "summary line wrong: $(tail -n 1 inspect.txt)"
# A window's pressure range must be what the dashpot gives: p = -F_y / face.
awk '$1 == 20 && $3 == "FSI_FLUID_LOAD" {exit !($9 < $10 && $11 > 0)}' inspect.txt \
  || fail "window 20 fluid load line lacks pressure range or force: $(awk '$1 == 20' inspect.txt)"
pass "traffic log: $windows windows, $states solid states of 50 particles, $requests resend requests"

set +e
"$FSI_BIN_DIR/fsi-inspect" no_such.lcmlog >/dev/null 2>&1
status=$?
set -e
[ "$status" -eq 2 ] || fail "fsi inspect on a missing log: status $status, expected 2"
pass "fsi inspect on a missing log exits 2"
