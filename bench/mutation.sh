#!/usr/bin/env bash
# fsi bench: mutation score: which of bench/mutations.list's planted bugs the tests catch
# Mutation bench: does the test suite catch small plausible bugs? Every mutation of
# bench/mutations.list is applied alone to a clean copy of the committed tree (git
# archive HEAD, in a folder outside the repository), built (Release), and the tests
# run; a mutant is caught ("killed") when at least one test fails. Prints a markdown
# table (mutant, file, what it breaks, tests that caught it) and the kill rate.
#
#   bench/mutation.sh [--only NAME] [--tests REGEX | --expected] [-j N] [--keep]
#                     [--skip-clean]
#     --only NAME    one mutant (repeatable)
#     --tests REGEX  run only the tests matching REGEX (ctest -R) for every mutant
#     --expected     run, for each mutant, only the tests its 'catch:' line names
#     -j N           ctest's parallel jobs (default 1) and build jobs (default 2)
#     --keep         keep the scratch folder (printed at the end; each mutant's
#                    ctest output, with the failing tests' messages, is NAME.txt there)
#     --skip-clean   do not run the tests on the clean copy first (only right after a
#                    clean run of the same commit: a test failing there would be
#                    counted as a catch)
#
# The copy is built once clean and its suite run once (a test that fails there is a
# failure of the tree, not a catch: the bench stops). Each mutant then changes its one
# file, is rebuilt incrementally, tested, and the file is put back from the archive.
# A mutation whose sed changes nothing is an error (exit 2): the list must follow the
# code. A mutant that does not build counts as an error too, not as a catch.
# Exit status: 0 when every mutant was caught, 1 when one survived, 2 on errors.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
repo="$(cd "$here/.." && pwd)"
list="$here/mutations.list"
only=() tests="" expected=0 jobs=1 keep=0 skip_clean=0
while [ $# -gt 0 ]; do
  case "$1" in
    --only) only+=("$2"); shift 2 ;;
    --tests) tests="$2"; shift 2 ;;
    --expected) expected=1; shift ;;
    -j) jobs="$2"; shift 2 ;;
    --keep) keep=1; shift ;;
    --skip-clean) skip_clean=1; shift ;;
    -h|--help) sed -n '2,27p' "$0"; exit 0 ;;
    *) echo "mutation.sh: unknown option '$1'" >&2; exit 2 ;;
  esac
done

# The list as one record per line: name<TAB>file<TAB>sed<TAB>catch<TAB>breaks.
records="$(awk '
  function flush() { if (name != "") print name "\t" file "\t" sedx "\t" catch "\t" breaks;
                     name = file = sedx = catch = breaks = "" }
  /^#/ { next }
  /^[[:space:]]*$/ { flush(); next }
  { key = $1; sub(/^[a-z]+:[[:space:]]*/, "") }
  key == "name:" { name = $0 } key == "file:" { file = $0 } key == "sed:" { sedx = $0 }
  key == "catch:" { catch = $0 } key == "breaks:" { breaks = $0 }
  END { flush() }' "$list")"
[ -n "$records" ] || { echo "mutation.sh: no mutations in $list" >&2; exit 2; }
if [ ${#only[@]} -gt 0 ]; then
  for n in "${only[@]}"; do
    grep -q "^$n	" <<<"$records" || { echo "mutation.sh: no mutation '$n' in $list" >&2; exit 2; }
  done
  records="$(awk -F'\t' -v names=" ${only[*]} " 'index(names, " " $1 " ")' <<<"$records")"
fi

work="$(mktemp -d /tmp/fsi-mutation.XXXXXX)"
cleanup() { [ "$keep" = 1 ] || rm -rf "$work"; }
trap cleanup EXIT
mkdir -p "$work/src" "$work/pristine"
cd "$work"
git -C "$repo" archive HEAD | tar -x -C "$work/src"
git -C "$repo" archive HEAD | tar -x -C "$work/pristine"
commit="$(git -C "$repo" rev-parse --short HEAD)"
echo "mutation bench: commit $commit, $(wc -l <<<"$records") mutants, scratch $work" >&2

build() {
  cmake -S "$work/src" -B "$work/build" -DCMAKE_BUILD_TYPE=Release >"$work/cmake.txt" 2>&1 &&
    cmake --build "$work/build" -j2 >"$work/build.txt" 2>&1
}
# run_tests REGEX OUT: ctest with REGEX (empty: all); prints the failed tests' names.
run_tests() {
  local regex="$1" out="$2"
  (cd "$work/build" && ctest ${regex:+-R "$regex"} -j "$jobs" --output-on-failure >"$out" 2>&1) || true
  awk '/The following tests FAILED:/ {f = 1; next}
       f && /^[[:space:]]*[0-9]+ - / {print $3}' "$out"
}

start=$(date +%s)
build || { tail -20 "$work/build.txt"; echo "mutation.sh: the clean tree does not build" >&2; exit 2; }
if [ "$expected" = 1 ]; then
  clean_regex="$(cut -f4 <<<"$records" | paste -sd'|')"
else
  clean_regex="$tests"
fi
if [ "$skip_clean" = 1 ]; then
  echo "clean tree: built, its tests not run (--skip-clean)" >&2
else
  clean_failed="$(run_tests "$clean_regex" "$work/clean.txt")"
  if [ -n "$clean_failed" ]; then
    echo "mutation.sh: the clean tree fails: $clean_failed (see $work/clean.txt)" >&2
    keep=1
    exit 2
  fi
  grep -q "tests passed" "$work/clean.txt" || { cat "$work/clean.txt" >&2; exit 2; }
  echo "clean tree: $(grep 'tests passed' "$work/clean.txt") in $(( $(date +%s) - start )) s" >&2
fi

rows="" killed=0 total=0 errors=0
while IFS=$'\t' read -r name file sedx catch breaks; do
  total=$((total + 1))
  t0=$(date +%s)
  target="$work/src/$file"
  if [ ! -f "$target" ]; then
    echo "mutation.sh: $name: no file $file" >&2
    errors=$((errors + 1)); rows+="| $name | \`$file\` | $breaks | ERROR: no such file | |"$'\n'; continue
  fi
  sed -e "$sedx" "$work/pristine/$file" >"$target"
  if cmp -s "$target" "$work/pristine/$file"; then
    echo "mutation.sh: $name: the sed expression changes nothing in $file" >&2
    errors=$((errors + 1)); rows+="| $name | \`$file\` | $breaks | ERROR: does not apply | |"$'\n'; continue
  fi
  if ! build; then
    echo "mutation.sh: $name: does not build (see $work/build.txt)" >&2
    cp "$work/pristine/$file" "$target"
    errors=$((errors + 1)); rows+="| $name | \`$file\` | $breaks | ERROR: does not build | |"$'\n'; continue
  fi
  regex="$tests"
  [ "$expected" = 1 ] && regex="$catch"
  failed="$(run_tests "$regex" "$work/$name.txt")"
  cp "$work/pristine/$file" "$target"
  if [ -n "$failed" ]; then
    killed=$((killed + 1))
    verdict="$(paste -sd' ' <<<"$failed" | sed 's/ /, /g')"
  else
    verdict="**survived**"
  fi
  seconds=$(( $(date +%s) - t0 ))
  echo "$name: ${verdict} ($seconds s)" >&2
  rows+="| $name | \`$file\` | $breaks | $verdict | $seconds |"$'\n'
done <<<"$records"
# Leave the copy's build as clean as it started (for --keep).
build || true

scope="the whole suite"
[ -n "$tests" ] && scope="tests matching \`$tests\`"
[ "$expected" = 1 ] && scope="each mutant's own 'catch:' tests"
[ "$skip_clean" = 1 ] && scope="$scope (clean run skipped)"
echo
echo "Mutation bench, commit $commit, $(date -u +%Y-%m-%d), $scope, $(( $(date +%s) - start )) s:"
echo
echo "| mutant | file | breaks | caught by | s |"
echo "|---|---|---|---|---|"
printf '%s' "$rows"
echo
rate="$(awk -v k=$killed -v t=$total 'BEGIN {printf "%.0f", t ? 100 * k / t : 0}')"
if [ "$errors" -gt 0 ]; then
  echo "Killed $killed of $total ($rate %); $errors error(s)."
else
  echo "Killed $killed of $total ($rate %)."
fi
[ "$keep" = 1 ] && echo "scratch folder kept: $work" >&2
[ "$errors" -gt 0 ] && exit 2
[ "$killed" -eq "$total" ] || exit 1
exit 0
