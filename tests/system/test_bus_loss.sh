#!/usr/bin/env bash
# 20 % of all published messages withheld at random (the bus's test switch): the run
# recovers every one by resend requests and its results are bit-identical to a
# loss-free run's.
source "$(dirname "$0")/lib.sh"
small_case case.ini 0.3

"$FSI_RUN" case.ini --out clean >clean.txt 2>&1 || { cat clean.txt; fail "loss-free run failed"; }
FSI_TEST_DROP_FRACTION=0.2 FSI_TEST_DROP_SEED=7 "$FSI_RUN" case.ini --out lossy >lossy.txt 2>&1 \
  || { cat lossy.txt; fail "run with 20 % loss failed"; }

same_results clean lossy
pass "results bit-identical with 20 % of messages dropped"

grep -q "test_drop_fraction = 0.2" lossy/run.log || fail "run.log does not record the test switch"
for p in solid fluid; do
  dropped=$(log_stat lossy/run.log "$p" bus_dropped_by_test)
  resent=$(log_stat lossy/run.log "$p" bus_resent)
  published=$(log_stat lossy/run.log "$p" bus_published)
  echo "$p: published $published, withheld $dropped, resent on request $resent"
  # 0.3 s in 1 ms windows is 300+ windows with several messages each: a 20 % drop
  # rate that withheld fewer than 10 % would mean the switch is not working.
  awk -v d="$dropped" -v p="$published" 'BEGIN {exit !(d > 0.1 * (p + d))}' \
    || fail "$p: only $dropped of $((published + dropped)) messages withheld"
  [ "${resent:-0}" -gt 0 ] || fail "$p: nothing was resent, so loss was not exercised"
done
pass "losses were real and were recovered by resends"
