#!/usr/bin/env bash
# Heavy message loss (the bus's test switch withholds 50 % and 80 % of every process's
# published messages) costs a bounded factor of wall time, not the minutes to hours
# that a re-request back-off capped at 0.5 s gave, and the results stay bit-identical
# to the loss-free run's (docs/protocol.md, "Reliability").
source "$(dirname "$0")/lib.sh"
demo="$FSI_SOURCE_DIR/cases/demo_spring_dashpot.ini"

# wall LOG COMMAND...: prints the wall seconds of COMMAND (output to LOG), to 0.01 s;
# returns the command's status.
wall() {
  local log="$1" t0 t1 rc=0
  shift
  t0=$(date +%s.%N)
  "$@" >"$log" 2>&1 || rc=$?
  t1=$(date +%s.%N)
  awk -v a="$t0" -v b="$t1" 'BEGIN {printf "%.2f", b - a}'
  return $rc
}

# The demo case (2 s in 2001 windows of 1 ms). Bound: 10 times the loss-free wall time
# plus 5 s. The goal is 5 times; the margin is for a machine shared with other jobs,
# where a loss-free run itself varies by 2x. Before the fix a 50 % run took about
# 2000 times as long (1 to 4 windows per second), so the bound still separates the
# two by far; `timeout` makes a
# failure end at the bound.
clean_s=$(wall clean.txt "$FSI_RUN" "$demo" --out clean) || { cat clean.txt; fail "loss-free run failed"; }
bound=$(awk -v c="$clean_s" 'BEGIN {printf "%.0f", 10 * c + 5}')
set +e
lossy_s=$(FSI_TEST_DROP_FRACTION=0.5 FSI_TEST_DROP_SEED=11 \
  wall lossy50.txt timeout "$bound" "$FSI_RUN" "$demo" --out lossy50)
status=$?
set -e
[ "$status" -eq 0 ] || { tail -n 5 lossy50.txt; fail "demo with 50 % loss: status $status (124: not done within the bound of $bound s; loss-free took $clean_s s)"; }
same_results clean lossy50
grep -q "test_drop_fraction = 0.5" lossy50/run.log || fail "run.log does not record the test switch"
pass "demo with 50 % loss: $lossy_s s (loss-free $clean_s s, bound $bound s), bit-identical"

# 80 %: a short demo with a small window timeout, so that a wait that does not end
# fails in seconds instead of the default 600 s.
short=(--set run.end_time=0.2 --set run.window_timeout=10)
"$FSI_RUN" "$demo" --out clean80 "${short[@]}" >clean80.txt 2>&1 || { cat clean80.txt; fail "short loss-free run failed"; }
set +e
lossy_s=$(FSI_TEST_DROP_FRACTION=0.8 FSI_TEST_DROP_SEED=5 \
  wall lossy80.txt timeout 60 "$FSI_RUN" "$demo" --out lossy80 "${short[@]}")
status=$?
set -e
[ "$status" -eq 0 ] || { tail -n 5 lossy80.txt; fail "short demo with 80 % loss: status $status"; }
same_results clean80 lossy80
pass "short demo (201 windows) with 80 % loss: $lossy_s s, bit-identical"
