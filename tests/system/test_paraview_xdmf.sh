#!/usr/bin/env bash
# ParaView reads the particle output of core/h5_output: the unit test
# test_h5_output writes particles.h5/.xmf, then pvbatch opens the .xmf and
# paraview_check_xdmf.py compares time steps, point counts, fields and values.
set -euo pipefail

: "${FSI_SOURCE_DIR:?FSI_SOURCE_DIR not set}"
: "${FSI_BIN_DIR:?FSI_BIN_DIR not set}"
: "${FSI_TEST_TMP:?FSI_TEST_TMP not set}"

fail() {
    echo "test_paraview_xdmf: FAIL: $*" >&2
    exit 1
}

command -v pvbatch >/dev/null 2>&1 ||
    fail "pvbatch not found; install ParaView by running launch/setup.sh"
command -v h5dump >/dev/null 2>&1 ||
    fail "h5dump not found; install hdf5-tools by running launch/setup.sh"

writer="$FSI_BIN_DIR/../tests/test_h5_output"
[[ -x $writer ]] || fail "$writer not found; build the tree first"

mkdir -p "$FSI_TEST_TMP"
rm -rf "$FSI_TEST_TMP/h5_output" "$FSI_TEST_TMP/h5_output_again"
log="$FSI_TEST_TMP/test_h5_output.log"
if ! FSI_TEST_TMP="$FSI_TEST_TMP" "$writer" >"$log" 2>&1; then
    cat "$log" >&2
    fail "$writer failed, so there is nothing to open in ParaView"
fi

h5="$FSI_TEST_TMP/h5_output/particles.h5"
xmf="$FSI_TEST_TMP/h5_output/particles.xmf"
dim=$(h5dump -a /dimension "$h5" | sed -n 's/.*(0): *\([0-9]*\).*/\1/p')
[[ $dim == 2 || $dim == 3 ]] || fail "cannot read the dimension attribute of $h5"

# Expected values: the formulas of tests/unit/test_h5_output.c evaluated by hand
# (times 0.5 + 0.75 f; position 10f + i + 0.25c; pressure 1000f + i + 0.5;
# velocity -(100f + 10i + c) - 0.125; stress 1000f + 10i + c + 0.75; material 7f + i).
# Only components 0..1 (vector) and 0..3 (tensor) are used, valid in 2-D and 3-D.
if ! pvbatch "$FSI_SOURCE_DIR/tests/system/paraview_check_xdmf.py" "$xmf" \
    --dim "$dim" --times 0.5,1.25,2 --counts 5,5,7 \
    --fields pressure:scalar,velocity:vector,stress:tensor,material:scalar \
    --point 0:0=0,0.25 --point 2:6=26,26.25 \
    --value 0:pressure:0:0=0.5 --value 2:pressure:6:0=2006.5 \
    --value 1:velocity:4:1=-141.125 --value 2:velocity:6:0=-260.125 \
    --value 0:stress:1:1=11.75 --value 2:stress:6:3=2063.75 \
    --value 1:material:0:0=7 --value 2:material:6:0=20; then
    fail "ParaView does not read $xmf as written (see the messages above)"
fi
echo "test_paraview_xdmf: OK"
