#!/usr/bin/env bash
# Coupled checkpoints and restart (docs/checkpoints.md): a run interrupted by kill -9 and
# restarted with `fsi run --restart OUT` ends with the same output, bit for bit (every
# frame of fluid.h5 and solid.h5 compared with h5diff, probes.csv, coupling.csv and the
# participants' diagnostics (fluid_diagnostics.csv, solid_diagnostics.csv) with
# cmp), as the same run never interrupted.
# The scene is test_solver_combinations': C1 with the water against the plate, 0.004 s,
# frames every 0.001 s, a checkpoint at each (--checkpoint-interval 0.001), windows of at
# most 2e-4 s (with ISPH's own 1e-3 s windows ISPH + NOSB-PD is unstable on this scene,
# explicit or in the first iteration of an implicit window: test_solver_combinations).
#   (a) every fluid x solid combination the registry lists, explicit coupling, the solid
#       killed (test switch FSI_TEST_KILL, SIGKILL) at three quarters of the run's windows;
#   (b) the same with implicit coupling (IQN-ILS, whose history of earlier windows is part
#       of the checkpoint), the fluid killed;
#   (c) NOSB-PD with fracture (failure on, critical_stretch 2e-5: bonds break within the
#       run), explicit and implicit;
#   (d) `fsi run` itself killed with kill -9 (every process of the run goes with it) once a
#       checkpoint is complete;
#   (e) refused with exit 2 and a message, nothing run: --restart of a folder without a
#       complete checkpoint, of a checkpoint whose COMPLETE names another code version,
#       and with a case or --set beside it; a state file cut short stops the restarted
#       run naming the file.
source "$(dirname "$0")/lib.sh"
PY=/usr/bin/python3
CASE="$FSI_SOURCE_DIR/cases/c1_elastic_plate.ini"
SCENE=(--threads 1 --set run.end_time=0.004 --set run.output_interval=0.001 --set run.max_window=2e-4
       --set "fluid.block water.min=0.148,0" --set "fluid.block water.max=0.292,0.292"
       --checkpoint-interval 0.001)

"$FSI_BIN_DIR/fsi-solvers" >solvers.txt || { cat solvers.txt; fail "fsi solvers failed"; }
fluids=$(awk '!/^#/ && $1 == "fluid" && $3 == "solver" {print $2}' solvers.txt)
solids=$(awk '!/^#/ && $1 == "solid" && $3 == "solver" {print $2}' solvers.txt)

windows_of() { awk '/^windows = / {print $3}' "$1/run.log" | tail -1; }

# interrupted_same NAME VICTIM ARGS...: runs NAME.whole, then NAME killed (VICTIM at 3/4 of
# the whole run's windows) and restarted; 0 when the two outputs are the same.
interrupted_same() {
  local name="$1" victim="$2"
  shift 2
  "$FSI_RUN" "$CASE" --out "$name.whole" "${SCENE[@]}" "$@" >"$name.whole.txt" 2>&1 ||
    { tail -5 "$name.whole.txt"; echo "$name: the uninterrupted run failed"; return 1; }
  local k=$(( $(windows_of "$name.whole") * 3 / 4 ))
  if FSI_TEST_KILL="$victim:$k" "$FSI_RUN" "$CASE" --out "$name" "${SCENE[@]}" "$@" \
      >"$name.killed.txt" 2>&1; then
    echo "$name: the run killed at window $k finished"; return 1
  fi
  "$FSI_BIN_DIR/fsi-run" --restart "$name" --threads 1 >"$name.restart.txt" 2>&1 ||
    { tail -5 "$name.restart.txt"; echo "$name: the restart failed"; return 1; }
  grep -q "restart from .*window_" "$name/run.log" || { echo "$name: run.log names no restart"; return 1; }
  (same_results "$name.whole" "$name") || return 1
  if [ -e "$name.whole/coupling.csv" ]; then
    cmp -s "$name.whole/coupling.csv" "$name/coupling.csv" ||
      { echo "$name: coupling.csv differs"; return 1; }
  fi
  output_readable "$name" fluid solid || { echo "$name: output not readable"; return 1; }
  echo "$name: killed at window $k of $(windows_of "$name.whole"), restarted from $(grep -o 'window_[0-9][0-9]*' "$name/run.log" | tail -1): same output"
}

failed=""
for fluid in $fluids; do
  for solid in $solids; do
    interrupted_same "$fluid+$solid" solid --set fluid.solver="$fluid" --set solid.solver="$solid" ||
      failed="$failed $fluid+$solid"
    interrupted_same "$fluid+$solid.implicit" fluid --set fluid.solver="$fluid" \
      --set solid.solver="$solid" --set run.scheme=implicit \
      --set run.coupling_on_max_iterations=continue || failed="$failed $fluid+$solid(implicit)"
  done
done
[ -z "$failed" ] || fail "restart not bit-identical for:$failed"
pass "every combination, explicit and implicit: killed and restarted = uninterrupted"

FRACTURE=(--set fluid.solver=ulph --set solid.solver=nosbpd --set solid.nosbpd.failure=true
          --set solid.nosbpd.critical_stretch=2e-5)
interrupted_same crack solid "${FRACTURE[@]}" || fail "fracture, explicit"
interrupted_same crack.implicit solid "${FRACTURE[@]}" --set run.scheme=implicit \
  --set run.coupling_on_max_iterations=continue || fail "fracture, implicit"
"$PY" -c "
import glob, h5py, sys
last = sorted(glob.glob('crack/solid.frames/[0-9]*.h5'))[-1]
d = h5py.File(last)['damage'][()]
print('largest damage in the last frame: %.3g' % d.max())
sys.exit(0 if d.max() > 0 else 1)" || fail "the fracture scene broke no bond"
pass "fracturing NOSB-PD, explicit and implicit: killed and restarted = uninterrupted"

# (d) kill -9 of fsi run itself
"$FSI_RUN" "$CASE" --out hard "${SCENE[@]}" --set run.end_time=0.02 >hard.txt 2>&1 &
pid=$!
for _ in $(seq 600); do
  ls hard/checkpoints/window_*/COMPLETE >/dev/null 2>&1 && break
  sleep 0.05
done
ls hard/checkpoints/window_*/COMPLETE >/dev/null 2>&1 || { kill -9 $pid; fail "no checkpoint appeared"; }
sleep 0.3
kill -9 $pid
wait $pid 2>/dev/null || true
sleep 0.5
[ -z "$(run_pids hard 2>/dev/null)" ] || fail "processes of the killed run are still alive"
"$FSI_BIN_DIR/fsi-run" --restart hard --threads 1 >hard.restart.txt 2>&1 || { tail -5 hard.restart.txt; fail "restart after kill -9 of fsi run"; }
"$FSI_RUN" "$CASE" --out hard.whole "${SCENE[@]}" --set run.end_time=0.02 >hard.whole.txt 2>&1 ||
  fail "the uninterrupted run"
same_results hard.whole hard
pass "kill -9 of fsi run, restarted: the same output as the uninterrupted run"

# (e) refusals
mkdir -p empty
"$FSI_BIN_DIR/fsi-run" --restart empty >refuse1.txt 2>&1 && fail "--restart of a folder without a checkpoint ran"
[ $? -eq 2 ] || true
grep -q "no complete checkpoint\|cannot open case file" refuse1.txt || { cat refuse1.txt; fail "no message for a folder without a checkpoint"; }
cp -r crack other
latest=$(ls -d other/checkpoints/window_* | tail -1)
sed -i 's/^version = .*/version = 0.0-elsewhere/' "$latest/COMPLETE"
set +e
"$FSI_BIN_DIR/fsi-run" --restart other >refuse2.txt 2>&1
rc=$?
set -e
[ $rc -eq 2 ] && grep -q "version 0.0-elsewhere" refuse2.txt || { cat refuse2.txt; fail "a checkpoint of another version was not refused (exit $rc)"; }
set +e
"$FSI_BIN_DIR/fsi-run" "$CASE" --restart crack >refuse3.txt 2>&1
rc=$?
set -e
[ $rc -eq 2 ] || { cat refuse3.txt; fail "--restart with a case beside it: exit $rc"; }
cp -r crack cut
latest=$(ls -d cut/checkpoints/window_* | tail -1)
truncate -s -100 "$latest/solid.state"
set +e
"$FSI_BIN_DIR/fsi-run" --restart cut >refuse4.txt 2>&1
rc=$?
set -e
[ $rc -ne 0 ] && grep -q "solid.state" refuse4.txt cut/solid.log ||
  { cat refuse4.txt; fail "a state file cut short was not refused by name (exit $rc)"; }
pass "refused: no checkpoint, another version, a case beside --restart, a cut state file"
