#!/usr/bin/env bash
# A solver written elsewhere builds against an installed copy and runs coupled:
# `cmake --install` into a scratch prefix, the example participants built out of the
# tree with find_package(fsi) (and the example fluid once more with pkg-config and
# plain cc), then the installed fsi-run runs the demo with those programs as
# `solver = external` and must give the same results as the project's own build.
source "$(dirname "$0")/lib.sh"
build_dir="$(dirname "$FSI_BIN_DIR")"
prefix="$FSI_TEST_TMP/prefix"

cmake --install "$build_dir" --prefix "$prefix" >install.txt 2>&1 || { cat install.txt; fail "cmake --install failed"; }
for f in bin/fsi-run bin/fsi-coupler bin/fsi-record lib/libfsi_participant.a \
         include/fsi/participant.h lib/pkgconfig/fsi-participant.pc \
         lib/cmake/fsi/fsiConfig.cmake lib/cmake/fsi/fsiConfigVersion.cmake \
         share/fsi/python/fsi_traffic.py share/fsi/python/fsi/step_t.py; do
  [ -e "$prefix/$f" ] || fail "not installed: $f"
done
# The installed fsi-run finds every solver program beside itself.
"$prefix/bin/fsi-solvers" >solvers.txt || fail "installed fsi-solvers failed"
missing=$(awk '$1 == "fluid" || $1 == "solid"' solvers.txt | awk '$NF != "yes"' | wc -l)
[ "$missing" -eq 0 ] || fail "installed fsi-solvers finds $missing programs missing: $(cat solvers.txt)"
"$prefix/bin/fsi-spy" --help >/dev/null || fail "installed fsi-spy --help failed"
if [ -f "$build_dir/java/fsi_lcmtypes.jar" ]; then
  [ -f "$prefix/share/fsi/java/fsi_lcmtypes.jar" ] || fail "the Java types were built but not installed"
fi
pass "installed: programs, library, headers, pkg-config file, CMake package, Python types"

# Every installed header compiles on its own (they include nothing that is not installed).
for h in "$prefix"/include/fsi/*.h; do
  echo "#include \"${h##*/}\"" | cc -std=c11 -Wall -Wextra -Werror -fsyntax-only \
    -I"$prefix/include/fsi" -x c - 2>header.txt || { cat header.txt; fail "${h##*/} does not compile alone"; }
done
pass "each installed header is self-contained"

# Out of the tree, with find_package(fsi): a copy of examples/ far from the source.
cp -r "$FSI_SOURCE_DIR/examples" examples
cmake -S examples -B examples-build -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_BUILD_TYPE=Release \
  >configure.txt 2>&1 || { cat configure.txt; fail "configuring examples/ against the install failed"; }
cmake --build examples-build >build.txt 2>&1 || { cat build.txt; fail "building examples/ against the install failed"; }
for p in fsi-spring-solid fsi-dashpot-fluid; do
  [ -x "examples-build/$p" ] || fail "examples-build/$p was not built"
done
pass "examples/ built out of the tree with find_package(fsi)"

# With pkg-config and the C compiler alone.
export PKG_CONFIG_PATH="$prefix/lib/pkgconfig"
# shellcheck disable=SC2046  # pkg-config's flags are meant to split into words
cc -std=c11 -O2 -Wall -Wextra -Werror $(pkg-config --cflags fsi-participant) \
  examples/dashpot_fluid.c $(pkg-config --libs fsi-participant) -o dashpot-pkg-config \
  2>cc.txt || { cat cc.txt; fail "cc with pkg-config fsi-participant failed"; }
pass "example fluid built with pkg-config fsi-participant"

# The demo with those programs, by the installed fsi-run, against the project's build.
small_case builtin.ini 0.3
sed -e "s|^solver = spring_oscillators|solver = external\nexecutable = $PWD/examples-build/fsi-spring-solid|" \
    -e "s|^solver = linear_dashpot|solver = external\nexecutable = $PWD/REPLACE_FLUID|" builtin.ini >template.ini
sed "s|REPLACE_FLUID|examples-build/fsi-dashpot-fluid|" template.ini >cmake.ini
sed "s|REPLACE_FLUID|dashpot-pkg-config|" template.ini >pkg-config.ini
grep -q "^solver = external" cmake.ini || fail "test case not rewritten: $(cat cmake.ini)"
"$FSI_RUN" builtin.ini --out builtin >builtin.txt 2>&1 || { cat builtin.txt; fail "in-tree run failed"; }
for run in cmake pkg-config; do
  "$prefix/bin/fsi-run" "$run.ini" --out "$run" --log-traffic --set run.window_timeout=20 >"$run.txt" 2>&1 \
    || { cat "$run.txt" "$run"/*.log; fail "installed fsi-run with the $run-built programs failed"; }
  grep -q "^exit = ok" "$run/run.log" || fail "$run: run.log does not say exit = ok: $(grep "^exit" "$run/run.log")"
  output_readable "$run" solid fluid || fail "$run: output not readable"
  same_results builtin "$run"
done
rows=$(($(wc -l <cmake/probes.csv) - 1))
pass "installed fsi-run ran the out-of-tree programs: finished, $rows probe rows, results identical to the project's build"

# The installed Python types read the installed fsi-run's traffic log (recorded by the
# installed fsi-record): one FSI_STEP per window, as run.log counts them.
windows=$(awk '$1 == "windows" {print $3}' cmake/run.log)
steps=$(PYTHONPATH="$prefix/share/fsi/python" /usr/bin/python3 -m fsi_traffic cmake/traffic.lcmlog \
  | awk '$3 == "FSI_STEP"' | wc -l)
[ "$steps" -eq $((windows + 1)) ] || fail "installed fsi_traffic.py: $steps FSI_STEP lines for $windows windows"
pass "the installed Python reader decodes the installed run's traffic log ($steps grants for $windows windows)"
