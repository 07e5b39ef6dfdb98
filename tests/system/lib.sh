# Shared helpers of the system tests (sourced). Every test gets FSI_SOURCE_DIR,
# FSI_BIN_DIR and its own FSI_TEST_TMP from ctest.
set -euo pipefail
: "${FSI_SOURCE_DIR:?}" "${FSI_BIN_DIR:?}" "${FSI_TEST_TMP:?}"
# Every run gets window_timeout = 20 s (fsi_run_for_tests.sh): a deadlock fails in
# seconds with the coupler's message, not at ctest's timeout.
FSI_RUN="$FSI_SOURCE_DIR/tests/system/fsi_run_for_tests.sh"
rm -rf "$FSI_TEST_TMP"
mkdir -p "$FSI_TEST_TMP"
cd "$FSI_TEST_TMP"

fail() { echo "FAIL: $*" >&2; exit 1; }
pass() { echo "ok: $*"; }

# A small deterministic case of the example participants (about 1 s to run):
#   small_case FILE [end_time]
small_case() {
  cat >"$1" <<CASE
[run]
title = system test
end_time = ${2:-0.3}
max_window = 1e-3
output_interval = 0.05
probe_interval = 0.01

[solid]
solver = spring_oscillators
particles = 50
time_step = 1e-4

[fluid]
solver = linear_dashpot
damping = 2.0
CASE
}

# Bit-identical results of two output folders (every dataset, every probe value). A
# participant missing from both (a fluid-only or solid-only run) is skipped.
same_results() {
  local a="$1" b="$2"
  for f in solid.h5 fluid.h5; do
    [ -e "$a/$f" ] || [ -e "$b/$f" ] || continue
    h5diff -q "$a/$f" "$b/$f" || fail "$f differs between $a and $b"
  done
  cmp -s "$a/probes.csv" "$b/probes.csv" || fail "probes.csv differs between $a and $b"
}

# Value of "name = value" from a participant's block of run.log.
log_stat() {
  local log="$1" participant="$2" name="$3"
  awk -v p="[participant $participant]" -v n="$name" '
    $0 == p {inside = 1; next} /^\[/ {inside = 0}
    inside && $1 == n {print $3; exit}' "$log"
}
