#!/usr/bin/env bash
# The WCSPH fluid (fluid_solver/wcsph, docs/wcsph.md), about 20 s in all:
#   - F0 hydrostatic tank (cases/f0_hydrostatic_tank.ini with solver = wcsph) at
#     dx = 0.05 m (20 x 10 fluid particles, walls four layers), to t = 2 s, with each
#     density diffusion form: the three bottom probes within 1 % of rho0 g H = 4905 Pa
#     (measured +0.65 % molteni, +0.62 % antuono; +1.08 % with h = 1.7 dx), the largest
#     fluid speed below 1 % of sqrt(g H) (measured 0.009 and 0.006 m/s, bound 0.022),
#     every fluid particle in the tank in every frame, nothing non-finite;
#   - C1 (dam break on an elastic plate, NOSB-PD) to 5 ms with --set fluid.solver=wcsph:
#     the swap by one override runs, no fluid particle inside the solid;
#   - C4 (a 2 m column on an aluminium plate, NOSB-PD) at dx = 0.025 m (solid 0.0125 m)
#     to 0.02 s with the default solid_coupling = dummy: no fluid inside the solid; the
#     impulse the fluid sent equals the one the solid received (1e-7); the plate carries
#     the column: the impulse is at least 85 % of M g t (measured 92 %; with
#     solid_coupling = contact the water falls through its first spacing: 28 %), and the
#     fluid's momentum budget closes (impulse on the plate plus the fluid's momentum
#     within 3 % of M g t: the tank's side walls take the rest; measured 98.5 %).
source "$(dirname "$0")/lib.sh"
PY=/usr/bin/python3

for form in molteni antuono; do
  "$FSI_RUN" "$FSI_SOURCE_DIR/cases/f0_hydrostatic_tank.ini" --out "f0_$form" --threads 1 \
    --set fluid.solver=wcsph --set fluid.wcsph.density_diffusion_form=$form \
    --set fluid.spacing=0.05 --set "fluid.wall bottom.min=-0.2,-0.2" \
    --set "fluid.wall bottom.max=1.2,0" --set "fluid.wall left.min=-0.2,0" \
    --set "fluid.wall right.max=1.2,0.6" >"f0_$form.txt" 2>&1 \
    || { cat "f0_$form.txt"; fail "F0 with WCSPH ($form) failed"; }
  "$PY" "$FSI_SOURCE_DIR/tests/system/f0_check.py" "f0_$form" || fail "F0 with WCSPH ($form)"
  pass "F0 with WCSPH ($form): bottom pressure within 1 %, at rest, in the tank"
done

"$FSI_RUN" "$FSI_SOURCE_DIR/cases/c1_elastic_plate.ini" --out c1 --threads 1 \
  --set fluid.solver=wcsph --set run.end_time=0.005 >c1.txt 2>&1 \
  || { cat c1.txt; fail "C1 with WCSPH failed"; }
grep -q "fluid particles inside the solid (closer than half the solid's spacing to a solid particle): at most 0 at once, in 0 windows" \
  c1/fluid.log || { grep interface c1/fluid.log; fail "C1: fluid particles entered the solid"; }
pass "C1 with --set fluid.solver=wcsph: runs, no fluid inside the solid"

"$FSI_RUN" "$FSI_SOURCE_DIR/cases/c4_plate_under_water.ini" --out c4 --threads 1 \
  --set fluid.solver=wcsph --set fluid.spacing=0.025 --set solid.spacing=0.0125 \
  --set "fluid.wall left.min=-0.1,-0.05" --set "fluid.wall right.max=1.1,2.1" \
  --set run.end_time=0.02 >c4.txt 2>&1 || { cat c4.txt; fail "C4 with WCSPH failed"; }
grep -q "fluid particles inside the solid (closer than half the solid's spacing to a solid particle): at most 0 at once, in 0 windows" \
  c4/fluid.log || { grep interface c4/fluid.log; fail "C4: fluid particles entered the solid"; }
"$PY" - c4 <<'PY' || fail "C4 with WCSPH: loads"
import re, sys
out = sys.argv[1]
fluid, solid = open(out + "/fluid.log").read(), open(out + "/solid.log").read()
vec = lambda text: [float(x) for x in text.split(",")]
sent = re.search(r"loads sent to the solid: impulse \(([^)]*)\) N s.*fluid momentum "
                 r"\(([^)]*)\) N s at the start, \(([^)]*)\) N s at the end", fluid)
got = re.search(r"loads received from the fluid: impulse \(([^)]*)\) N s", solid)
mass = float(re.search(r"fluid mass (\S+),", fluid).group(1))
t_end = float(re.search(r"\nsimulated_time = (\S+) s", open(out + "/run.log").read()).group(1))
j_sent, p0, p1, j_got = vec(sent.group(1)), vec(sent.group(2)), vec(sent.group(3)), vec(got.group(1))
weight_impulse = mass * 9.81 * t_end
carried = -j_sent[1] / weight_impulse
budget = (-j_sent[1] - (p1[1] - p0[1])) / weight_impulse
print("impulse sent %.9g N s, received %.9g N s; M g t = %.6g N s: the plate carries %.1f %%, "
      "plate + fluid momentum %.1f %%" % (j_sent[1], j_got[1], weight_impulse, 100 * carried, 100 * budget))
ok = abs(j_got[1] - j_sent[1]) <= 1e-7 * abs(j_sent[1]) and carried > 0.85 and abs(budget - 1) < 0.03
sys.exit(0 if ok else 1)
PY
pass "C4 with WCSPH (dummy solid): no fluid inside, loads sent = received, the plate carries the column"
