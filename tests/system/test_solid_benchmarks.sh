#!/usr/bin/env bash
# The NOSB-PD solid (and TLSPH on S2) against the analytical references of
# docs/validation.md, at the coarsest resolutions of bench/solid_validation.sh (which
# runs the full tables):
#   S1 cantilever at dx = 0.02 m: tip deflection within 2 % of Timoshenko's value at
#      the loaded column (the issue's bound at dx = 0.01; measured +0.83 % at 0.02, and
#      the error shrinks with dx, docs/validation.md);
#   S2 clamped plate at T/dx = 10 over 0.6 s (two periods and a bit): period within 2 %
#      and amplitude within 3 % of thin-plate theory, the issue's bounds for T/dx = 20,
#      met already at the coarsest lattice (measured +0.84 % and -0.54 %; thin-plate
#      theory itself is about 0.6 % short on the period of a plate with L/T = 10, from
#      shear and rotary inertia), and total energy conserved within 1 % without damping
#      (the issue's bound; measured 1e-4 %).
# About 70 s.
source "$(dirname "$0")/lib.sh"
PY=/usr/bin/python3

dx=0.02
"$FSI_RUN" "$FSI_SOURCE_DIR/cases/s1_cantilever.ini" --out s1 --threads 1 \
  --set solid.spacing=$dx --set "solid.block clamp.min=-0.06,0" --set "solid.region fixed.min=-0.06,0" \
  --set "solid.region tip_load.min=0.98,0" --set "solid.probe tip.point=0.99,0.09" >s1.txt 2>&1 ||
  { cat s1.txt; fail "S1 run failed"; }
"$PY" - s1 <<'PY' || fail "S1 tip deflection"
import csv, sys
uy = float(list(csv.DictReader(l for l in open(sys.argv[1] + "/probes.csv") if not l.startswith("#")))[-1]["tip_uy"])
a, F, E, nu, H = 0.99, 85000.0, 22e9, 0.3, 0.2
ref = F * a**3 / (3 * E * H**3 / 12) + F * a / (5 / 6 * E / (2 * (1 + nu)) * H)
err = -uy / ref - 1
print("S1 dx = 0.02: tip uy %.5e m, Timoshenko %.5e m, error %+.2f %%" % (uy, ref, 100 * err))
sys.exit(0 if abs(err) < 0.02 else 1)
PY
pass "S1 tip deflection within 2 % of Timoshenko at dx = 0.02 m"

# check_s2 NAME PERIOD_BOUND AMPLITUDE_BOUND [--set ...]: S2 at T/dx = 10 over 0.6 s,
# period and amplitude within the bounds (fractions) of thin-plate theory, energy within
# 1 %; prints the period into NAME/period.txt.
check_s2() {
  local name="$1" period_bound="$2" amplitude_bound="$3"
  shift 3
  local dx=0.002
  "$FSI_RUN" "$FSI_SOURCE_DIR/cases/s2_plate_oscillation.ini" --out "$name" --threads 1 \
    --set solid.spacing=$dx --set "solid.block clamp.min=-0.006,-0.01" \
    --set "solid.region fixed.min=-0.006,-0.01" --set "solid.probe tip.point=0.199,0.001" \
    --set run.end_time=0.6 "$@" >"$name.txt" 2>&1 || { cat "$name.txt"; fail "S2 $name run failed"; }
  "$PY" - "$name" "$FSI_SOURCE_DIR/bench" "$period_bound" "$amplitude_bound" <<'PY' ||
import re, sys
sys.path.insert(0, sys.argv[2])
import fsi_results, oscillation
probes = fsi_results.read_probes(sys.argv[1])
period, amplitude, cycles = oscillation.period_amplitude(probes["time"], probes["tip_uy"])
ref_t, ref_a = 72.39 * 0.2 / (3.25e6 / 1000) ** 0.5, 0.115 * 0.2
log = open(sys.argv[1] + "/solid.log").read()
k, s, e0 = (float(v) for v in re.search(
    r"energy at the end: kinetic (\S+) J, strain (\S+) J; initial (\S+) J", log).groups())
drift = (k + s - e0) / e0
print("S2 %s T/dx = 10: period %.7f s (%+.2f %%), amplitude %.5f m (%+.2f %%), %d cycle(s), "
      "energy drift %+.4f %%" % (sys.argv[1], period, 100 * (period / ref_t - 1), amplitude,
                                 100 * (amplitude / ref_a - 1), cycles, 100 * drift))
open(sys.argv[1] + "/period.txt", "w").write("%.10g\n" % period)
# The diagnostics (docs/output.md): kinetic + strain energy in every window within 1 % of
# the initial (no damping, no loads: the same bound as the end's), the last row the
# energies the log gives (its 6 digits).
import csv
rows = list(csv.DictReader(l for l in open(sys.argv[1] + "/solid_diagnostics.csv") if not l.startswith("#")))
energy = [float(r["kinetic_energy"]) + float(r["strain_energy"]) for r in rows]
worst = max(abs(v / e0 - 1) for v in energy)
print("S2 %s diagnostics: %d rows, kinetic + strain within %.4f %% of the initial in every "
      "window" % (sys.argv[1], len(rows), 100 * worst))
ok = cycles >= 1 and abs(period / ref_t - 1) < float(sys.argv[3]) \
    and abs(amplitude / ref_a - 1) < float(sys.argv[4]) and abs(drift) < 0.01 \
    and worst < 0.01 and abs(energy[-1] / (k + s) - 1) < 1e-5
sys.exit(0 if ok else 1)
PY
    fail "S2 $name: period, amplitude or energy"
  pass "S2 $name: period within $period_bound, amplitude within $amplitude_bound, energy within 1 % at T/dx = 10"
}

check_s2 s2 0.02 0.03

# TLSPH (docs/tlsph.md) on the same S2: the same bounds with its default quadratic fit
# (measured +1.37 % and -0.12 %), with velocity Verlet and with RK4, whose period must
# agree with Verlet's to 1e-5 (measured 4e-6: the time error is far below the
# lattice's); 003's own first-order correction within 003 Table 3's bars at T/dx = 10,
# 5.68 % and 6.96 % (measured +4.35 % and +2.80 %).
check_s2 s2_tlsph 0.02 0.03 --set solid.solver=tlsph
check_s2 s2_tlsph_rk4 0.02 0.03 --set solid.solver=tlsph --set solid.integrator=rk4
"$PY" -c "import sys; a, b = (float(open(f + '/period.txt').read()) for f in sys.argv[1:]); \
print('S2 TLSPH period: Verlet %.9g s, RK4 %.9g s' % (a, b)); sys.exit(0 if abs(a / b - 1) < 1e-5 else 1)" \
  s2_tlsph s2_tlsph_rk4 || fail "S2 TLSPH: RK4's period differs from Verlet's by more than 1e-5"
pass "S2 TLSPH: RK4 and Verlet periods agree to 1e-5"
check_s2 s2_tlsph_order1 0.0568 0.0696 --set solid.solver=tlsph --set solid.tlsph.gradient_order=1
