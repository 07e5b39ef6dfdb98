#!/usr/bin/env bash
# The NOSB-PD solid driven past its stable step stops with a clear message instead
# of writing NaN; the same scene at the default time_step_safety runs to the end.
#
# Scene: benchmark S2's clamped plate at half the length and twice the spacing
# (L = 0.1 m, T = 0.02 m, dx = 2 mm: 500 points + 30 clamped), released with the
# cantilever mode's velocity. Its stable step estimate is 2.99e-5 s (solid.log).
# Windows of 1e-4 s: at time_step_safety = 4 each window is ONE sub-step of 1e-4 s,
# i.e. 3.35 x the estimate (the sub-step is window / ceil(window / (safety *
# stable)), so what counts is this ratio, not the key's value). docs/nosbpd.md
# measured velocity Verlet on this model stable up to 2.4-2.5 x the estimate; 3.35 x
# is well past it and blows up within a few windows (measured: the energy check
# stops it at t = 0.5 ms, window 5, after frames at 0 .. 0.4 ms were written). At the
# default 0.8 each window is 5 sub-steps of 2e-5 s (0.67 x) and the run ends.
#
# Checks of the unstable run:
#  - fsi run exits 1 (a participant failed) and names the solid;
#  - the solid warned at start-up that time_step_safety is beyond the stable step;
#  - its error (solid.log, run.log) says "unstable", names a particle and its
#    position (where) and t = ... (when); which check fires first (energy growth,
#    a point moving more than one spacing in a sub-step, or an inverted deformation
#    gradient) is not part of the contract, each message names all three;
#  - solid.h5 is readable by h5dump, holds at least two frames (so frames written
#    while the instability was growing are checked, not only the initial one), and
#    no frame holds a NaN or Inf in any field.
source "$(dirname "$0")/lib.sh"
checker="$FSI_SOURCE_DIR/tests/system/solid_h5_check.py"

cat >plate.ini <<'CASE'
[run]
title = coarse clamped plate (stability test)
end_time = 0.01
max_window = 1e-4
output_interval = 1e-4
probe_interval = 1e-4

[solid]
solver = nosbpd
spacing = 0.002
density = 1000
youngs_modulus = 1.99875e6
poisson_ratio = 0.3975
plane = strain
initial_velocity = cantilever_mode
mode_amplitude = 0.01
mode_length = 0.1
mode_origin = 0

[solid.block clamp]
min = -0.006, -0.01
max = 0, 0.01

[solid.block plate]
min = 0, -0.01
max = 0.1, 0.01

[solid.region fixed]
min = -0.006, -0.01
max = 0, 0.01
action = clamp

[solid.probe tip]
point = 0.099, 0.001
CASE

# --- past the stable step ---------------------------------------------------------
set +e
"$FSI_RUN" plate.ini --out unstable --set solid.time_step_safety=4 >unstable.txt 2>&1
status=$?
set -e
[ "$status" -eq 1 ] || { cat unstable.txt; fail "unstable run: exit $status, expected 1"; }
grep -q "run failed: participant 'solid'" unstable.txt ||
  { cat unstable.txt; fail "unstable run: 'fsi run' does not name the solid as the failure"; }
grep -q "warning: time_step_safety = 4 is beyond the estimated stable step" unstable/solid.log ||
  { cat unstable/solid.log; fail "no start-up warning about time_step_safety > 1"; }

error=$(grep -m1 '^\[solid\] error: ' unstable/solid.log) ||
  { cat unstable/solid.log; fail "solid.log has no error line"; }
echo "$error"
echo "$error" | grep -q "unstable" || fail "the error does not say the run is unstable: $error"
# where: "particle 77 (0.095, -0.009)" or the model's "point id 77 at (...)"
echo "$error" | grep -Eq "(particle|point id) [0-9]+ (at )?\(-?[0-9.e+-]+, -?[0-9.e+-]+\)" ||
  fail "the error does not name a particle and its position: $error"
echo "$error" | grep -Eq "t = [0-9.e+-]+ s" || fail "the error does not say when (t = ... s): $error"
grep -q "^exit = failure: participant 'solid'.*unstable" unstable/run.log ||
  fail "run.log does not record the solid's unstable stop as the exit reason"

h5dump -H unstable/solid.h5 >/dev/null || fail "unstable run: solid.h5 unreadable by h5dump"
summary=$(/usr/bin/python3 "$checker" finite unstable/solid.h5) ||
  fail "unstable run: solid.h5 holds non-finite values ($summary)"
frames=$(echo "$summary" | awk '{print $2}')
[ "$frames" -ge 2 ] ||
  fail "unstable run wrote $frames frame(s): it blew up before anything but the initial frame"
pass "time_step_safety = 4 (one sub-step of 1e-4 s per window) stopped: exit 1, $summary, all finite"

# --- the same scene at the default safety ------------------------------------------
"$FSI_RUN" plate.ini --out stable >stable.txt 2>&1 ||
  { cat stable.txt; fail "the same scene at the default time_step_safety failed"; }
! grep -q "beyond the estimated stable step" stable/solid.log ||
  fail "the default time_step_safety warns about the stable step"
summary=$(/usr/bin/python3 "$checker" finite stable/solid.h5) ||
  fail "stable run: solid.h5 holds non-finite values ($summary)"
echo "$summary" | grep -q "last_time 0.01$" || fail "stable run did not reach t = 0.01 s ($summary)"
pass "default time_step_safety: exit 0, $summary"
