#!/usr/bin/env bash
# Generated and quoted documentation matches the code:
#  (a) docs/cases.md is exactly what `fsi keys` prints from the key tables;
#  (b) the first ```c block of docs/participant_api.md is examples/dashpot_fluid.c,
#      byte for byte.
source "$(dirname "$0")/lib.sh"

# (a) the case-file reference
cases_md="$FSI_SOURCE_DIR/docs/cases.md"
[ -x "$FSI_BIN_DIR/fsi-keys" ] || fail "$FSI_BIN_DIR/fsi-keys is missing (build the fsi-keys target)"
[ -f "$cases_md" ] || fail "docs/cases.md is missing: generate it with ./fsi keys > docs/cases.md"
"$FSI_BIN_DIR/fsi-keys" >cases.generated.md || fail "fsi-keys failed"
if ! cmp -s "$cases_md" cases.generated.md; then
  diff -u "$cases_md" cases.generated.md || true
  fail "docs/cases.md differs from the key tables in the code: regenerate with ./fsi keys > docs/cases.md"
fi
pass "docs/cases.md matches fsi keys"

# (b) the example quoted in the participant API guide
api_md="$FSI_SOURCE_DIR/docs/participant_api.md"
example="$FSI_SOURCE_DIR/examples/dashpot_fluid.c"
[ -f "$api_md" ] || fail "docs/participant_api.md is missing"
# Lines strictly between the first line that is exactly ```c and the next line
# that is exactly ``` (trailing blanks and CR tolerated on the fence lines only).
awk '
  state == 0 && /^```c[ \t\r]*$/ { state = 1; next }
  state == 1 && /^```[ \t\r]*$/  { state = 2; exit }
  state == 1                     { print }
  END { if (state != 2) exit 1 }
' "$api_md" >quoted_example.c || fail "docs/participant_api.md has no complete \`\`\`c block"
if ! cmp -s "$example" quoted_example.c; then
  diff -u "$example" quoted_example.c || true
  fail "the first \`\`\`c block of docs/participant_api.md differs from examples/dashpot_fluid.c: paste the file in again"
fi
pass "docs/participant_api.md quotes examples/dashpot_fluid.c verbatim"
