#!/usr/bin/env bash
# fsi bench: C3 sluice gate free-end displacement per T/dx (no reference data)
# C3 dam-break wave on an elastic sluice gate (docs/validation.md
# C3): cases/c3_sluice_gate.ini at one or more resolutions T / dx (T = 7 mm the gate's
# thickness), and the displacement of the gate's free end (point A). No reference data.
#
#   bench/c3_sluice_gate.sh [OUT] [--n "3 4"] [--resume | --report] [--threads T] [--set k=v ...]
#
# Each run's output is OUT/tN (log OUT/tN.txt), N = T / dx. Every length that depends on
# the spacing follows it as in the case (whose numbers are those of N = 3): the water
# column, the gap to the gate, the gate's length and the rigid wall above it are the
# whole numbers of spacings nearest 0.5, 0.2, 0.3, 0.125 and 0.012 m; the gate hangs to
# one spacing above the floor; the clamp block and the other walls are four spacings
# thick; the probe sits on the middle point of the gate's lowest row (of the middle two,
# the downstream one). Writes OUT/c3_sluice_gate.md (particles, windows, largest
# displacements, fluid particles inside the solid, wall time), OUT/c3_sluice_gate.png
# (point A against time) and OUT/c3_snapshots.png (bench/c3_sluice_gate.py).
# --resume keeps the runs of OUT that finished; --report runs nothing and reports the
# runs in OUT (finished or not). --set is passed to every run.
# Default N = 3 (the case's) on 1 thread: 76 minutes on the loaded shared machine,
# roughly 40 on a quiet one (docs/validation.md C3); N = 4 takes about 2.4 times that.
set -euo pipefail

THREADS=1
. "$(dirname "${BASH_SOURCE[0]}")/sweep.bash"
sweep_parse c3_sluice_gate --n "3" "$@"

# The --set options (one "section.key=value" a line) of the geometry at T / dx = $1.
geometry() {
  "$PY" - "$1" <<'PYEOF'
import sys
n = int(sys.argv[1])
dx = 0.007 / n
def at(*m):                                 # lattice coordinates -> "x, y" in metres
    return ",".join(f"{k * dx:.12g}" for k in m)
cw, ch = round(0.5 / dx), round(0.2 / dx)   # the water column
g0 = cw + round(0.3 / dx)                   # the gate's upstream face
top = 1 + round(0.125 / dx)                 # the clamp line: the gate hangs to y = dx
ww = round(0.012 / dx)                      # the rigid wall above the gate
w, ceil, end = 4, round(0.49 / dx), round(1.4 / dx)
for line in (f"fluid.spacing={dx:.12g}", f"solid.spacing={dx:.12g}",
             f"fluid.block water.max={at(cw, ch)}",
             f"solid.block gate.min={at(g0, 1)}", f"solid.block gate.max={at(g0 + n, top)}",
             f"solid.block clamp.min={at(g0, top)}", f"solid.block clamp.max={at(g0 + n, top + w)}",
             f"solid.region clamp.min={at(g0, top)}", f"solid.region clamp.max={at(g0 + n, top + w)}",
             f"solid.probe tip.point={at(g0 + n // 2 + 0.5, 1.5)}",
             f"fluid.wall floor.min={at(-w, -w)}", f"fluid.wall floor.max={at(end, 0)}",
             f"fluid.wall left.min={at(-w, 0)}", f"fluid.wall left.max={at(0, ceil)}",
             f"fluid.wall above_gate.min={at(g0, top)}", f"fluid.wall above_gate.max={at(g0 + ww, ceil)}",
             f"fluid.probe dam_foot.point={at(cw, 0)}"):
    print(line)
PYEOF
}

DIRS=()
for n in $LIST; do
  GEO=()
  while IFS= read -r kv; do GEO+=(--set "$kv"); done < <(geometry "$n")
  DIRS+=("$OUT/t$n")
  log "t$n: dx = T / $n = $("$PY" -c "print(0.007 / $n)") m"
  sweep_run "$OUT/t$n" "$ROOT/cases/c3_sluice_gate.ini" "${GEO[@]}"
done

"$PY" "$ROOT/bench/c3_sluice_gate.py" --png "$OUT/c3_sluice_gate.png" \
  --snapshots "$OUT/c3_snapshots.png" --md "$OUT/c3_sluice_gate.md" "${DIRS[@]}" |
  tee "$OUT/c3_sluice_gate.txt"
cat "$OUT/c3_sluice_gate.md"
log "report: $OUT/c3_sluice_gate.md, plots: $OUT/c3_sluice_gate.png, $OUT/c3_snapshots.png"
