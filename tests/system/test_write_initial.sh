#!/usr/bin/env bash
# fsi run CASE --check --write-initial: frame 0 of every participant, nothing run, for
# a case with a disc solid (a Turek-Hron-like cylinder with a flag) and an inclined
# (turned) baffle wall; the particles where the shapes put them
# (shapes_frame0_check.py). A bad shape exits 2 naming file, line and key.
source "$(dirname "$0")/lib.sh"

cat >shapes.ini <<'CASE'
[run]
title = shapes
end_time = 0.1
max_window = 1e-3
output_interval = 0.02

[solid]
solver = nosbpd
spacing = 0.004
density = 2500
youngs_modulus = 1e6
poisson_ratio = 0
gravity = 0, -9.81

[solid.block cylinder]
shape = disc
centre = 0.4, 0.1
radius = 0.04

[solid.block flag]
min = 0.44, 0.096
max = 0.52, 0.104

[solid.region hold]
min = 0.36, 0.06
max = 0.44, 0.14
action = clamp

[fluid]
solver = ulph
spacing = 0.004
sound_speed = 20
gravity = 0, -9.81

[fluid.block water]
min = 0, 0
max = 0.144, 0.12

[fluid.wall floor]
min = -0.012, -0.012
max = 0.6, 0

[fluid.wall left]
min = -0.012, 0
max = 0, 0.3

[fluid.wall baffle]
min = 0.2, 0.2
max = 0.28, 0.212
angle = 30
CASE

"$FSI_RUN" shapes.ini --check --write-initial --out out >run.txt 2>&1 \
  || { cat run.txt out/*.log 2>/dev/null; fail "--check --write-initial failed"; }
grep -q "frame 0 in" run.txt || { cat run.txt; fail "no frame 0 message"; }
for p in fluid solid; do
  [ -s "out/$p.h5" ] && [ -s "out/$p.xmf" ] || fail "out/$p.h5 or .xmf missing"
  [ "$(ls "out/$p.frames" | grep -c '^[0-9]*\.h5$')" -eq 1 ] || fail "$p: not exactly one frame"
done
output_readable out fluid solid || fail "frame 0 does not read back"
[ ! -e out/probes.csv ] || fail "probes.csv written: something ran"
/usr/bin/python3 "$FSI_SOURCE_DIR/tests/system/shapes_frame0_check.py" out \
  || fail "particles not where the shapes put them"
pass "frame 0 of both participants: $(/usr/bin/python3 "$FSI_SOURCE_DIR/tests/system/shapes_frame0_check.py" out)"

# Every fluid and solid solver builds its particles and writes frame 0 alone.
for pair in wcsph:pseudo_spring isph:tlsph; do
  "$FSI_RUN" shapes.ini --check --write-initial --out "out_${pair%:*}" \
    --set "fluid.solver=${pair%:*}" --set "solid.solver=${pair#*:}" >"$pair.txt" 2>&1 \
    || { cat "$pair.txt"; fail "$pair: --write-initial failed"; }
  output_readable "out_${pair%:*}" fluid solid || fail "$pair: frame 0 does not read back"
done
pass "frame 0 with wcsph + pseudo_spring and isph + tlsph"

# --write-initial without --check is refused
set +e
"$FSI_RUN" shapes.ini --write-initial --out out_alone >alone.txt 2>&1
status=$?
set -e
[ "$status" -eq 2 ] && [ ! -e out_alone ] || { cat alone.txt; fail "--write-initial alone: exit $status"; }

# Bad shapes: exit 2, file, line and key, no output folder.
sed 's/^radius = 0.04/radius = 0/' shapes.ini >bad.ini
expect_bad_case radius "^bad.ini:[0-9]+: \[solid.block cylinder\] radius: must be > 0" --check --write-initial
sed 's/^shape = disc/shape = blob/' shapes.ini >bad.ini
expect_bad_case unknown_shape "^bad.ini:[0-9]+: \[solid.block cylinder\] shape: .*blob" --check --write-initial
sed 's/^angle = 30/angle = 30\nshape = polygon\npoints = 0.2,0.2 0.3,0.2/' shapes.ini >bad.ini
expect_bad_case two_corners "^bad.ini:[0-9]+: \[fluid.wall baffle\] points: too few corners" --check --write-initial
sed 's/^angle = 30/shape = polygon\npoints = 0.2,0.2 0.3,0.3 0.3,0.2 0.2,0.3/' shapes.ini >bad.ini
expect_bad_case crossing "^bad.ini:[0-9]+: \[fluid.wall baffle\] points: edge 1 .* crosses edge 3" --check --write-initial
