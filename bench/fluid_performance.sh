#!/usr/bin/env bash
# Speed of the ULPH fluid (docs/performance.md, "Fluid (ULPH)"): the F1 dam break
# (cases/f1_dam_break.ini) at dx = a / 57 = 1.0026 mm and a / 114 = 0.5013 mm (the
# nearest spacings to 1 mm and 0.5 mm that divide the column a = 0.05715 m; walls four
# layers thick, scaled with the spacing as bench/f1_dam_break.sh does), on 1 and 2
# threads, RUNS runs each, the first END seconds of the collapse (defaults: 0.005 s =
# 1663 steps at a / 57, 0.001 s = 665 steps at a / 114; cfl_acoustic = 0.1, c0 = 40 m/s).
#
#   bench/fluid_performance.sh [OUT] [--runs=N] [--threads="1 2"] [--end57=T] [--end114=T]
#                              [--set=k=v ...]
#
# Writes OUT/fluid_performance.md: particles, steps, the median particle-steps/s (each
# fluid.log's "performance:" line: fluid particles x steps / (rates + integration)
# seconds), the per-phase split of the median run, and the speed-up of 2 threads over 1.
# FSI_BUILD=DIR runs another build's binaries (e.g. an older commit's, for a comparison
# within one run of the script).
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD="${FSI_BUILD:-$ROOT/build}"
RUN="$BUILD/bin/fsi-run"
PY=/usr/bin/python3
OUT="$ROOT/out/bench/fluid_performance"
RUNS=3
THREADS="1 2"
END57=0.005
END114=0.001
EXTRA=()
for arg in "$@"; do
  case "$arg" in
    --runs=*) RUNS="${arg#*=}" ;;
    --threads=*) THREADS="${arg#*=}" ;;
    --end57=*) END57="${arg#*=}" ;;
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
for r in $(seq 1 "$RUNS"); do
  for n in 57 114; do
    end=$END57; [ "$n" = 114 ] && end=$END114
    for t in $THREADS; do
      log "a / $n, $t thread(s), run $r ..."
      f1_run "$RUN" "$n" "$t" "$OUT/n${n}_t${t}_r$r" --set "run.end_time=$end" "${EXTRA[@]}" ||
        log "run failed, see $OUT/n${n}_t${t}_r$r.txt"
    done
  done
done

"$PY" - "$OUT" "$RUNS" "$THREADS" > "$OUT/fluid_performance.md" <<'EOF'
import re, statistics, sys
out, runs, threads = sys.argv[1], int(sys.argv[2]), sys.argv[3].split()
perf = re.compile(r"performance: (\d+) steps of (\d+) fluid particles \((\d+) in all, (\d+) "
                  r"neighbour pairs\) on (\d+) thread.*\(([0-9.e+]+) particle-steps/s\)")
phase = re.compile(r"([a-z :]+?) ([0-9.]+) s \(([0-9.]+) %\)")
print("| a / dx | fluid particles (all) | steps | threads | particle-steps/s, median "
      "(runs) | speed-up | neighbour search | operators | EOS | walls | density filter "
      "| momentum | integration | exchange + output |")
print("| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |")
for n in (57, 114):
    base = None
    for t in threads:
        rows = []
        for r in range(1, runs + 1):
            text = open(f"{out}/n{n}_t{t}_r{r}/fluid.log").read()
            m = perf.search(text)
            split = dict((k.strip(), float(p)) for k, s, p in
                         phase.findall(text.split("phases:")[-1]))
            rows.append((float(m.group(6)), m, split))
        rows.sort(key=lambda x: x[0])
        med, m, split = rows[len(rows) // 2]
        base = base or med
        share = lambda k: "%.1f %%" % split.get(k, 0.0)
        print(f"| {n} | {m.group(2)} ({m.group(3)}) | {m.group(1)} | {t} | {med:.3g} "
              f"({' '.join('%.3g' % x[0] for x in rows)}) | {med / base:.2f} | "
              f"{share('rates: neighbour search')} | {share('rates: operators')} | "
              f"{share('rates: equation of state')} | {share('rates: walls')} | "
              f"{share('rates: density filter')} | {share('rates: momentum')} | "
              f"{share('integration')} | "
              f"{split.get('exchange', 0) + split.get('output', 0):.1f} % |")
EOF
cat "$OUT/fluid_performance.md"
log "report: $OUT/fluid_performance.md"
