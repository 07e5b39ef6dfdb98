#!/usr/bin/env bash
# A full disk stops the run: exit 1, a message naming the file and the system's
# reason, and everything written before stays readable (solid.h5/fluid.h5 with every
# frame they list, the .xmf sidecars, probes.csv ending at a complete row, no
# "exit = ok" in run.log). The disk is a 2 MB tmpfs in a private user and mount
# namespace (unshare -rm, no root needed); the run frames every window so it fills up
# in well under a second.
source "$(dirname "$0")/lib.sh"
command -v unshare >/dev/null || fail "unshare (util-linux) not found"
check="$FSI_SOURCE_DIR/tests/system/output_files_check.py"
small_case case.ini 5
sed -i 's/^output_interval = .*/output_interval = 1e-3/; s/^probe_interval = .*/probe_interval = 1e-3/' case.ini
mkdir disk
# The tmpfs lives only inside the namespace: the result is copied out before it ends.
unshare -rm sh -c 'mount -t tmpfs -o size=2m tmpfs disk || exit 99
  "$0" case.ini --out disk/run >run.txt 2>&1; echo $? >status; cp -r disk/run copy' "$FSI_RUN"
status=$(cat status)
[ "$status" != 99 ] || fail "cannot mount a tmpfs in a user namespace here"
[ "$status" = 1 ] || { cat run.txt; fail "full disk: fsi run exited $status, expected 1"; }
grep -q "cannot write $FSI_TEST_TMP/disk/run/[^ ]*: No space left on device" run.txt ||
  grep -q "cannot write $FSI_TEST_TMP/disk/run/[^ ]* (.*): No space left on device" run.txt ||
  { cat run.txt; fail "the message does not name the file and 'No space left on device'"; }
! grep -q "^exit = ok" copy/run.log || fail "run.log says exit = ok"
/usr/bin/python3 "$check" copy solid fluid >frames.txt ||
  fail "the output written before the disk filled up is not readable"
while read -r name h5 xmf; do
  [ "$h5" -ge 10 ] && [ "$xmf" -ge 10 ] || fail "$name: only $h5 frames in $name.h5, $xmf in $name.xmf"
done <frames.txt
h5dump -H copy/solid.h5 >/dev/null && h5dump -H copy/fluid.h5 >/dev/null ||
  fail "h5dump cannot read solid.h5 or fluid.h5"
[ -z "$(tail -c 1 copy/probes.csv)" ] || fail "probes.csv does not end with a complete row"
columns=$(head -1 copy/probes.csv | tr ',' '\n' | wc -l)
awk -F, -v n="$columns" 'NF != n {bad = 1} END {exit bad}' copy/probes.csv ||
  fail "probes.csv has a row with a field count other than the header's $columns"
pass "full disk: exit 1 naming the file ($(grep -o "cannot write $FSI_TEST_TMP[^ :]*" run.txt | head -1)), $(tr '\n' ' ' <frames.txt)frames readable, probes.csv $(($(wc -l <copy/probes.csv) - 1)) complete rows"
