#!/usr/bin/env bash
# Users open the output while a run writes it (ParaView, h5py, h5dump): that must never
# break the run nor lose a frame, and every read must see complete, consistent files.
# Readers loop over solid.h5/fluid.h5 (h5dump -H, and h5py + the .xmf sidecars through
# output_files_check.py) while the example participants write a frame every window;
# the run must exit 0 with every frame listed, and no read may fail.
source "$(dirname "$0")/lib.sh"
check="$FSI_SOURCE_DIR/tests/system/output_files_check.py"
small_case case.ini 0.2
sed -i 's/^output_interval = .*/output_interval = 1e-3/' case.ini
frames=201   # t = 0, 1e-3, ..., 0.2

reader() {   # reader KIND: reads until the file 'stop' appears; one line per read
  local kind="$1"
  while [ ! -e stop ]; do
    if [ ! -e run/solid.h5 ] || [ ! -e run/fluid.h5 ]; then sleep 0.01; continue; fi
    if [ "$kind" = h5dump ]; then
      if h5dump -H run/solid.h5 >/dev/null 2>&1 && h5dump -H run/fluid.h5 >/dev/null 2>&1
      then echo ok; else echo "h5dump failed"; fi
    else
      /usr/bin/python3 "$check" run solid fluid >/dev/null 2>"py.err" && echo ok ||
        { echo "h5py: $(cat py.err)"; }
    fi
  done
}
reader h5dump >reads_h5dump.txt &
dump_pid=$!
reader h5py >reads_h5py.txt &
py_pid=$!
set +e
"$FSI_RUN" case.ini --out run >run.txt 2>&1
status=$?
set -e
touch stop
wait "$dump_pid" "$py_pid"
[ "$status" = 0 ] || { cat run.txt; fail "the run exited $status while being read"; }
/usr/bin/python3 "$check" run solid fluid >final.txt || fail "the final output is not readable"
grep -qx "solid $frames $frames" final.txt && grep -qx "fluid $frames $frames" final.txt ||
  fail "frames lost while being read: $(tr '\n' ' ' <final.txt)(expected $frames each)"
bad=$(cat reads_h5dump.txt reads_h5py.txt | grep -vc '^ok$' || true)
[ "$bad" = 0 ] || { grep -v '^ok$' reads_*.txt | head -5; fail "$bad reads saw broken files"; }
n_dump=$(wc -l <reads_h5dump.txt)
n_py=$(wc -l <reads_h5py.txt)
[ "$n_dump" -ge 5 ] && [ "$n_py" -ge 2 ] ||
  fail "only $n_dump h5dump and $n_py h5py reads during the run: nothing tested"
pass "run read $n_dump times by h5dump and $n_py times by h5py: exit 0, all $frames frames of both, every read consistent"
