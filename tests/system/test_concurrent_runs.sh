#!/usr/bin/env bash
# Two runs at once on the same default LCM URL do not hear each other: each runs in
# its own network namespace, and each gives exactly the results of a run alone.
source "$(dirname "$0")/lib.sh"
small_case case.ini 0.3

"$FSI_RUN" case.ini --out alone >alone.txt 2>&1 || { cat alone.txt; fail "run alone failed"; }
"$FSI_RUN" case.ini --out first >first.txt 2>&1 &
a=$!
"$FSI_RUN" case.ini --out second >second.txt 2>&1 &
b=$!
wait $a || { cat first.txt; fail "first of two concurrent runs failed"; }
wait $b || { cat second.txt; fail "second of two concurrent runs failed"; }
same_results alone first
same_results alone second
for run in first second; do
  for p in solid fluid; do
    foreign=$(log_stat "$run/run.log" "$p" bus_ignored_foreign_run)
    [ "$foreign" = 0 ] || fail "$run/$p heard $foreign messages of another run"
  done
done
pass "two concurrent runs: both identical to a run alone, no foreign messages heard"
