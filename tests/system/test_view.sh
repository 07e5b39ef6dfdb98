#!/usr/bin/env bash
# fsi view (launch/view.py, docs/output.md "fsi view") on a coupled run (C1 to 0.04 s),
# a fluid-only one (F0 to 0.2 s) and a solid-only one (S3 to 0.005 s, coarse): each writes a
# non-empty PNG in which particles were drawn and coloured (tests/system/view_check.py
# counts the pixels inside the axes boxes the PNG records; a copy with the boxes
# blanked must fail the same check), every field a run has renders, a field no
# participant has and an unknown field exit 2, --time picks the nearest frame and draws
# one panel per time, --frames writes one PNG per frame, --movie a GIF with every frame,
# and a folder without output exits 2 with a message. About 30 s on a quiet machine
# (two dozen renders of about 1 s each, mostly matplotlib's start).
source "$(dirname "$0")/lib.sh"
PY=/usr/bin/python3
VIEW=("$FSI_SOURCE_DIR/fsi" view)
CHECK=("$PY" "$FSI_SOURCE_DIR/tests/system/view_check.py")

run_case() {
  local out="$1" case="$2"; shift 2
  "$FSI_RUN" "$FSI_SOURCE_DIR/cases/$case.ini" --out "$out" "$@" >"$out.txt" 2>&1 ||
    { cat "$out.txt"; fail "run of $case failed"; }
}
run_case c1 c1_elastic_plate --set run.end_time=0.04
run_case f0 f0_hydrostatic_tank --set run.end_time=0.2
# S3 at a spacing of 0.125 m (8 points across, the clamp 3 long): 664 points, 2 s.
run_case s3 s3_steel_beam --set run.end_time=0.005 --set solid.spacing=0.125 \
  --set "solid.block clamp.min=-0.375,-0.5" --set "solid.region fixed.min=-0.375,-0.5"

# view OUT ARGS... -- CHECK-ARGS...: fsi view writes a non-empty PNG that passes the
# pixel check (the PNG is the one named by --out, else OUT/view.png).
view() {
  local out="$1" png="$1/view.png" args=() a
  shift
  while [ $# -gt 0 ] && [ "$1" != "--" ]; do
    args+=("$1"); [ "$1" = "--out" ] && png="$2"; shift
  done
  shift
  rm -f "$png"
  "${VIEW[@]}" "$out" ${args[@]+"${args[@]}"} >view.txt 2>&1 ||
    { cat view.txt; fail "fsi view $out ${args[*]} failed"; }
  [ -s "$png" ] || fail "fsi view $out ${args[*]} wrote no PNG ($png)"
  "${CHECK[@]}" "$png" "$@" >check.txt || { cat check.txt; fail "fsi view $out ${args[*]}: pixel check"; }
}

# Default fields: the fluid by pressure, the solid by displacement, both coloured.
view c1 -- --drawn 0.1 --coloured 0.05 --time "t = 0.04 s"
"${CHECK[@]}" c1/view.png --blank blank.png >/dev/null
if "${CHECK[@]}" blank.png >/dev/null 2>&1; then fail "the pixel check passes an image without particles"; fi
view f0 -- --drawn 0.2 --coloured 0.1
view s3 -- --drawn 0.05 --coloured 0.05
pass "fsi view on a coupled, a fluid-only and a solid-only run: particles drawn and coloured"

# Every field of each run; a participant without it is drawn grey (C1's fluid for the
# solid's fields: still drawn, less of it coloured).
for f in pressure velocity displacement stress damage; do
  view c1 --field "$f" --out "c1_$f.png" -- --drawn 0.1 --coloured 0.001
done
# A component of both signs takes a diverging map, grey near 0: drawn is what counts.
view c1 --field stress_xy --out c1_stress_xy.png -- --drawn 0.1
view f0 --field velocity --out f0_velocity.png -- --drawn 0.2 --coloured 0.1
for f in stress damage velocity; do view s3 --field "$f" --out "s3_$f.png" -- --drawn 0.05 --coloured 0.05; done
pass "every field of each run renders (F0's pressure and S3's displacement: the defaults above)"

# Bad input: exit 2, a message, no PNG.
expect_2() {
  local what="$1" pattern="$2"; shift 2
  set +e
  "${VIEW[@]}" "$@" --out bad.png >bad.txt 2>&1
  local rc=$?
  set -e
  [ "$rc" = 2 ] || { cat bad.txt; fail "$what: exit $rc, expected 2"; }
  grep -q "$pattern" bad.txt || { cat bad.txt; fail "$what: no message matching '$pattern'"; }
  [ ! -e bad.png ] || fail "$what: a PNG was written"
}
expect_2 "unknown field" "unknown field 'vorticity'" c1 --field vorticity
expect_2 "a field no participant has" "no participant has the field 'damage'" f0 --field damage
expect_2 "fluid field of a solid-only run" "no participant has the field 'pressure'" s3 --field pressure
mkdir -p empty
expect_2 "a folder without output" "no particle output" empty
expect_2 "a missing folder" "not a folder" missing
expect_2 "a bad time" "expected a time" c1 --time soon
pass "bad field, folder or time: exit 2 with a message"

# --time: the nearest frame; a list gives one panel per time.
view c1 --time 0.021 --out near.png -- --time "t = 0.02 s" --panels 1
view c1 --time 0,0.02,0.04 --out panels.png -- --panels 3 --drawn 0.05
pass "--time picks the nearest frame and draws one panel per time"

# --frames: one PNG per frame; --movie: those and a GIF with every frame.
for out in c1; do
  n=$(ls "$out"/solid.frames/[0-9]*.h5 | wc -l)
  "${VIEW[@]}" "$out" --frames --out "${out}_frames" >/dev/null || fail "fsi view $out --frames"
  m=$(ls "${out}_frames"/frame_*.png | wc -l)
  [ "$m" = "$n" ] || fail "fsi view $out --frames wrote $m PNGs for $n frames"
  "${CHECK[@]}" "${out}_frames/frame_$(printf %06d $((n - 1))).png" >/dev/null ||
    fail "fsi view $out --frames: the last frame has no particles"
done
n=$(ls f0/fluid.frames/[0-9]*.h5 | wc -l)
"${VIEW[@]}" f0 --movie --out f0.gif >/dev/null || fail "fsi view f0 --movie"
[ "$(ls f0_frames/frame_*.png | wc -l)" = "$n" ] || fail "--movie: not one PNG per frame"
frames=$("$PY" -c "from PIL import Image; print(Image.open('f0.gif').n_frames)")
[ "$frames" = "$n" ] || fail "--movie: the GIF has $frames frames, the run $n"
pass "--frames writes one PNG per frame ($n for F0), --movie a GIF of them"
