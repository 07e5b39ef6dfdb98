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

# expect_bad_case NAME PATTERN [fsi run options...]: runs bad.ini (in the current
# folder) with the options; asserts exit 2, a message matching PATTERN (grep -E) and no
# output folder out_NAME.
expect_bad_case() {
  local name="$1" pattern="$2"
  shift 2
  set +e
  "$FSI_RUN" bad.ini --out "out_$name" "$@" >"$name.txt" 2>&1
  local status=$?
  set -e
  [ "$status" -eq 2 ] || { cat "$name.txt"; fail "$name: exit status $status, expected 2"; }
  grep -qE -- "$pattern" "$name.txt" || { cat "$name.txt"; fail "$name: message does not match '$pattern'"; }
  [ ! -e "out_$name" ] || fail "$name: output folder was created"
  pass "$name: $(head -n 1 "$name.txt")"
}

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
# h5_same A B NAME: status 0 when A/NAME.h5 and B/NAME.h5 hold the same data. The
# data is in the files of NAME.frames that NAME.h5 links to (docs/output.md): h5diff
# of NAME.h5 alone compares only the links (with --follow-symlinks only the first
# frame), so every file is compared.
h5_same() {
  local a="$1" b="$2" name="$3" f
  h5diff -q "$a/$name.h5" "$b/$name.h5" >/dev/null 2>&1 || return 1
  [ "$(cd "$a/$name.frames" && ls)" = "$(cd "$b/$name.frames" && ls)" ] || return 1
  for f in "$a/$name.frames"/*.h5; do
    h5diff -q "$f" "$b/$name.frames/${f##*/}" >/dev/null 2>&1 || return 1
  done
}

# output_readable DIR NAME...: DIR/NAME.h5 and DIR/NAME.xmf are complete and every
# frame they list reads back (tests/system/output_files_check.py). h5dump -H alone is
# not enough: it exits 0 even when a frame file a link names is broken.
output_readable() {
  local dir="$1"
  shift
  /usr/bin/python3 "$FSI_SOURCE_DIR/tests/system/output_files_check.py" "$dir" "$@" >/dev/null
}

same_results() {
  local a="$1" b="$2"
  for f in solid fluid; do
    [ -e "$a/$f.h5" ] || [ -e "$b/$f.h5" ] || continue
    h5_same "$a" "$b" "$f" || fail "$f.h5 (or a file of $f.frames) differs between $a and $b"
    [ -e "$a/${f}_diagnostics.csv" ] || [ -e "$b/${f}_diagnostics.csv" ] || continue
    cmp -s "$a/${f}_diagnostics.csv" "$b/${f}_diagnostics.csv" ||
      fail "${f}_diagnostics.csv differs between $a and $b"
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

# Pids of the processes `fsi run` started for the output folder DIR (coupler,
# participants, recorder), found by the FSI_OUT of their environment: processes of
# other runs on the machine are never matched.
run_pids() {
  local dir
  dir="$(cd "$1" && pwd -P)"
  grep -lsxzF "FSI_OUT=$dir" /proc/[0-9]*/environ 2>/dev/null | cut -d/ -f3 || true
}

# Waits until the run writing DIR is under way (a few probe rows); fails otherwise.
wait_under_way() {
  local dir="$1" rows=0
  for _ in $(seq 150); do
    rows=$( { wc -l <"$dir/probes.csv"; } 2>/dev/null || echo 0)
    [ "$rows" -gt 3 ] && return 0
    sleep 0.1
  done
  fail "the run into $dir did not get under way"
}
