#!/usr/bin/env bash
# The ULPH fluid's bad input and blow-ups: each case error is refused before anything
# runs (exit 2, FILE:LINE: [section] key: message), and a run driven past its stable step
# stops with exit 1 and a message naming what, the particle, where and when. A few seconds.
source "$(dirname "$0")/lib.sh"
CASE="$FSI_SOURCE_DIR/cases/f0_hydrostatic_tank.ini"

expect_refused() {   # expect_refused PATTERN --set ...
  local pattern="$1"; shift
  set +e
  "$FSI_RUN" "$CASE" --check "$@" >err.txt 2>&1
  local status=$?
  set -e
  [ "$status" -eq 2 ] || { cat err.txt; fail "$* : exit $status, expected 2"; }
  grep -qF -- "$pattern" err.txt || { cat err.txt; fail "$* : no '$pattern'"; }
  pass "refused: $(head -n 1 err.txt)"
}
expect_refused "[fluid.wall left]: overlaps [fluid.block water]" --set "fluid.wall left.max=0.04,0.6"
expect_refused "[fluid] spacing: -1 must be > 0" --set fluid.spacing=-1
expect_refused "[fluid.block water] max: the box is 25.5 spacings long along y" \
  --set "fluid.block water.max=1,0.51"
expect_refused "[fluid.probe bottom_left] point: lies in no [fluid.block]" \
  --set "fluid.probe bottom_left.point=2,0"
expect_refused "[fluid] sound_speed: is 0" --set fluid.max_velocity=0 --set fluid.max_pressure=0
expect_refused "[fluid.ulph] artificial_viscosity: 0.9 must be <= 0.5" \
  --set fluid.ulph.artificial_viscosity=0.9
# A scheme's own key has one place, its solver section.
expect_refused "[fluid] artificial_viscosity: a key of solvers ulph, wcsph; write it in [fluid.ulph] or [fluid.wcsph]" \
  --set fluid.artificial_viscosity=0.1
expect_refused "[fluid.wall left] motion_direction: is zero" \
  --set "fluid.wall left.motion=harmonic" --set "fluid.wall left.motion_direction=0,0"
expect_refused "[fluid.wall left] motion: " --set "fluid.wall left.motion=wobble"
expect_refused "[fluid.wall left] motion_period: " --set "fluid.wall left.motion_period=0"
expect_refused "[fluid.probe bottom_left] follow: names no [fluid.wall lid]" \
  --set "fluid.probe bottom_left.follow=lid"
expect_refused "[fluid.probe bottom_left] quantity: " --set "fluid.probe bottom_left.quantity=speed"

# Four times the acoustic step without damping: the energy check stops the run.
set +e
"$FSI_RUN" "$CASE" --out unstable --threads 1 --set fluid.spacing=0.05 \
  --set "fluid.wall bottom.min=-0.2,-0.2" --set "fluid.wall bottom.max=1.2,0" \
  --set "fluid.wall left.min=-0.2,0" --set "fluid.wall right.max=1.2,0.6" \
  --set "fluid.probe bottom_left.point=0.25,0" --set fluid.sound_speed=20 \
  --set fluid.cfl_acoustic=1 --set fluid.cfl_force=1 --set fluid.ulph.artificial_viscosity=0 \
  --set fluid.ulph.density_filter_interval=0 --set run.max_window=0.01 >unstable.txt 2>&1
status=$?
set -e
[ "$status" -eq 1 ] || { cat unstable.txt; fail "unstable run: exit $status, expected 1"; }
grep -E "fastest: particle [0-9]+ at \(.*\) .* at t = .* \(window [0-9]+\): the integration is unstable" \
  unstable.txt >/dev/null || { cat unstable.txt; fail "unstable run: no message naming what, where, when"; }
pass "unstable run stopped: $(grep -o 'kinetic energy grew.*' unstable.txt | head -n 1 | cut -c1-100)..."
