#!/usr/bin/env bash
# ParaView (pvbatch: Xdmf3ReaderS via OpenDataFile, Xdmf3ReaderT and the legacy
# XDMF reader) opens a coupled run's output: both participants' frames fall on the
# same times (the coupler sets them), with the right particle counts, one vertex
# cell per particle (cells == points, else nothing shows), fields and initial
# positions. Then the combined file run/run.xmf (paraview_check_run.py): the three
# readers give both participants as two blocks (or pieces) with their arrays, for the
# example participants and for a short C1 run of the real solvers, whose frames hold
# what ParaView's SPH interpolators take: mass, density and the smoothing length (field
# data); the SPH interpolator on the fluid block gives a Shepard sum of 1 within 5 %
# and the particles' density.
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
pvbatch "$FSI_SOURCE_DIR/tests/system/paraview_check_run.py" run/run.xmf --times "$times" \
  --block fluid=force,pressure --block solid=velocity,acceleration,load,id >combined.txt 2>&1 ||
  { cat combined.txt; fail "ParaView does not open run/run.xmf with both participants"; }

"$FSI_RUN" "$FSI_SOURCE_DIR/cases/c1_elastic_plate.ini" --out c1 --set run.end_time=0.004 \
  --set run.output_interval=0.002 >c1.txt 2>&1 || { cat c1.txt; fail "the C1 run failed"; }
pvbatch "$FSI_SOURCE_DIR/tests/system/paraview_check_run.py" c1/run.xmf --times 0,0.002,0.004 \
  --block fluid=velocity,pressure,density,mass,flags \
  --block solid=displacement,velocity,stress,density,mass --constant smoothing_length \
  --sph fluid >c1_check.txt 2>&1 ||
  { cat c1_check.txt; fail "ParaView does not open C1's run.xmf with what the SPH filters take"; }
sph=$(grep -m1 -o "Shepard sum [0-9.]*" c1_check.txt)
pass "ParaView (3 readers) reads both participants' series: 7 frames at the same times, 50 particles and 50 cells, all fields; run.xmf opens fluid and solid together (examples, and C1 with mass, density, smoothing_length; SPH interpolator: $sph)"
