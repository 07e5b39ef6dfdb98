#!/usr/bin/env bash
# Waiting is cheap on the wire: in a loss-free coupled run whose windows take tens
# of milliseconds (ULPH water against the NOSB-PD plate of C1), nobody asks for a
# message before it is overdue by what such waits took, so resend requests are rare
# and nothing is sent twice. The earlier scheme asked 3 ms into every wait: about 9
# requests per window here, more than half of all messages on the bus.
source "$(dirname "$0")/lib.sh"
"$FSI_RUN" "$FSI_SOURCE_DIR/cases/c1_elastic_plate.ini" --out run --set run.end_time=0.003 \
  >run.txt 2>&1 || { cat run.txt; fail "C1 run failed"; }
windows=$(awk '$1 == "windows" {print $3}' run/run.log)
requests=$(sed -n 's/^bus coupler: .*resend requests \([0-9]*\),.*/\1/p' run/run.log)
copies=$(sed -n 's/^bus coupler: .*extra copies \([0-9]*\),.*/\1/p' run/run.log)
for p in fluid solid; do
  requests=$((requests + $(log_stat run/run.log "$p" bus_resend_requests)))
  copies=$((${copies:-0} + $(log_stat run/run.log "$p" bus_extra_copies || true) + 0))
done
echo "$windows windows: $requests resend requests, $copies extra copies"
# One request per window at most: a wide margin for a loaded machine, where a
# process that is not scheduled for a while makes some waits overdue.
[ "$requests" -le "$windows" ] || fail "$requests resend requests in $windows loss-free windows"
[ "$copies" -eq 0 ] || fail "$copies extra copies sent although nothing was lost on purpose"
pass "loss-free C1: $requests resend requests in $windows windows, no extra copies"
