#!/usr/bin/env bash
# fsi-run as the system tests call it ($FSI_RUN, lib.sh): the same command with
# [run] window_timeout = FSI_TEST_WINDOW_TIMEOUT (20 s) set before the test's own
# options, so a deadlocked run stops within seconds with the coupler's "stuck or
# deadlocked" message instead of hanging until ctest's 600 s timeout (the key's
# default is 600 s). A test that sets window_timeout itself with --set still wins:
# later overrides replace earlier ones. The windows of the test cases take
# milliseconds; 20 s leaves room for a machine running many more processes than cores.
set -euo pipefail
: "${FSI_BIN_DIR:?}"
[ $# -ge 1 ] || exec "$FSI_BIN_DIR/fsi-run"
case_file="$1"
shift
exec "$FSI_BIN_DIR/fsi-run" "$case_file" --set "run.window_timeout=${FSI_TEST_WINDOW_TIMEOUT:-20}" "$@"
