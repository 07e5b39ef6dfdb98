#!/usr/bin/env bash
# `fsi spy`: the Java message types for lcm-spy (built when Debian's liblcm-java and a
# JDK are present) decode every message of a traffic log with LCM's own Java log
# reader, and the log played back in spy's private network arrives whole (fsi-record
# standing in for lcm-spy, which needs a display). Without liblcm-java or a JDK,
# `fsi spy` must say what is missing and exit 2.
source "$(dirname "$0")/lib.sh"
build_dir="$(dirname "$FSI_BIN_DIR")"
spy="$FSI_SOURCE_DIR/launch/spy.sh"
export FSI_LCMTYPES_JAR="$build_dir/java/fsi_lcmtypes.jar"
export PYTHONPATH="$build_dir/python"

"$spy" --help >help.txt || fail "fsi spy --help failed"
grep -q "usage: fsi spy LOG" help.txt || fail "fsi spy --help: $(cat help.txt)"
set +e
"$spy" no_such.lcmlog >/dev/null 2>missing.txt
status=$?
set -e
[ "$status" -eq 2 ] && grep -q "no_such.lcmlog" missing.txt || fail "missing log: status $status, '$(cat missing.txt)'"
pass "fsi spy --help; a missing log exits 2"

small_case case.ini 0.05
"$FSI_RUN" case.ini --out run --log-traffic >run.txt 2>&1 || { cat run.txt; fail "run failed"; }

if [ ! -f /usr/share/java/lcm.jar ] || ! command -v javac >/dev/null; then
  [ ! -f "$FSI_LCMTYPES_JAR" ] || fail "the jar was built although lcm.jar or javac is missing"
  set +e
  "$spy" run/traffic.lcmlog >/dev/null 2>nojar.txt
  status=$?
  set -e
  [ "$status" -eq 2 ] && grep -q "liblcm-java\|JDK\|java" nojar.txt || fail "without liblcm-java or a JDK: status $status, '$(cat nojar.txt)'"
  pass "no liblcm-java or JDK here: fsi spy says so and exits 2"
  exit 0
fi

[ -f "$FSI_LCMTYPES_JAR" ] || fail "liblcm-java and a JDK are here but $FSI_LCMTYPES_JAR was not built"
# the listing first: grep -q in a pipe under pipefail can close it while unzip still
# writes, and unzip's SIGPIPE then fails the check (seen once in CI)
listing=$(unzip -l "$FSI_LCMTYPES_JAR") || fail "cannot list the jar"
grep -q "fsi/solid_state_t.class" <<<"$listing" || fail "the jar lacks fsi/solid_state_t.class"
javac -nowarn -cp /usr/share/java/lcm.jar -d classes "$FSI_SOURCE_DIR/tests/system/DecodeTrafficLog.java"
java -cp "/usr/share/java/lcm.jar:$FSI_LCMTYPES_JAR:classes" DecodeTrafficLog run/traffic.lcmlog \
  >java_counts.txt || fail "the Java types do not decode the log: $(cat java_counts.txt)"
/usr/bin/python3 - run/traffic.lcmlog >python_counts.txt <<'PY'
import collections, sys, fsi_traffic
c = collections.Counter(e.channel for e in fsi_traffic.read_events(sys.argv[1]) if e.channel.startswith("FSI_"))
for channel in sorted(c):
    print(channel, c[channel])
PY
diff python_counts.txt java_counts.txt || fail "the Java types decode other counts than the Python ones"
pass "the jar's types decode all $(awk '{s += $2} END {print s}' java_counts.txt) FSI_ events of the log"

# The playback path of `fsi spy LOG --speed 1` (real time: faster, UDP on loopback
# drops messages in bursts), with fsi-record recording in the private network in
# lcm-spy's place: every event arrives, nothing else.
FSI_TEST_SPY_RECORDER="$FSI_BIN_DIR/fsi-record" FSI_TEST_SPY_RECORD="$PWD/replayed.lcmlog" timeout 60 "$spy" run/traffic.lcmlog --speed 1 \
  >spy.txt 2>&1 || { cat spy.txt; fail "fsi spy's playback failed"; }
/usr/bin/python3 -m fsi_traffic run/traffic.lcmlog >sent.txt
/usr/bin/python3 -m fsi_traffic replayed.lcmlog >received.txt
diff sent.txt received.txt >/dev/null || fail "the played-back log differs from the log: $(diff sent.txt received.txt | head -5)"
pass "fsi spy plays the log in its private network: $(wc -l <received.txt) window lines arrive whole"

# lcm-spy itself, where a virtual display is at hand (Debian's xvfb; not installed by
# set-up): it starts, finds the project's ten message types and stays up while the
# log plays.
if command -v Xvfb >/dev/null; then
  Xvfb -displayfd 1 -nolisten tcp -screen 0 1024x768x24 >display.txt 2>xvfb.txt &
  xvfb=$!
  for _ in $(seq 50); do [ -s display.txt ] && break; sleep 0.1; done
  [ -s display.txt ] || { kill "$xvfb"; fail "Xvfb did not start: $(cat xvfb.txt)"; }
  DISPLAY=":$(head -n 1 display.txt)" "$spy" run/traffic.lcmlog --speed 1 >lcm-spy.txt 2>&1 &
  viewer=$!
  # The JVM's start and lcm-spy's search of the classpath take seconds, more on a busy
  # machine: wait for its report (up to 60 s), then give the log time to play.
  for _ in $(seq 600); do
    grep -q "LCM types" lcm-spy.txt && break
    kill -0 "$viewer" 2>/dev/null || break
    sleep 0.1
  done
  sleep 3
  alive=0; kill -0 "$viewer" 2>/dev/null && alive=1
  kill "$viewer" 2>/dev/null || true
  wait "$viewer" 2>/dev/null || true
  kill "$xvfb"; wait "$xvfb" 2>/dev/null || true
  [ "$alive" -eq 1 ] || fail "lcm-spy ended early: $(cat lcm-spy.txt)"
  grep -q "Found 10 LCM types" lcm-spy.txt || fail "lcm-spy did not find the message types: $(cat lcm-spy.txt)"
  ! grep -q "Exception\|NoClassDefFoundError" lcm-spy.txt || fail "lcm-spy: $(grep -m 3 "Exception\|NoClassDef" lcm-spy.txt)"
  pass "lcm-spy runs on a virtual display with the project's types"
fi
