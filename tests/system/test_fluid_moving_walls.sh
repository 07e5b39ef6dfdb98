#!/usr/bin/env bash
# Walls with a prescribed motion in a real run: cases/f2_sloshing.ini, coarse
# (dx = 0.05 m, walls four layers thick, the tank 1.75 m long) and 1 s long. In every output frame each wall particle is at
# x0 + X(t) with velocity X'(t) (fluid_solver/fluid_motion.h), no fluid particle is
# outside the moving tank, and the free-surface probe FS1 has moved (the water
# sloshes). About 10 s.
source "$(dirname "$0")/lib.sh"
CASE="$FSI_SOURCE_DIR/cases/f2_sloshing.ini"
"$FSI_RUN" "$CASE" --out moving --threads 1 --set fluid.spacing=0.05 \
  --set "fluid.block water.max=1.75,0.5" --set "fluid.wall bottom.min=-0.2,-0.2" \
  --set "fluid.wall bottom.max=1.95,0" --set "fluid.wall left.min=-0.2,0" \
  --set "fluid.wall right.min=1.75,0" --set "fluid.wall right.max=1.95,1.15" \
  --set run.end_time=1 \
  --set run.output_interval=0.05 >run.txt 2>&1 || { cat run.txt; fail "moving-wall run failed"; }
pass "moving-wall run finished"
/usr/bin/python3 "$FSI_SOURCE_DIR/tests/system/fluid_wall_motion_check.py" moving \
  0.032 1.875 90 0 1.75 || fail "wall particles not at x0 + X(t), or water outside the tank"
pass "wall particles follow X(t), X'(t); water inside the tank"
/usr/bin/python3 - <<'PY' || fail "FS1 elevation did not move"
import csv
rows = list(csv.DictReader(l for l in open("moving/probes.csv") if not l.startswith("#")))
eta = [float(r["FS1_eta"]) for r in rows]
print(f"FS1: {len(eta)} values, range {min(eta):.4f} .. {max(eta):.4f} m")
assert min(eta) < -0.005 and max(eta) < 0.2
PY
pass "FS1 elevation recorded"
