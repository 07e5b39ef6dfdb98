#!/usr/bin/env bash
# fsi bench: fluid scheme speed on F1: particle-steps/s and wall time, 1 and 2 threads
# Speed of the fluid schemes (docs/performance.md): the F1 dam break
# (cases/f1_dam_break.ini) at dx = a / N for each N of --n (default 57 and 114: the
# nearest spacings to 1 mm and 0.5 mm that divide the column a = 0.05715 m; 100 is the
# peer's scene, 20 000 fluid particles; walls four layers thick, scaled with the
# spacing as bench/f1_dam_break.sh does), for each scheme of --schemes
# (`--set fluid.solver=SCHEME`, the scheme's own keys from the case's [fluid.SCHEME]
# section or its defaults), on 1 and 2 threads, RUNS runs each, the first END seconds
# of the collapse (defaults: 0.005 s at a / 57 and a / 100, 0.001 s at a / 114).
#
#   bench/fluid_performance.sh [OUT] [--runs=N] [--threads="1 2"] [--n="57 114"]
#                              [--schemes="ulph wcsph"] [--end57=T] [--end100=T]
#                              [--end114=T] [--set=k=v ...]
#
# Writes OUT/fluid_performance.md: per scheme, resolution and thread count the
# particles, steps, the median particle-steps/s (each fluid.log's "performance:" line:
# fluid particles x steps / (rates + integration) seconds), the median wall time of the
# whole run to END, the speed-up of 2 threads over 1, and the largest phases of the
# median run. FSI_BUILD=DIR runs another build's binaries (e.g. an older commit's, for a
# comparison within one run of the script).
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD="${FSI_BUILD:-$ROOT/build}"
RUN="$BUILD/bin/fsi-run"
PY=/usr/bin/python3
OUT="$ROOT/out/bench/fluid_performance"
RUNS=3
THREADS="1 2"
NS="57 114"
SCHEMES="ulph wcsph"
END57=0.005
END100=0.005
END114=0.001
EXTRA=()
for arg in "$@"; do
  case "$arg" in
    --runs=*) RUNS="${arg#*=}" ;;
    --threads=*) THREADS="${arg#*=}" ;;
    --n=*) NS="${arg#*=}" ;;
    --schemes=*) SCHEMES="${arg#*=}" ;;
    --end57=*) END57="${arg#*=}" ;;
    --end100=*) END100="${arg#*=}" ;;
    --end114=*) END114="${arg#*=}" ;;
    --set=*) EXTRA+=(--set "${arg#*=}") ;;
    -*) echo "fluid_performance: unknown option $arg" >&2; exit 2 ;;
    *) OUT="$arg" ;;
  esac
done
mkdir -p "$OUT"
log() { echo "[fluid_performance] $*" >&2; }
. "$ROOT/bench/f1_run.bash"

# Runs are interleaved (run 1 of every configuration, then run 2, ...) so that a change
# in the machine's load spreads over all of them.
end_of() { case "$1" in 57) echo "$END57" ;; 100) echo "$END100" ;; 114) echo "$END114" ;;
                        *) echo "$END57" ;; esac; }
for r in $(seq 1 "$RUNS"); do
  for n in $NS; do
    for scheme in $SCHEMES; do
      for t in $THREADS; do
        dir="$OUT/${scheme}_n${n}_t${t}_r$r"
        log "$scheme, a / $n, $t thread(s), run $r ..."
        f1_run "$RUN" "$n" "$t" "$dir" --set "run.end_time=$(end_of "$n")" \
          --set "fluid.solver=$scheme" "${EXTRA[@]}" || log "run failed, see $dir.txt"
      done
    done
  done
done

"$PY" - "$OUT" "$RUNS" "$THREADS" "$NS" "$SCHEMES" > "$OUT/fluid_performance.md" <<'EOF'
import os, re, statistics, sys
out, runs = sys.argv[1], int(sys.argv[2])
threads, ns, schemes = sys.argv[3].split(), sys.argv[4].split(), sys.argv[5].split()
perf = re.compile(r"performance: (\d+) steps of (\d+) fluid particles \((\d+) in all, (\d+) "
                  r"neighbour pairs\) on (\d+) thread.*\(([0-9.e+]+) particle-steps/s\)")
phase = re.compile(r"([a-z :-]+?) ([0-9.]+) s \(([0-9.]+) %\)")
wall = re.compile(r"finished in ([0-9.]+) s")
print("| scheme | a / dx | fluid particles (all) | steps | threads | particle-steps/s, "
      "median (runs) | wall time [s], median | speed-up | largest phases of the median run |")
print("| --- | --- | --- | --- | --- | --- | --- | --- | --- |")
for n in ns:
    for scheme in schemes:
        base = None
        for t in threads:
            rows = []
            for r in range(1, runs + 1):
                d = f"{out}/{scheme}_n{n}_t{t}_r{r}"
                if not os.path.exists(f"{d}/fluid.log"):
                    continue
                text = open(f"{d}/fluid.log").read()
                m = perf.search(text)
                w = wall.search(open(f"{d}.txt").read())
                if not m or not w:
                    continue
                split = [(k.strip(), float(p)) for k, s, p in
                         phase.findall(text.split("phases:")[-1])]
                rows.append((float(m.group(6)), m, split, float(w.group(1))))
            if not rows:
                print(f"| {scheme} | {n} | - | - | {t} | failed | - | - | - |")
                continue
            rows.sort(key=lambda x: x[0])
            med, m, split, _ = rows[len(rows) // 2]
            wall_med = statistics.median(x[3] for x in rows)
            base = base or med
            top = ", ".join(f"{k} {p:.0f} %" for k, p in
                            sorted((x for x in split if x[0] != "rates"),
                                   key=lambda x: -x[1])[:4])
            print(f"| {scheme} | {n} | {m.group(2)} ({m.group(3)}) | {m.group(1)} | {t} | "
                  f"{med:.3g} ({' '.join('%.3g' % x[0] for x in rows)}) | {wall_med:.1f} | "
                  f"{med / base:.2f} | {top} |")
EOF
cat "$OUT/fluid_performance.md"
log "report: $OUT/fluid_performance.md"
