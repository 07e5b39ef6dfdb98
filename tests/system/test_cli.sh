#!/usr/bin/env bash
# The command-line conventions (README.md, "Running cases"): fsi --help, -h, help CMD
# and --version exit 0 and say something; unknown commands exit 2; every program of
# launch/ answers --help and --version; long options take --opt=value as well as
# --opt value; fsi keys NAME prints only that part of the reference; fsi bench lists
# every benchmark with the line saying what it measures.
source "$(dirname "$0")/lib.sh"
# The front end takes the programs of this build and builds nothing (launch/fsi).
export FSI_BIN_DIR
FSI="$FSI_SOURCE_DIR/fsi"

# expect_status STATUS NAME COMMAND...: runs COMMAND, output in NAME.txt.
expect_status() {
  local want="$1" name="$2" status
  shift 2
  set +e
  "$@" >"$name.txt" 2>&1
  status=$?
  set -e
  [ "$status" -eq "$want" ] || { cat "$name.txt"; fail "$name: exit status $status, expected $want"; }
}

# The front end's help: every command of its table, the same text for all three.
expect_status 0 help "$FSI" --help
for cmd in main test run inspect replay keys solvers plot-coupling bench setup build; do
  grep -q "^  fsi $cmd\b" help.txt || { cat help.txt; fail "fsi --help does not list '$cmd'"; }
done
expect_status 0 help_short "$FSI" -h
expect_status 0 help_word "$FSI" help
cmp -s help.txt help_short.txt && cmp -s help.txt help_word.txt ||
  fail "fsi --help, fsi -h and fsi help differ"
pass "fsi --help, -h and help list every command"

# fsi help CMD for every command fsi --help lists (new ones included); a program's own
# usage for those that run one.
commands="$(sed -n 's/^  fsi \([a-z-]*\).*/\1/p' help.txt)"
[ "$(echo "$commands" | wc -l)" -ge 13 ] || fail "fsi --help lists too few commands: $commands"
for cmd in $commands; do
  expect_status 0 "help_$cmd" "$FSI" help "$cmd"
  grep -q "usage: fsi $cmd" "help_$cmd.txt" || { cat "help_$cmd.txt"; fail "fsi help $cmd: no usage line"; }
done
# fsi CMD --help is the same, and runs nothing (fsi main --help would run C1 otherwise).
for cmd in main test bench plot-coupling run keys; do
  expect_status 0 "dash_help_$cmd" "$FSI" "$cmd" --help
  cmp -s "help_$cmd.txt" "dash_help_$cmd.txt" || fail "fsi $cmd --help differs from fsi help $cmd"
done
[ ! -e "$FSI_SOURCE_DIR/out/--help" ] || fail "fsi main --help ran the scene"
grep -q -- "--checkpoint-interval" help_run.txt || fail "fsi help run does not show fsi-run's options"
grep -q -- "--participant" help_replay.txt || fail "fsi help replay does not show fsi-replay's options"
pass "fsi help CMD gives a usage for every command"

# One version, from CMakeLists.txt's project(... VERSION), in the front end and the programs.
version="$(sed -n 's/^project([^)]* VERSION \([0-9][0-9.]*\).*/\1/p' "$FSI_SOURCE_DIR/CMakeLists.txt")"
[ -n "$version" ] || fail "no project VERSION in CMakeLists.txt"
expect_status 0 version "$FSI" --version
grep -qE "^fsi $version(-|$)" version.txt || { cat version.txt; fail "fsi --version does not print $version"; }
expect_status 0 version_word "$FSI" version
cmp -s version.txt version_word.txt || fail "fsi --version and fsi version differ"
for program in fsi-run fsi-inspect fsi-replay fsi-keys fsi-solvers fsi-record; do
  expect_status 0 "${program}_help" "$FSI_BIN_DIR/$program" --help
  grep -q "^usage:" "${program}_help.txt" || fail "$program --help prints no usage"
  expect_status 0 "${program}_h" "$FSI_BIN_DIR/$program" -h
  cmp -s "${program}_help.txt" "${program}_h.txt" || fail "$program -h differs from --help"
  expect_status 0 "${program}_version" "$FSI_BIN_DIR/$program" --version
  grep -q " $version-" "${program}_version.txt" || { cat "${program}_version.txt"; fail "$program --version"; }
  expect_status 2 "${program}_unknown" "$FSI_BIN_DIR/$program" --no-such-option
  grep -q "unknown option '--no-such-option'" "${program}_unknown.txt" ||
    { cat "${program}_unknown.txt"; fail "$program: no message for an unknown option"; }
done
grep -qx "version: \"$version\"" "$FSI_SOURCE_DIR/CITATION.cff" ||
  fail "CITATION.cff's version is not CMakeLists.txt's $version"
grep -q "Apache License" "$FSI_SOURCE_DIR/LICENSE" && grep -q "Version 2.0, January 2004" "$FSI_SOURCE_DIR/LICENSE" ||
  fail "LICENSE is not the Apache License 2.0"
pass "fsi --version: $(cat version.txt); every program answers --help, -h, --version; CITATION.cff the same version"

# Unknown commands and help topics exit 2 and name the commands.
expect_status 2 nosuch "$FSI" nosuch
grep -q "unknown command 'nosuch'.* run " nosuch.txt || { cat nosuch.txt; fail "fsi nosuch: message"; }
expect_status 2 help_nosuch "$FSI" help nosuch
grep -q "no command 'nosuch'" help_nosuch.txt || { cat help_nosuch.txt; fail "fsi help nosuch: message"; }
expect_status 2 no_command "$FSI"
pass "fsi nosuch and fsi help nosuch exit 2"

# --opt=value is --opt value: a value given either way reaches the case check...
small_case good.ini
expect_status 2 set_equals "$FSI_BIN_DIR/fsi-run" good.ini --check --set=fluid.damping=lots
grep -q "^--set fluid.damping=lots: \[fluid\] damping: 'lots' is not a number" set_equals.txt ||
  { cat set_equals.txt; fail "--set=VALUE did not reach the case check"; }
expect_status 0 set_equals_good "$FSI_BIN_DIR/fsi-run" good.ini --check --set=fluid.damping=3 \
  --threads=1
expect_status 2 threads_equals "$FSI_BIN_DIR/fsi-run" good.ini --check --threads=0
grep -q "threads needs a whole number" threads_equals.txt || { cat threads_equals.txt; fail "--threads=0"; }
# ... and a run writes where --out= says, with a --set= applied.
expect_status 0 run_equals "$FSI_RUN" good.ini --out=out_equals --set=run.end_time=0.05 --force
[ -s out_equals/probes.csv ] || fail "--out=out_equals: no probes.csv there"
grep -q "end_time = 0.05" out_equals/case.resolved.ini || fail "--set=run.end_time=0.05 not applied"
# A missing value, a value given to a flag, a second case: exit 2, nothing written.
expect_status 2 missing_value "$FSI_BIN_DIR/fsi-run" good.ini --out
grep -q -- "--out needs a value" missing_value.txt || { cat missing_value.txt; fail "missing value: message"; }
expect_status 2 empty_value "$FSI_BIN_DIR/fsi-run" good.ini --out=
expect_status 2 flag_value "$FSI_BIN_DIR/fsi-run" good.ini --out=out_flag --force=yes
grep -q -- "--force takes no value" flag_value.txt || { cat flag_value.txt; fail "--force=yes: message"; }
[ ! -e out_flag ] || fail "--force=yes: an output folder was created"
expect_status 2 replay_equals "$FSI_BIN_DIR/fsi-replay" out_equals --participant=gas
grep -q "participant must be fluid or solid, not 'gas'" replay_equals.txt ||
  { cat replay_equals.txt; fail "fsi replay --participant=gas did not reach its check"; }
pass "--opt=value works as --opt value; missing values and flags with values exit 2"

# fsi keys NAME: only that part of the reference.
expect_status 0 keys_tlsph "$FSI" keys tlsph
grep -q '^#### \[solid.tlsph\]' keys_tlsph.txt || fail "fsi keys tlsph: no [solid.tlsph] keys"
grep -q '`gradient_order`' keys_tlsph.txt || fail "fsi keys tlsph: no gradient_order key"
! grep -qi 'ulph\|\[fluid\.\|nosbpd\]' keys_tlsph.txt || fail "fsi keys tlsph prints other solvers' keys"
expect_status 0 keys_run "$FSI" keys run
grep -q '`end_time`' keys_run.txt && ! grep -q 'solver = ' keys_run.txt || fail "fsi keys run"
expect_status 0 keys_fluid "$FSI" keys fluid
for s in ulph wcsph isph; do grep -q "^### solver = $s (fluid)" keys_fluid.txt || fail "fsi keys fluid: no $s"; done
! grep -q '(solid)' keys_fluid.txt || fail "fsi keys fluid prints solid solvers"
expect_status 2 keys_nosuch "$FSI" keys nosuch
grep -q "no section, solver or role 'nosuch'; one of: .*tlsph" keys_nosuch.txt ||
  { cat keys_nosuch.txt; fail "fsi keys nosuch: message"; }
pass "fsi keys tlsph / run / fluid print their parts only; an unknown name exits 2"

# fsi bench: every bench/*.sh with its one-line description.
expect_status 0 bench "$FSI" bench
n=0
for script in "$FSI_SOURCE_DIR"/bench/*.sh; do
  name="$(basename "$script" .sh)"
  what="$(sed -n 's/^# fsi bench: //p' "$script" | head -n 1)"
  [ -n "$what" ] || fail "bench/$name.sh has no '# fsi bench: WHAT IT MEASURES' line"
  grep -qF "$name" bench.txt && grep -qF "$what" bench.txt || { cat bench.txt; fail "fsi bench does not list $name"; }
  n=$((n + 1))
done
expect_status 2 bench_nosuch "$FSI" bench nosuch
pass "fsi bench lists all $n benchmarks with what each measures"
