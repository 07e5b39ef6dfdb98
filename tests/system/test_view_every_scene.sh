#!/usr/bin/env bash
# fsi view and fsi plot on every scene's output: each case of cases/ runs for 2e-4 s
# (one or a few windows, frames at 0 and at the end), then `fsi view OUT` must write a
# PNG in which particles were drawn and coloured (tests/system/view_check.py) and
# `fsi plot OUT` a non-empty diagnostics.png with at least 2 % of its pixels drawn
# (its six panels' lines; an empty figure draws about 1 %). The coupled demo of the
# example participants writes no diagnostics (external programs need not): fsi plot
# must then say so and exit 2. S4's glass steps 1e-8 s, so it runs 2e-6 s. About
# 1-2 minutes.
source "$(dirname "$0")/lib.sh"
PY=/usr/bin/python3
T=2e-4
n=0
for case in "$FSI_SOURCE_DIR"/cases/*.ini; do
  name=$(basename "$case" .ini)
  t=$T; [ "$name" = s4_notched_plate ] && t=2e-6
  "$FSI_RUN" "$case" --out "$name" --threads 1 --set run.end_time=$t \
    --set run.output_interval=$t >"$name.txt" 2>&1 || { tail -5 "$name.txt"; fail "$name: run failed"; }
  "$FSI_SOURCE_DIR/fsi" view "$name" >"$name.view.txt" 2>&1 ||
    { cat "$name.view.txt"; fail "$name: fsi view failed"; }
  "$PY" "$FSI_SOURCE_DIR/tests/system/view_check.py" "$name/view.png" >"$name.check.txt" ||
    { cat "$name.check.txt"; fail "$name: fsi view drew no particles"; }
  if ls "$name"/*_diagnostics.csv >/dev/null 2>&1; then
    "$FSI_SOURCE_DIR/fsi" plot "$name" >"$name.plot.txt" 2>&1 ||
      { cat "$name.plot.txt"; fail "$name: fsi plot failed"; }
    "$PY" - "$name/diagnostics.png" <<'PY' || fail "$name: fsi plot drew nothing"
import sys
import numpy as np
from PIL import Image
im = np.asarray(Image.open(sys.argv[1]).convert("RGB")).astype(int)
drawn = float((im.min(axis=2) < 235).mean())
print("%s: %.1f %% of the pixels drawn" % (sys.argv[1], 100 * drawn))
sys.exit(0 if drawn > 0.02 else 1)
PY
  else
    status=0
    "$FSI_SOURCE_DIR/fsi" plot "$name" >"$name.plot.txt" 2>&1 || status=$?
    [ "$status" = 2 ] || { cat "$name.plot.txt"; fail "$name: no diagnostics, fsi plot exited $status (expected 2)"; }
  fi
  n=$((n + 1))
done
[ "$n" -ge 17 ] || fail "only $n cases found"
pass "fsi view and fsi plot on all $n scenes"
