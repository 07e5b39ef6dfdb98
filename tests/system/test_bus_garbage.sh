#!/usr/bin/env bash
# Garbage on the bus (random bytes on our channels, one type on another's channel,
# another run's and another protocol version's messages, unknown channels) is
# ignored and counted; the results equal a clean run's.
source "$(dirname "$0")/lib.sh"
small_case case.ini 0.3
URL="udpm://239.255.76.67:7667?ttl=0"

"$FSI_RUN" case.ini --out clean >clean.txt 2>&1 || { cat clean.txt; fail "clean run failed"; }

# Our own private namespace holds the run (attached with --lcm-url) and the noise.
unshare -rn bash -c '
  set -e
  ip link set lo up
  ip route add 224.0.0.0/4 dev lo
  "$1/fsi-test-bus-noise" "$2" 30 >noise.txt 2>&1 &
  noise=$!
  sleep 0.3
  "$3" case.ini --out noisy --lcm-url "$2" >noisy.txt 2>&1
  status=$?
  kill $noise 2>/dev/null || true
  exit $status
' _ "$FSI_BIN_DIR" "$URL" "$FSI_RUN" || { cat noisy.txt; fail "run with bus noise failed"; }

same_results clean noisy
pass "results with garbage on the bus identical to a clean run"
grep -q "isolation = user-given LCM URL" noisy/run.log || fail "run.log does not record --lcm-url"
for p in solid fluid; do
  for counter in bus_ignored_undecodable bus_ignored_foreign_run bus_ignored_bad_version bus_ignored_unknown_channel; do
    n=$(log_stat noisy/run.log "$p" "$counter")
    [ "${n:-0}" -gt 0 ] || fail "$p: $counter is ${n:-missing}; the noise was not seen or not counted"
  done
  echo "$p: undecodable $(log_stat noisy/run.log "$p" bus_ignored_undecodable), foreign run $(log_stat noisy/run.log "$p" bus_ignored_foreign_run), bad version $(log_stat noisy/run.log "$p" bus_ignored_bad_version), unknown channel $(log_stat noisy/run.log "$p" bus_ignored_unknown_channel)"
done
pass "every kind of garbage was counted and ignored"
