#!/usr/bin/env bash
# ParaView (pvbatch: Xdmf3ReaderS via OpenDataFile, Xdmf3ReaderT and the legacy
# XDMF reader) opens a coupled run's output: both participants' frames fall on the
# same times (the coupler sets them), with the right particle counts, one vertex
# cell per particle (cells == points, else nothing shows), fields and initial
# positions.
source "$(dirname "$0")/lib.sh"
command -v pvbatch >/dev/null || fail "pvbatch not found; run launch/setup.sh"
small_case case.ini 0.3

"$FSI_RUN" case.ini --out run >run.txt 2>&1 || { cat run.txt; fail "run failed"; }
check="$FSI_SOURCE_DIR/tests/system/paraview_check_xdmf.py"
times=0,0.05,0.1,0.15,0.2,0.25,0.3
# 50 particles spaced 0.01 m along x, all starting 0.01 m up (the example's defaults).
pvbatch "$check" run/solid.xmf --dim 2 --times "$times" --counts 50,50,50,50,50,50,50 \
  --fields velocity:vector,acceleration:vector,load:vector,id:scalar \
  --point 0:0=0,0.01 --point 0:49=0.49,0.01 --value 0:id:49:0=49 --value 0:velocity:10:1=0 \
  || fail "ParaView does not read the solid's output as written"
pvbatch "$check" run/fluid.xmf --dim 2 --times "$times" --counts 50,50,50,50,50,50,50 \
  --fields force:vector,pressure:scalar --point 0:0=0,0.01 --value 0:force:0:1=0 \
  || fail "ParaView does not read the fluid's output as written"
pass "ParaView (3 readers) reads both participants' series: 7 frames at the same times, 50 particles and 50 cells, all fields"
