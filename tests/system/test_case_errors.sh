#!/usr/bin/env bash
# Bad input: every kind of case error exits with status 2, names file, line, section
# and key, and leaves no output folder behind.
source "$(dirname "$0")/lib.sh"
small_case good.ini

# Line numbers below refer to small_case's layout: [run] at 1, end_time 3, [solid] 8,
# solver 9, particles 10, time_step 11, [fluid] 13, solver 14, damping 15.
sed 's/^particles = 50/particls = 50/' good.ini >bad.ini
expect_bad_case typo "^bad.ini:10: \[solid\] particls: unknown key 'particls' \(did you mean 'particles'\?\)"

sed '/^end_time/d' good.ini >bad.ini
expect_bad_case missing_key "^bad.ini:1: \[run\] end_time: required key missing"

sed 's/^damping = 2.0/damping = lots/' good.ini >bad.ini
expect_bad_case bad_value "^bad.ini:15: \[fluid\] damping: 'lots' is not a number"

sed 's/^time_step = 1e-4/time_step = -1e-4/' good.ini >bad.ini
expect_bad_case negative "^bad.ini:11: \[solid\] time_step: -1e-4 must be > 0"

sed 's/^solver = linear_dashpot/solver = ulhp/' good.ini >bad.ini
expect_bad_case unknown_solver "^bad.ini:14: \[fluid\] solver: unknown solver 'ulhp'"

sed 's/^solver = linear_dashpot/solver = spring_oscillators/' good.ini >bad.ini
expect_bad_case wrong_role "^bad.ini:14: \[fluid\] solver: .*solid"

sed 's/^\[fluid\]/[fluidd]/' good.ini >bad.ini
expect_bad_case unknown_section "^bad.ini:13: .*\[fluidd\]"

sed 's/^damping = 2.0/damping 2.0/' good.ini >bad.ini
expect_bad_case syntax "^bad.ini:15: syntax error"

sed 's/^damping = 2.0/damping = 2.0\ndamping = 3.0/' good.ini >bad.ini
expect_bad_case duplicate "^bad.ini:16: \[fluid\] damping: .*15"

cp good.ini bad.ini
expect_bad_case bad_set "^--set solid.particles=0: \[solid\] particles: 0 must be >= 1" --set solid.particles=0
expect_bad_case bad_set_form "^--set nodot" --set nodot
expect_bad_case unknown_option "unknown option '--frobnicate'" --frobnicate

set +e
"$FSI_RUN" does_not_exist.ini --out out_missing >missing.txt 2>&1
status=$?
set -e
[ "$status" -eq 2 ] && grep -q "does_not_exist.ini" missing.txt && [ ! -e out_missing ] \
  || { cat missing.txt; fail "missing case file: status $status"; }
pass "missing case file: $(head -n 1 missing.txt)"

# Object sections [ROLE.KIND NAME]; appended lines start at 16. The example solvers
# take no object sections.
{ cat good.ini; printf '[solid.block beam]\nmin = 0\n'; } >bad.ini
expect_bad_case object_kind "^bad.ini:16: \[solid.block beam\]: unknown object kind 'block' for solver spring_oscillators"

{ cat good.ini; printf '[fluid.wall tank]\n[fluid.wall   tank]\n'; } >bad.ini
expect_bad_case duplicate_object "^bad.ini:17: section \[fluid.wall tank\] given twice \(first at bad.ini:16\)"

{ sed '/^\[fluid\]/,$d' good.ini; printf '[fluid.wall tank]\n'; } >bad.ini
expect_bad_case object_without_participant "^bad.ini:13: \[fluid.wall tank\]: no \[fluid\] section"

cp good.ini bad.ini
expect_bad_case set_object "^--set solid.block beam.max=1: \[solid.block beam\]: unknown object kind" \
  --set "solid.block beam.max=1"

# Keys valid one by one but not together.
cp good.ini bad.ini
expect_bad_case watchdog_vs_heartbeat \
  "^--set run.watchdog_timeout=0.3: \[run\] watchdog_timeout: 0.3 s is less than twice heartbeat_interval" \
  --set run.watchdog_timeout=0.3

# Several errors are all reported at once.
sed 's/^particles = 50/particls = 50/; s/^damping = 2.0/damping = -1/' good.ini >bad.ini
expect_bad_case two_errors "has 2 errors"

# A solid interface depth that does not cover the fluid's reach below the surface
# (docs/coupling.md, Unequal spacings): C6 with the solid 4 times finer than its fluid,
# whose ULPH kernel reaches 1.2 * 3 * 2.5 mm - 1.25 mm = 7.75 mm below the surface.
sed 's/^spacing = 0.0025$/&\ninterface_depth = 0.005/; T; :a; n; ba' \
  "$FSI_SOURCE_DIR/cases/c6_notched_obstacle.ini" >bad.ini
line=$(grep -n '^interface_depth' bad.ini | cut -d: -f1)
[ -n "$line" ] || fail "interface_depth not inserted into bad.ini"
expect_bad_case interface_depth \
  "^bad.ini:$line: \[solid\] interface_depth: 0.005 m does not cover the fluid's reach below the surface, 0.00775 m" \
  --set solid.spacing=0.000625

# Solver sections (docs/cases.md): a scheme's own key in [fluid] names its section; a
# typo in the section of a solver that is not chosen (here ULPH's beside the dashpot)
# is still an error; an unknown [fluid.xyz] names the known ones.
c1="$FSI_SOURCE_DIR/cases/c1_elastic_plate.ini"
line=$(grep -n '^artificial_viscosity' "$c1" | cut -d: -f1)
[ -n "$line" ] || fail "no artificial_viscosity line in $c1"
sed "${line}d; s/^sound_speed = .*$/&\nartificial_viscosity = 0.1/" "$c1" >bad.ini
line=$(grep -n '^artificial_viscosity' bad.ini | cut -d: -f1)
expect_bad_case own_key_in_fluid \
  "^bad.ini:$line: \[fluid\] artificial_viscosity: a key of solvers ulph, wcsph; write it in \[fluid.ulph\] or \[fluid.wcsph\]"
cp "$c1" bad.ini
expect_bad_case own_key_set \
  "^--set fluid.smoothing_factor=1.3: \[fluid\] smoothing_factor: a key of solvers ulph, wcsph, isph; write it in \[fluid.ulph\] or \[fluid.wcsph\] or \[fluid.isph\]" \
  --set fluid.smoothing_factor=1.3
expect_bad_case own_key_bound \
  "^--set fluid.ulph.artificial_viscosity=0.9: \[fluid.ulph\] artificial_viscosity: 0.9 must be <= 0.5" \
  --set fluid.ulph.artificial_viscosity=0.9
expect_bad_case support_written \
  "^--set fluid.support=0.02: \[fluid\] support: a derived value, not a setting" \
  --set fluid.support=0.02
printf '\n[fluid.ulph]\nartifical_viscosity = 0.1\n' | cat good.ini - >bad.ini
line=$(grep -n '^artifical_viscosity' bad.ini | cut -d: -f1)
expect_bad_case unchosen_section_typo \
  "^bad.ini:$line: \[fluid.ulph\] artifical_viscosity: unknown key 'artifical_viscosity' \(did you mean 'artificial_viscosity'\?\)"
printf '\n[fluid.xyz]\n' | cat good.ini - >bad.ini
line=$(grep -n '^\[fluid.xyz\]' bad.ini | cut -d: -f1)
expect_bad_case unknown_solver_section \
  "^bad.ini:$line: \[fluid.xyz\]: unknown section: 'xyz' is no fluid solver \(solver sections: \[fluid.linear_dashpot\], \[fluid.ulph\], \[fluid.wcsph\], \[fluid.isph\]\)"


# What a solid model accepts (solid_model_check.c): RK4 only with a model whose force
# commits nothing, a law of F only with a model that has F, a plastic law only with an
# incremental model.
s2="$FSI_SOURCE_DIR/cases/s2_plate_oscillation.ini"
cp "$s2" bad.ini
expect_bad_case rk4_with_committing_model \
  "^--set solid.integrator=rk4: \[solid\] integrator: rk4 evaluates the internal force at trial states it throws away, and nosbpd commits" \
  --set solid.integrator=rk4
expect_bad_case law_without_deformation_gradient \
  "^--set solid.constitutive=neo_hookean: \[solid\] constitutive: neo_hookean is a function of the deformation gradient, which pseudo_spring does not have" \
  --set solid.solver=pseudo_spring --set solid.constitutive=neo_hookean
expect_bad_case plastic_law_total_model \
  "\[solid\] constitutive: drucker_prager needs an incremental stress update" \
  --set solid.solver=tlsph --set solid.constitutive=drucker_prager \
  --set solid.cohesion=1e4 --set solid.friction_angle=30
