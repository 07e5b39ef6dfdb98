#!/usr/bin/env bash
# C1, the `./fsi main` scene (cases/c1_elastic_plate.ini at its default dx = 4 mm): a
# water column collapses against a clamped elastic plate, ULPH + NOSB-PD coupled, to
# t = 0.25 s, past the first peak of the plate's deflection (about 1-3 minutes on one
# thread). Asserts:
#   - the run finishes (stable through the impact on a plate three particles thick,
#     the solid taking one sub-step per window);
#   - no fluid particle comes within half a spacing of a plate particle in any window;
#   - the first peak of the upper-left corner's horizontal displacement is within
#     15 % of the mean of the four published peaks (data/elastic_obstacle_xdisp_num_*:
#     0.045-0.048 m, mean 0.0465 m) and its time within the published times
#     0.217-0.260 s widened by 0.02 s. The four references differ by 7 % among
#     themselves; this case measured +7.5 % (docs/validation.md C1): 15 % is about
#     twice either;
#   - the resolved case holds the derived [fluid] support and the solid uses it.
source "$(dirname "$0")/lib.sh"
PY=/usr/bin/python3

"$FSI_RUN" "$FSI_SOURCE_DIR/cases/c1_elastic_plate.ini" --out c1 --threads 1 \
  --set run.end_time=0.25 >c1.txt 2>&1 || { cat c1.txt; tail -5 c1/*.log; fail "C1 coupled run failed"; }

# The fluid's support radius, 1.2 * 3 * 4 mm, is derived into the resolved case, and
# the solid takes its interface depth from it (reach = support - dx_f / 2).
grep -qE '^support = 0.0144 +; # derived$' c1/case.resolved.ini ||
  { grep -n support c1/case.resolved.ini; fail "no derived [fluid] support = 0.0144 in case.resolved.ini"; }
grep -q '^\[fluid.ulph\]' c1/case.resolved.ini && grep -q '^\[solid.nosbpd\]' c1/case.resolved.ini ||
  fail "the chosen solvers' sections are missing from case.resolved.ini"
grep -q "its reach 0.0124 m" c1/solid.log || { grep interface c1/solid.log; fail "the solid's reach is not 0.0124 m"; }
pass "derived support 0.0144 m in the resolved case; the solid's reach 0.0124 m"

grep -q "fluid particles inside the solid (closer than half the solid's spacing to a solid particle): at most 0 at once, in 0 windows" \
  c1/fluid.log || { grep interface c1/fluid.log; fail "fluid particles entered the plate"; }
pass "no fluid particle inside the plate in any window"

"$PY" - c1 "$FSI_SOURCE_DIR/data" <<'PY' || fail "C1 corner displacement"
import csv, glob, sys
out, data = sys.argv[1], sys.argv[2]
rows = list(csv.DictReader(l for l in open(out + "/probes.csv") if not l.startswith("#")))
peak, t_peak = max((float(r["corner_ux"]), float(r["time"])) for r in rows)
refs = []
for path in sorted(glob.glob(data + "/elastic_obstacle_xdisp_num_*.csv")):
    pts = [(float(a), float(b)) for a, b in list(csv.reader(open(path)))[1:] if float(a) <= 0.35]
    refs.append(max((u, t) for t, u in pts))
mean = sum(u for u, _ in refs) / len(refs)
t_lo, t_hi = min(t for _, t in refs) - 0.02, max(t for _, t in refs) + 0.02
print("first peak %.4f m at %.3f s; published peaks %s, mean %.4f m: %+.1f %%"
      % (peak, t_peak, ", ".join("%.4f m at %.3f s" % r for r in refs), mean, 100 * (peak / mean - 1)))
ok = abs(peak / mean - 1) < 0.15 and t_lo <= t_peak <= t_hi
sys.exit(0 if ok else 1)
PY
pass "C1: corner's first peak within 15 % of the published peaks, at a published time"
