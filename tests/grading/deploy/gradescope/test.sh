#!/usr/bin/env bash
# The Gradescope autograder end to end, as Gradescope runs it, in a folder laid out like
# /autograder (AUTOGRADER_ROOT moves it):
#
#   test.sh <root> <work> <grading_class>
#
# `cmake/workbook gradescope rotation` writes build/gradescope/autograder.zip; it is unpacked
# into <work>/autograder/source, run_autograder is copied to <work>/autograder/ and setup.sh
# runs (it installs nothing that is already here and builds the graders of rotation from the
# zip's own copy of the workbook). Then run_autograder grades a correct submission (in
# exercises/), the untouched stub (the .cpp alone), a file that does not compile and an empty
# submission, and once more with no graders built at all; every results.json must follow
# Gradescope's format (grading_class schema) with the expected score out of 11 (the exercises of rotation.cpp).
set -euo pipefail
root=$1 work=$2 class_tool=$3
fail() { echo "FAILED: $*" >&2; exit 1; }

rm -rf "$work" && mkdir -p "$work/autograder/source" "$work/unbuilt/source"
"$root/cmake/workbook" gradescope rotation
zip=$root/build/gradescope/autograder.zip
(cd "$work/autograder/source" && cmake -E tar xf "$zip")
for f in setup.sh run_autograder gradescope.conf workbook/CMakeLists.txt workbook/solutions/rotation.cpp; do
  [[ -e $work/autograder/source/$f ]] || fail "autograder.zip has no $f at its root"
done
[[ -x $work/autograder/source/run_autograder ]] || fail "run_autograder is not executable in autograder.zip"
grep -qx 'TOPICS="rotation"' "$work/autograder/source/gradescope.conf" || fail "gradescope.conf does not name the topic"
cp "$work/autograder/source/run_autograder" "$work/autograder/run_autograder"

echo "== setup.sh (the graders of rotation, from the zip)"
start=$(date +%s)
AUTOGRADER_ROOT=$work/autograder JOBS=${JOBS:-2} bash "$work/autograder/source/setup.sh" > "$work/setup.txt" 2>&1 ||
  { tail -n 30 "$work/setup.txt"; fail "setup.sh failed"; }
echo "   built in $(( $(date +%s) - start )) s: $(tail -n 1 "$work/setup.txt")"

# grade <case> <autograder root> <score> [<file> <content>]: one submission, then its results.json.
grade() {
  local name=$1 ag=$2 score=$3 file=${4:-} content=${5:-}
  rm -rf "$ag/submission" "$ag/results" && mkdir -p "$ag/submission"
  if [[ -n $file ]]; then mkdir -p "$(dirname "$ag/submission/$file")" && printf '%s' "$content" > "$ag/submission/$file"; fi
  AUTOGRADER_ROOT=$ag "$ag/run_autograder" > "$work/$name.txt" 2>&1 || fail "$name: run_autograder exited with status $?"
  [[ -f $ag/results/results.json ]] || fail "$name: no results.json"
  cp "$ag/results/results.json" "$work/$name.json"
  local max=11
  [[ $ag == "$work/unbuilt" ]] && max=0
  "$class_tool" schema "$ag/results/results.json" --score "$score" --max-score "$max" || fail "$name: results.json is wrong"
}

grade correct "$work/autograder" 11 exercises/rotation.cpp "$(cat "$root/solutions/rotation.cpp")"
# The zip holds no .git: its results still name the commit it was packed from.
if commit=$(git -C "$root" rev-parse HEAD 2>/dev/null); then
  grep -q "\"commit\": \"$commit\"" "$work/correct.json" || fail "correct: results.json does not name the packed commit $commit"
  grep -q '"commit_from": "packed_from.txt' "$work/correct.json" || fail "correct: results.json does not say where its commit came from"
fi
grade stub "$work/autograder" 0 rotation.cpp "$(cat "$root/exercises/rotation.cpp")"
grep -q 'not started' "$work/stub.json" || fail "stub: no test says 'not started'"
grade broken "$work/autograder" 0 exercises/rotation.cpp "$(sed 's/todo("hat");/todo("hat")/' "$root/exercises/rotation.cpp")"
grep -q '"verdict": "build error"' "$work/broken.json" || fail "broken: no build error"
grep -q 'error: expected' "$work/broken.json" || fail "broken: the compiler's error is not shown"
grade empty "$work/autograder" 0
grep -q 'is not in the submission' "$work/empty.json" || fail "empty: the missing file is not named"
cp "$work/autograder/source/run_autograder" "$work/unbuilt/run_autograder"
grade unbuilt "$work/unbuilt" 0 exercises/rotation.cpp "$(cat "$root/solutions/rotation.cpp")"
grep -q 'graders are not built' "$work/unbuilt.json" || fail "unbuilt: results.json does not say why"
echo "== Gradescope: autograder.zip builds; correct 11/11, stub 0, broken 0 (build error), empty 0, no graders 0 (said why); every results.json in Gradescope's format"
