#!/usr/bin/env bash
# fsi replay: one participant of a run recorded with --log-traffic runs again alone,
# against the recorded messages and without any network, and reproduces its HDF5
# output and every message it published bit for bit. With a changed physical key
# the replay must see the difference (so this test can fail), and bad input is
# refused with status 2 before anything is written.
source "$(dirname "$0")/lib.sh"
REPLAY="$FSI_BIN_DIR/fsi-replay"

# Value of "name = value" in a replay's run.log.
replay_stat() { awk -v n="$2" '$1 == n {sub(/^[^=]*= /, ""); print; exit}' "$1/run.log"; }

# Every window of a recording before the finishing one has its step, a DONE from
# each participant and, in a coupled run, both interface messages; prints the first
# window with a gap.
recording_gap() {
  "$FSI_BIN_DIR/fsi-inspect" "$1/traffic.lcmlog" | awk '
    $1 ~ /^[0-9]+$/ { w = $1 + 0; seen[w, $3] += $4; any[$3] = 1; if (w > last) last = w }
    END {
      coupled = ("FSI_SOLID_STATE" in any) && ("FSI_FLUID_LOAD" in any)
      for (w = 0; w < last; w++)
        if (!seen[w, "FSI_STEP"] || seen[w, "FSI_DONE"] < 1 + coupled ||
            (coupled && (!seen[w, "FSI_SOLID_STATE"] || !seen[w, "FSI_FLUID_LOAD"]))) {
          print "window " w; exit
        }
    }'
}

# A recorder is a process like the others: on a machine loaded far beyond its cores
# the kernel can drop a multicast datagram before the recorder reads it, and a replay
# cannot be made from a log with a gap. Such a recording is made again (up to three
# times, said in the test's output); the replay itself is never retried.
record() {   # record OUT CASE [fsi run options...]
  local out="$1" case="$2"; shift 2
  local attempt gap
  for attempt in 1 2 3; do
    "$FSI_RUN" "$case" --out "$out" --log-traffic --threads 1 --force "$@" >"$out.txt" 2>&1 \
      || { cat "$out.txt"; fail "recording $out failed"; }
    gap=$(recording_gap "$out")
    [ -z "$gap" ] && return 0
    echo "note: the recording of $out misses messages of $gap (attempt $attempt): recording again"
  done
  fail "three recordings of $out had gaps"
}

expect_reproduced() {   # expect_reproduced RUN PARTICIPANT
  local run="$1" p="$2" out="$1-replay-$2"
  "$REPLAY" "$run" --participant "$p" --out "$out" --threads 1 >"$out.txt" 2>&1 \
    || { cat "$out.txt" "$out/$p.log"; fail "replay of $p from $run: not reproduced"; }
  h5_same "$run" "$out" "$p" || fail "$p.h5 of the replay differs from $run"
  local compared differing
  compared=$(replay_stat "$out" messages_compared)
  differing=$(replay_stat "$out" messages_differing)
  [ "$differing" = 0 ] || fail "$p from $run: $differing messages differ"
  [ "$compared" -gt 2 ] || fail "$p from $run: only $compared messages compared"
  grep -q "replaying $p from .* (no network)" "$out/$p.log" || fail "$p log does not say it replayed"
  pass "$p replayed from $run: $compared messages and $p.h5 identical"
}

expect_detected() {   # expect_detected RUN PARTICIPANT KIND SET
  local run="$1" p="$2" kind="$3" set="$4" out="$1-changed-$2"
  set +e
  "$REPLAY" "$run" --participant "$p" --out "$out" --threads 1 --set "$set" >"$out.txt" 2>&1
  local status=$?
  set -e
  [ "$status" -eq 1 ] || { cat "$out.txt"; fail "replay of $p with $set: status $status, expected 1"; }
  if h5_same "$run" "$out" "$p"; then
    fail "replay of $p with $set: h5diff finds no difference"
  fi
  local differing first window
  differing=$(replay_stat "$out" messages_differing)
  first=$(replay_stat "$out" first_difference)
  window=$(awk '$1 == "first_difference_window" {print $3}' "$out/replay.log")
  [ "$differing" -gt 0 ] || fail "replay of $p with $set: no message differs"
  case "$first" in "$kind of window $window:"*) ;;
    *) fail "replay of $p with $set: first difference '$first' is not a $kind of window $window" ;;
  esac
  grep -q "NOT reproduced" "$out.txt" || fail "replay of $p with $set does not say so"
  pass "$p with $set: $differing messages differ, first: $first"
}

# 1. The example participants (the demo scene, 0.3 s: 301 windows).
record demo "$FSI_SOURCE_DIR/cases/demo_spring_dashpot.ini" --set run.end_time=0.3
expect_reproduced demo fluid
expect_reproduced demo solid
expect_detected demo fluid fluid_load fluid.damping=3.0
expect_detected demo solid solid_state solid.stiffness=101

# 2. A run whose messages were lost and resent: the log holds resent copies, late
#    first copies and repeated requests, and the replay still matches.
FSI_TEST_DROP_FRACTION=0.2 FSI_TEST_DROP_SEED=5 \
  record lossy "$FSI_SOURCE_DIR/cases/demo_spring_dashpot.ini" --set run.end_time=0.1
expect_reproduced lossy fluid
expect_reproduced lossy solid

# 3. The project's own solvers: ULPH water against an elastic NOSB-PD post, clamped
#    at its foot, that the water leans on (51 windows, under a second).
cat >fsi.ini <<'CASE'
[run]
title = replay test: water against an elastic post
end_time = 0.05
max_window = 1e-3
output_interval = 0.01
probe_interval = 1e-3

[fluid]
solver = ulph
spacing = 0.01
max_velocity = 1.4
max_pressure = 1000
gravity = 0, -9.81

[fluid.block water]
min = 0, 0
max = 0.14, 0.1

[fluid.wall bottom]
min = -0.04, -0.04
max = 0.24, 0

[fluid.wall left]
min = -0.04, 0
max = 0, 0.15

[fluid.wall right]
min = 0.2, 0
max = 0.24, 0.15

[solid]
solver = nosbpd
spacing = 0.01
density = 1100
youngs_modulus = 1e6
poisson_ratio = 0.3
gravity = 0, -9.81

[solid.block post]
min = 0.14, -0.03
max = 0.16, 0.08

[solid.region foot]
min = 0.14, -0.03
max = 0.16, 0
action = clamp
clamp_face = y_max
CASE
record fsi fsi.ini
awk '$3 == "FSI_FLUID_LOAD" && $11 > 0 {found = 1} END {exit !found}' \
  <("$FSI_BIN_DIR/fsi-inspect" fsi/traffic.lcmlog) || fail "the water never loads the post"
expect_reproduced fsi fluid
expect_reproduced fsi solid
expect_detected fsi fluid fluid_load fluid.viscosity=2e-3
# The solid's first message after its first changed window is that window's done_t,
# which carries its step and largest speed (docs/protocol.md, done_t's stats).
expect_detected fsi solid done solid.youngs_modulus=1.1e6

# 4. Bad input: status 2, a message, and no output folder.
expect_bad() {   # expect_bad NAME EXPECTED_TEXT ARGS...
  local name="$1" text="$2"; shift 2
  set +e
  "$REPLAY" --out "bad-$name" "$@" >"bad-$name.txt" 2>&1
  local status=$?
  set -e
  [ "$status" -eq 2 ] || { cat "bad-$name.txt"; fail "$name: status $status, expected 2"; }
  grep -q "$text" "bad-$name.txt" || { cat "bad-$name.txt"; fail "$name: no '$text' in the message"; }
  [ ! -e "bad-$name" ] || fail "$name: an output folder was created"
  pass "bad input refused: $name"
}
mkdir -p nolog empty
cp demo/case.resolved.ini demo/run.log nolog/
cp demo/case.resolved.ini demo/run.log empty/
: >empty/traffic.lcmlog
small_case solid_only.ini 0.05
sed -i '/^\[fluid\]/,$d' solid_only.ini
record solid_only solid_only.ini
expect_bad missing_log "traffic.lcmlog" nolog --participant fluid
expect_bad empty_log "holds no message of participant 'fluid'" empty --participant fluid
expect_bad no_section "has no \[fluid\] section" solid_only --participant fluid
expect_bad unknown_participant "must be fluid or solid" demo --participant coupler
expect_bad into_recording "must not be the recorded run" demo --participant fluid --force \
  --out demo
h5_same demo demo-replay-fluid fluid || fail "the recorded run was touched"
