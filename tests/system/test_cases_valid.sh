#!/usr/bin/env bash
# Every case shipped in cases/ passes `fsi run --check` (exit 0, nothing written): a
# renamed key or a changed rule must not leave a broken example behind.
source "$(dirname "$0")/lib.sh"
n=0
for c in "$FSI_SOURCE_DIR"/cases/*.ini; do
  out="check_$(basename "$c" .ini)"
  "$FSI_RUN" "$c" --check --out "$out" >"$out.txt" 2>&1 || { cat "$out.txt"; fail "$c does not validate"; }
  [ ! -e "$out" ] || fail "--check wrote output for $c"
  n=$((n + 1))
done
[ "$n" -ge 6 ] || fail "only $n cases found in $FSI_SOURCE_DIR/cases"
pass "all $n cases in cases/ validate"
