#!/usr/bin/env bash
# The output folder (README: --out, --force):
#  (a) --force replaces the files a run writes, by name, and nothing else; a folder
#      holding only the user's own files is not an earlier run's;
#  (b) a second run into a folder where a run is going is refused (status 2) with
#      the first run's pid, and the first run's files stay intact;
#  (c) --out naming a file, a path through a file, or a folder without read
#      permission: status 2, a message naming the path and the reason, nothing
#      created (fsi run and fsi replay).
source "$(dirname "$0")/lib.sh"
REPLAY="$FSI_BIN_DIR/fsi-replay"
small_case case.ini 0.1
small_case long.ini 60

run_id() { awk '$1 == "run_id" {print $3; exit}' "$1/run.log"; }

# (a) the user's files beside an earlier run's; stale temporaries and frame folders
# of a run that was killed (named as the parallel per-frame output names them).
"$FSI_RUN" case.ini --out forced >forced1.txt 2>&1 || { cat forced1.txt; fail "first run failed"; }
echo "t,x" >forced/measurements.csv
echo "my notes" >forced/notes.log
printf '\x89PNG user' >forced/photo.png
mkdir forced/mine && echo keep >forced/mine/solid.h5
: >forced/solid.xmf.tmp
: >forced/c1_elastic_plate.png   # what `fsi main` adds to its run's folder
: >forced/fluid.h5.tmp
mkdir -p forced/fluid.frames forced/solid.frames
: >forced/fluid.frames/000099.h5   # frame numbers and a count the new run does not write
: >forced/fluid.frames/static.h5
: >forced/fluid.frames/vertices_77.h5
: >forced/fluid.frames/000004.h5.tmp
: >forced/solid.frames/000098.h5
echo mine >forced/solid.frames/my_notes.txt
cp -r forced user_copy
first_id=$(run_id forced)

set +e
"$FSI_RUN" case.ini --out forced >forced2.txt 2>&1
status=$?
set -e
[ "$status" -eq 2 ] || { cat forced2.txt; fail "a second run without --force: status $status, expected 2"; }
grep -q "holds results of an earlier run" forced2.txt || { cat forced2.txt; fail "no 'earlier run' message"; }
[ "$(run_id forced)" = "$first_id" ] || fail "a refused run changed run.log"

"$FSI_RUN" case.ini --out forced --force >forced3.txt 2>&1 || { cat forced3.txt; fail "--force run failed"; }
for f in measurements.csv notes.log photo.png mine/solid.h5 solid.frames/my_notes.txt; do
  cmp -s "user_copy/$f" "forced/$f" || fail "--force removed or changed the user's $f"
done
[ "$(run_id forced)" != "$first_id" ] || fail "--force did not replace run.log"
for f in solid.xmf.tmp fluid.h5.tmp c1_elastic_plate.png fluid.frames/000099.h5 \
         fluid.frames/vertices_77.h5 fluid.frames/000004.h5.tmp solid.frames/000098.h5; do
  [ ! -e "forced/$f" ] || fail "--force left the earlier run's $f"
done
h5dump -H forced/solid.h5 >/dev/null || fail "solid.h5 of the --force run unreadable"
pass "--force replaced the run's files and kept measurements.csv, notes.log, photo.png, mine/, solid.frames/my_notes.txt"

mkdir users
cp user_copy/measurements.csv user_copy/notes.log user_copy/photo.png users/
"$FSI_RUN" case.ini --out users >users.txt 2>&1 ||
  { cat users.txt; fail "a folder with only the user's files was taken for an earlier run"; }
cmp -s user_copy/notes.log users/notes.log || fail "a run changed the user's notes.log"
pass "a folder holding only the user's files is not an earlier run's"

# (b) a second run while the first goes, with and without --force.
"$FSI_RUN" long.ini --out busy >busy1.txt 2>&1 &
first=$!
trap 'kill -TERM $first 2>/dev/null || true' EXIT
wait_under_way busy
first_id=$(run_id busy)
cp busy/case.resolved.ini busy_case_copy.ini
for force in "" --force; do
  set +e
  "$FSI_RUN" case.ini --out busy --set run.title=second $force >busy2.txt 2>&1
  status=$?
  set -e
  [ "$status" -eq 2 ] || { cat busy2.txt; fail "second run ($force) into a busy folder: status $status, expected 2"; }
  grep -q "in use by another run (pid $first)" busy2.txt ||
    { cat busy2.txt; fail "the refusal ($force) does not name the first run's pid $first"; }
done
kill -0 "$first" || fail "the first run ended while the second was refused"
[ "$(run_id busy)" = "$first_id" ] || fail "the refused run changed the first run's run.log"
cmp -s busy/case.resolved.ini busy_case_copy.ini || fail "the refused run changed case.resolved.ini"
[ "$(grep -c '^# fsi run log' busy/run.log)" = 1 ] || fail "run.log was written twice"
kill -INT "$first"
set +e
wait "$first"
set -e
trap - EXIT
grep -q "^exit = failure: interrupted" busy/run.log || fail "the first run's run.log has no exit line"
h5dump -H busy/solid.h5 >/dev/null || fail "the first run's solid.h5 is unreadable"
# The lock ended with the first run: none of its processes keeps it.
"$FSI_RUN" case.ini --out busy --force >busy3.txt 2>&1 ||
  { cat busy3.txt; fail "a run after the first ended was refused"; }
grep -q "^exit = ok" busy/run.log || fail "the run after the first did not finish"
pass "a second run into a busy folder is refused naming pid $first; the first run's files intact"

# (c) unusable output folders.
refused() {   # refused NAME PATH TEXT command...
  local name="$1" path="$2" text="$3"
  shift 3
  set +e
  "$@" >"bad-$name.txt" 2>&1
  local status=$?
  set -e
  [ "$status" -eq 2 ] || { cat "bad-$name.txt"; fail "$name: status $status, expected 2"; }
  grep -qF "$path" "bad-$name.txt" || { cat "bad-$name.txt"; fail "$name: the message does not name $path"; }
  grep -q "$text" "bad-$name.txt" || { cat "bad-$name.txt"; fail "$name: the message does not say '$text'"; }
  pass "$name refused: $(head -n 1 "bad-$name.txt")"
}
echo "a file" >plain_file
cp plain_file plain_copy
refused out_is_file plain_file "Not a directory" "$FSI_RUN" case.ini --out plain_file
refused out_is_file_force plain_file "Not a directory" "$FSI_RUN" case.ini --out plain_file --force
refused out_below_file plain_file/sub "Not a directory" "$FSI_RUN" case.ini --out plain_file/sub
cmp -s plain_file plain_copy || fail "the file named by --out was changed"

# A folder without read permission; root reads every folder, so as root the run is
# made as 'nobody' in a folder of its own.
mkdir unreadable
chmod 0300 unreadable
as_user=()
if [ "$(id -u)" = 0 ]; then
  command -v setpriv >/dev/null || fail "running as root, the unreadable-folder check needs setpriv"
  chown nobody unreadable
  as_user=(setpriv --reuid=nobody --regid=nogroup --clear-groups)
fi
refused out_unreadable unreadable "Permission denied" "${as_user[@]}" "$FSI_RUN" case.ini --out unreadable
chmod 0700 unreadable
[ -z "$(ls -A unreadable)" ] || fail "a refused run wrote into the unreadable folder: $(ls -A unreadable)"

# fsi replay shares the folder checks.
"$FSI_RUN" case.ini --out recorded --log-traffic >recorded.txt 2>&1 || { cat recorded.txt; fail "recording failed"; }
refused replay_out_is_file plain_file "Not a directory" "$REPLAY" recorded --participant solid --out plain_file
mkdir replayed && echo "my notes" >replayed/notes.log
"$REPLAY" recorded --participant solid --out replayed >replay1.txt 2>&1 || { cat replay1.txt; fail "replay failed"; }
"$REPLAY" recorded --participant solid --out replayed --force >replay2.txt 2>&1 || { cat replay2.txt; fail "replay --force failed"; }
cmp -s user_copy/notes.log replayed/notes.log || fail "fsi replay --force removed the user's notes.log"
pass "fsi replay: --out a file refused; --force keeps the user's notes.log"
