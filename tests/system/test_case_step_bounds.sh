#!/usr/bin/env bash
# Values that passed --check but made runs hang or run to nonsense (a window of 1e-300 s,
# a viscosity of 1e300 Pa s, a solid safety factor of 1e-300, densities of 1e-12 and
# 1e30 kg/m^3) are refused before anything runs: exit 2, the key in the message, no
# output folder. So are steps that are fine alone but too many up to end_time, with the
# message on the key the user wrote (FILE:LINE). Well under a second.
source "$(dirname "$0")/lib.sh"
F1="$FSI_SOURCE_DIR/cases/f1_dam_break.ini"
C1="$FSI_SOURCE_DIR/cases/c1_elastic_plate.ini"

expect_refused() {   # expect_refused CASE PATTERN --set ...
  local case_file="$1" pattern="$2"; shift 2
  set +e
  "$FSI_RUN" "$case_file" --check "$@" >err.txt 2>&1
  local status=$?
  # A case that is not refused would run: let it, briefly.
  timeout 20 "$FSI_RUN" "$case_file" --out refused "$@" >>err.txt 2>&1
  local run_status=$?
  set -e
  [ "$status" -eq 2 ] && [ "$run_status" -eq 2 ] ||
    { cat err.txt; fail "$* : exit $status (check) and $run_status (run), expected 2"; }
  grep -qF -- "$pattern" err.txt || { cat err.txt; fail "$* : no '$pattern'"; }
  [ ! -e refused ] || fail "$* : an output folder was created"
  pass "refused: $(head -n 1 err.txt | cut -c1-160)"
}

# The five values of the issue.
expect_refused "$F1" "[run] max_window: the coupling window (max_window) is 1e-300 s, below 1e-12 s" \
  --set run.max_window=1e-300
expect_refused "$F1" "[fluid] viscosity: 1e300 must be <= 10000" --set fluid.viscosity=1e300
expect_refused "$C1" "[solid] time_step_safety: the solid's sub-step" --set solid.time_step_safety=1e-300
expect_refused "$F1" "[fluid] density: 1e-12 must be >= 0.001" --set fluid.density=1e-12
expect_refused "$C1" "[solid] density: 1e30 must be <= 100000" --set solid.density=1e30
expect_refused "$C1" "[fluid] density: 1e30 must be <= 100000" --set fluid.density=1e30

# Inside every key's range, but the step they give is absurd: the key farthest off names it.
expect_refused "$F1" "[fluid] sound_speed: the fluid's acoustic step limit" --set fluid.sound_speed=1e300
expect_refused "$F1" "[fluid] cfl_acoustic: the fluid's acoustic step limit" --set fluid.cfl_acoustic=1e-300
expect_refused "$C1" "[solid] youngs_modulus: the solid's sub-step" --set solid.youngs_modulus=1e300
expect_refused "$F1" "[run] probe_interval: the coupling window (probe_interval)" \
  --set run.probe_interval=1e-300
expect_refused "$F1" "[run] end_time: the fluid's acoustic step limit" --set run.end_time=1e9
expect_refused "$F1" "[fluid] viscosity: the fluid's viscous step limit" \
  --set fluid.viscosity=1e4 --set run.end_time=1000

# In the file, the message names the file and the line of the key.
sed 's/^sound_speed = 40$/sound_speed = 1e300/' "$F1" >fast_sound.ini
line=$(grep -n '^sound_speed = 1e300$' fast_sound.ini | cut -d: -f1)
[ -n "$line" ] || fail "could not edit the case"
expect_refused fast_sound.ini "fast_sound.ini:$line: [fluid] sound_speed: the fluid's acoustic step limit"

# Every shipped case stays valid (test_cases_valid.sh checks them all; these are the
# shortest steps among them).
for f in s4_notched_plate c2_elastic_gate; do
  "$FSI_RUN" "$FSI_SOURCE_DIR/cases/$f.ini" --check >/dev/null || fail "$f is refused"
done
pass "the cases with the shortest steps pass"
