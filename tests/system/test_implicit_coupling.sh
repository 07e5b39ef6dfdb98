#!/usr/bin/env bash
# Implicit coupling ([run] scheme = implicit, docs/coupling.md "Implicit coupling").
# The scene is test_solver_combinations': C1 (cases/c1_elastic_plate.ini) with the water
# moved against the plate, so it is loaded from the first window, 0.002 s, in windows of
# at most 2e-4 s (ISPH's own step would give windows of 1e-3 s, with which the explicit
# first iteration of ISPH + NOSB-PD is unstable: test_solver_combinations).
#   (a) Every fluid x solid combination the registry lists (`fsi solvers`) saves and
#       restores its whole state: with the test switch FSI_TEST_REPEAT_MOTION=1 every
#       iteration of a window gives the fluid the first iteration's motion, so a
#       complete restore makes every repeated iteration compute exactly what the first
#       did. Asserted: in coupling.csv every repeated iteration's force residual is
#       exactly 0 and its displacement residual equals the first iteration's to the
#       last digit; and three iterations per window (coupling_min_iterations = 3) write
#       the same frames and probes, bit for bit, as one (coupling_max_iterations = 1).
#   (b) The example participants (examples/) do the same with their own state; an
#       implicit run of theirs with --log-traffic replays bit for bit (fsi replay) for
#       each participant, and fsi inspect lists iterations past the first.
#   (c) ULPH + NOSB-PD with IQN-ILS converges: every window is accepted converged
#       (coupling_on_max_iterations = stop), in at most 10 iterations, and the run
#       finishes; the mean iterations per window is printed.
#   (d) A changing interface set: C4's plate (cases/c4_plate_under_water.ini) under 0.5 m
#       of water at T / dx = 8, so that it has layers deeper than the fluid's reach, with
#       NOSB-PD's failure on and a critical stretch low enough that bonds break at the
#       clamps within 0.002 s (5e-6; the bending strain there is about 1.5e-5 at rest):
#       a cut horizon makes deeper points part of the interface. Asserted: some window's
#       history restarted for it (history_restarted 1 or 3 in coupling.csv),
#       broken bonds in the last frame, and every window still accepted converged. About
#       10 s on 2 threads.
#   (e) IQN-ILS against Aitken on the same window sequence: C4's plate under 0.5 m of
#       water at T / dx = 4 with a tenth of aluminium's density and no impedance answer
#       (the plain scheme that is unstable there explicitly, docs/stability.md), ten
#       windows of 2e-4 s (probes every 1e-3 s, so no window is cut short and IQN-ILS
#       reuses its columns). Asserted: the same windows accepted, every one converged,
#       and IQN-ILS needing fewer iterations in all than Aitken (measured: 44 against 61).
# Every coupling.csv here also has its (window, iteration) rows in order, each once.
source "$(dirname "$0")/lib.sh"
PY=/usr/bin/python3
CASE="$FSI_SOURCE_DIR/cases/c1_elastic_plate.ini"
SCENE=(--threads 1 --set run.end_time=0.002 --set run.output_interval=0.001 --set run.max_window=2e-4
       --set "fluid.block water.min=0.148,0" --set "fluid.block water.max=0.292,0.292"
       --set run.scheme=implicit)

"$FSI_BIN_DIR/fsi-solvers" >solvers.txt || { cat solvers.txt; fail "fsi solvers failed"; }
fluids=$(awk '!/^#/ && $1 == "fluid" && $3 == "solver" {print $2}' solvers.txt)
solids=$(awk '!/^#/ && $1 == "solid" && $3 == "solver" {print $2}' solvers.txt)

# repeated_iterations_identical DIR: every repeated iteration of coupling.csv has force
# residual 0 and the first iteration's displacement residual.
# rows_in_order DIR: coupling.csv's rows go window by window, iteration 0, 1, ... each once.
rows_in_order() {
  "$PY" - "$1/coupling.csv" <<'PY'
import csv, sys
rows = [(int(float(r["window"])), int(float(r["iteration"]))) for r in csv.DictReader(open(sys.argv[1]))]
bad = [(a, b) for a, b in zip(rows, rows[1:]) if not (b == (a[0], a[1] + 1) or (b[0] > a[0] and b[1] == 0))]
print("coupling.csv rows out of order:", bad[:5]) if bad else None
sys.exit(1 if bad or not rows or rows[0][1] != 0 else 0)
PY
}

repeated_iterations_identical() {
  "$PY" - "$1/coupling.csv" <<'PY'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
first, bad, repeated = {}, [], 0
for r in rows:
    w, i = int(float(r["window"])), int(float(r["iteration"]))
    if i == 0:
        first[w] = r["displacement_residual"]
        continue
    repeated += 1
    if float(r["force_residual"]) != 0.0 or r["displacement_residual"] != first[w]:
        bad.append((w, i, r["force_residual"], r["displacement_residual"], first[w]))
print("%d windows, %d repeated iterations, %d differ from their window's first" % (len(first), repeated, len(bad)))
for b in bad[:5]:
    print("  window %d iteration %d: force residual %s, displacement residual %s (first %s)" % b)
sys.exit(1 if bad or repeated == 0 else 0)
PY
}

failed=""
for fluid in $fluids; do
  for solid in $solids; do
    pair="$fluid+$solid"
    common=("${SCENE[@]}" --set fluid.solver="$fluid" --set solid.solver="$solid")
    if ! FSI_TEST_REPEAT_MOTION=1 "$FSI_RUN" "$CASE" --out "$pair.3" "${common[@]}" \
        --set run.coupling_min_iterations=3 --set run.coupling_max_iterations=3 \
        --set run.coupling_on_max_iterations=continue >"$pair.3.txt" 2>&1; then
      tail -5 "$pair.3.txt"; failed="$failed $pair(run)"; continue
    fi
    FSI_TEST_REPEAT_MOTION=1 "$FSI_RUN" "$CASE" --out "$pair.1" "${common[@]}" \
      --set run.coupling_max_iterations=1 --set run.coupling_on_max_iterations=continue \
      >"$pair.1.txt" 2>&1 || { tail -5 "$pair.1.txt"; failed="$failed $pair(run)"; continue; }
    repeated_iterations_identical "$pair.3" || { failed="$failed $pair(iterations)"; continue; }
    (same_results "$pair.3" "$pair.1") || { failed="$failed $pair(output)"; continue; }
    pass "$pair: three iterations per window repeat the first bit for bit"
  done
done
[ -z "$failed" ] || fail "save/restore incomplete for:$failed"

# (b) the examples
small_case ex.ini 0.05
sed -i 's/^end_time = .*/&\nscheme = implicit/' ex.ini
FSI_TEST_REPEAT_MOTION=1 "$FSI_RUN" ex.ini --out ex3 --set run.coupling_min_iterations=3 \
  --set run.coupling_max_iterations=3 --set run.coupling_on_max_iterations=continue >ex3.txt 2>&1 ||
  { cat ex3.txt; fail "examples, implicit"; }
FSI_TEST_REPEAT_MOTION=1 "$FSI_RUN" ex.ini --out ex1 --set run.coupling_max_iterations=1 \
  --set run.coupling_on_max_iterations=continue >ex1.txt 2>&1 || { cat ex1.txt; fail "examples"; }
repeated_iterations_identical ex3 || fail "examples: repeated iterations differ"
same_results ex3 ex1
pass "examples: three iterations per window repeat the first bit for bit"
# The traffic log of an implicit run (messages keyed by window and iteration) replays
# each participant bit for bit: what fsi_read_interface handed out stays valid until the
# next fsi_ongoing although the next iteration's data arrives while fsi_advance waits
# (before that was kept apart, the example fluid's frames took the next iteration's
# positions in the live run and not in the replay).
"$FSI_RUN" ex.ini --out exlog --log-traffic >exlog.txt 2>&1 || { cat exlog.txt; fail "examples, implicit, --log-traffic"; }
for who in fluid solid; do
  "$FSI_BIN_DIR/fsi-replay" exlog --participant "$who" >"replay_$who.txt" 2>&1 ||
    { cat "replay_$who.txt"; fail "replay of the implicit run's $who"; }
done
# (into a file first: grep -q ending a pipeline early fails it under pipefail)
"$FSI_BIN_DIR/fsi-inspect" exlog/traffic.lcmlog >inspect.txt || fail "fsi inspect failed"
awk '$2 >= 1 && $3 == "FSI_FLUID_LOAD" {found = 1} END {exit !found}' inspect.txt ||
  fail "fsi inspect shows no fluid load of an iteration past the first"
pass "implicit run: traffic log with iterations, fsi inspect lists them, replay bit for bit"

# (c) convergence
"$FSI_RUN" "$CASE" --out iqn "${SCENE[@]}" --set fluid.solver=ulph --set solid.solver=nosbpd \
  --set run.coupling_max_iterations=10 --set run.coupling_on_max_iterations=stop >iqn.txt 2>&1 ||
  { tail -5 iqn.txt; fail "ULPH + NOSB-PD implicit with IQN-ILS did not finish"; }
"$PY" - iqn/coupling.csv <<'PY' || fail "ULPH + NOSB-PD implicit: a window not converged"
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
accepted = [r for r in rows if r["accepted"] == "1"]
unconverged = [r for r in accepted if r["converged"] != "1"]
print("%d windows, %d iterations (%.2f per window), %d accepted unconverged" %
      (len(accepted), len(rows), len(rows) / max(len(accepted), 1), len(unconverged)))
sys.exit(1 if unconverged or not accepted else 0)
PY
rows_in_order iqn || fail "ULPH + NOSB-PD implicit: coupling.csv rows out of order"
pass "ULPH + NOSB-PD: every window converged with IQN-ILS"

# (d) a changing interface set
"$FSI_RUN" "$FSI_SOURCE_DIR/cases/c4_plate_under_water.ini" --out crack --threads 2 \
  --set run.end_time=0.002 --set run.output_interval=0.001 --set "fluid.block water.max=1,0.5" \
  --set fluid.max_pressure=4905 --set fluid.spacing=0.00625 --set solid.spacing=0.00625 \
  --set run.scheme=implicit --set solid.nosbpd.failure=true --set solid.nosbpd.critical_stretch=5e-6 \
  --set run.coupling_max_iterations=20 --set run.coupling_on_max_iterations=stop >crack.txt 2>&1 ||
  { tail -5 crack.txt; fail "fracturing plate, implicit: did not finish"; }
"$PY" - crack <<'PY' || fail "fracturing plate, implicit"
import csv, glob, sys
import h5py, numpy as np
out = sys.argv[1]
rows = list(csv.DictReader(open(out + "/coupling.csv")))
accepted = [r for r in rows if r["accepted"] == "1"]
# bit 1: the interface set changed (bit 2, a change of the window's length, also drops it)
restarts = sum(int(float(r["history_restarted"])) & 1 and r["iteration"] == "0" for r in rows)
unconverged = sum(r["converged"] != "1" for r in accepted)
last = sorted(glob.glob(out + "/solid.frames/[0-9]*.h5"))[-1]
with h5py.File(last) as f:
    damage = f["damage"][()] if "damage" in f else np.zeros(1)
print("%d windows, %d with the interface set changed (history restarted), %d unconverged; "
      "largest damage %.3g" % (len(accepted), restarts, unconverged, damage.max()))
sys.exit(0 if restarts > 0 and unconverged == 0 and damage.max() > 0 else 1)
PY
pass "fracturing plate: the history restarts when the interface set changes, every window converges"

# (e) IQN-ILS against Aitken
for acc in iqn_ils aitken; do
  "$FSI_RUN" "$FSI_SOURCE_DIR/cases/c4_plate_under_water.ini" --out "acc_$acc" --threads 1 \
    --set run.end_time=0.002 --set run.probe_interval=1e-3 --set "fluid.block water.max=1,0.5" \
    --set fluid.max_pressure=4905 --set fluid.spacing=0.0125 --set solid.spacing=0.0125 \
    --set solid.density=100 --set solid.interface_impedance=false --set run.scheme=implicit \
    --set run.coupling_acceleration=$acc --set run.coupling_max_iterations=30 \
    --set run.coupling_on_max_iterations=stop >"acc_$acc.txt" 2>&1 ||
    { tail -5 "acc_$acc.txt"; fail "plate at density ratio 0.1 with $acc: did not finish"; }
  rows_in_order "acc_$acc" || fail "$acc: coupling.csv rows out of order"
done
"$PY" - acc_iqn_ils acc_aitken <<'PY' || fail "IQN-ILS against Aitken"
import csv, sys
runs = {}
for out in sys.argv[1:]:
    rows = list(csv.DictReader(open(out + "/coupling.csv")))
    accepted = [(r["window"], r["dt"]) for r in rows if r["accepted"] == "1"]
    unconverged = sum(r["converged"] != "1" for r in rows if r["accepted"] == "1")
    runs[out] = (accepted, len(rows), unconverged)
    print("%s: %d windows, %d iterations (%.2f per window), %d unconverged" %
          (out, len(accepted), len(rows), len(rows) / max(len(accepted), 1), unconverged))
(wi, ni, ui), (wa, na, ua) = runs["acc_iqn_ils"], runs["acc_aitken"]
sys.exit(0 if wi == wa and len(wi) == 10 and ui == ua == 0 and ni < na else 1)
PY
pass "IQN-ILS converges in fewer iterations than Aitken on the same windows"
