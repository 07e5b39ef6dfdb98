#!/usr/bin/env bash
# The Python side of a traffic log: the message types lcm-gen makes for Python
# (build/python/fsi) and python/fsi_traffic.py decode every event of a logged
# implicit run with lost messages, and give the same windows, iterations, channels
# and message counts as `fsi inspect`; a cut log is refused.
source "$(dirname "$0")/lib.sh"
export PYTHONPATH="$(dirname "$FSI_BIN_DIR")/python"
small_case case.ini 0.05
sed -i 's/^end_time = .*/&\nscheme = implicit/' case.ini
FSI_TEST_DROP_FRACTION=0.1 FSI_TEST_DROP_SEED=5 "$FSI_RUN" case.ini --out run --log-traffic \
  --set run.coupling_min_iterations=3 --set run.coupling_max_iterations=3 \
  --set run.coupling_on_max_iterations=continue >run.txt 2>&1 || { cat run.txt; fail "run failed"; }
"$FSI_BIN_DIR/fsi-inspect" run/traffic.lcmlog >inspect.txt || fail "fsi inspect failed"

# fsi inspect's lines that count messages: window, iteration, channel, messages.
awk '$1 ~ /^-?[0-9]+$/ && $4 > 0 {print $1, $2, $3, $4}' inspect.txt | sort >inspect_counts.txt
/usr/bin/python3 -m fsi_traffic run/traffic.lcmlog | sort >python_counts.txt \
  || fail "fsi_traffic.py failed on the log"
[ -s python_counts.txt ] || fail "fsi_traffic.py found no messages"
diff inspect_counts.txt python_counts.txt >counts.diff \
  || { head -20 counts.diff; fail "fsi_traffic.py and fsi inspect count differently"; }
lines=$(wc -l <python_counts.txt)
iterations=$(awk '$2 == 2' python_counts.txt | wc -l)
[ "$iterations" -gt 0 ] || fail "no third iteration in the log of an implicit run of 3 iterations"
pass "fsi_traffic.py: $lines (window, iteration, channel) lines, as fsi inspect counts them"

# Every event decodes with the generated types, and the contents are what was sent.
/usr/bin/python3 - run/traffic.lcmlog <<'PY' || fail "decoded messages wrong"
import sys
import fsi
import fsi_traffic
events = list(fsi_traffic.read_events(sys.argv[1]))
# LCM's own LCM_SELF_TEST messages are in the log too; every FSI_ channel decodes.
undecoded = [e.channel for e in events if e.message is None and e.channel.startswith("FSI_")]
assert not undecoded, f"{len(undecoded)} events not decoded: {sorted(set(undecoded))}"
states = [e.message for e in events if e.channel == "FSI_SOLID_STATE"]
loads = [e.message for e in events if e.channel == "FSI_FLUID_LOAD"]
assert states and loads, "no interface messages"
assert all(isinstance(m, fsi.solid_state_t) and m.n == 50 and len(m.position) == 50 * m.dim
           for m in states), "a solid state without 50 particles"
assert all(m.header.sender == "fluid" and m.n == 50 for m in loads), "a fluid load wrong"
steps = [e.message for e in events if e.channel == "FSI_STEP"]
assert abs(max(s.t + s.dt for s in steps) - 0.05) < 1e-12, "the last window does not end at 0.05 s"
print(f"ok: {len(events)} events decoded, {len(states)} solid states, {len(loads)} fluid loads")
PY

# A log cut inside an event: a clear message, status 2.
head -c 1000 run/traffic.lcmlog >cut.lcmlog
set +e
/usr/bin/python3 -m fsi_traffic cut.lcmlog >/dev/null 2>cut.txt
status=$?
set -e
[ "$status" -eq 2 ] && grep -q "cut.lcmlog: ends inside" cut.txt \
  || fail "a cut log: status $status, message '$(cat cut.txt)'"
pass "a cut log is refused with status 2"
