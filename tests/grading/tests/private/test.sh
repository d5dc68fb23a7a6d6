#!/usr/bin/env bash
# Private tests end to end (tests/grading/README.md, "Private tests"), and the proof that nothing
# of them but a name and a verdict reaches a student:
#
#   test.sh <root> <work> <grading_class>
#
# The private folder lives outside the workbook, in a path with spaces, and holds this folder's
# rotation_test.cpp, whose source, inputs (37.28125, 611.40625) and expected values carry
# markers. `cmake/workbook gradescope --private-tests` packs it; setup.sh builds it into the
# judges from the zip; run_autograder grades a submission that fails the private tests (and
# prints and throws their inputs) and one that passes them. Then `cmake/workbook grade
# --private-tests` and `workbook_grade grade --private-feedback total` grade the same two on the
# same build, and `workbook_grade check` (a student's check) runs on it. Every student-visible
# file (results/*.json and .tsv, summary.md, class.csv, the LMS files, the similarity report,
# Gradescope's results.json) must hold no byte of any marker, while the staff log has them; a
# planted fault (WORKBOOK_GRADING_PLANT=leak-private: the detail left in the results) must be
# caught by the same scan. Last, the build refuses a private test on no exercise, one with a public
# test's name, and one that fails on the reference solution.
set -euo pipefail
root=$1 work=$2 class_tool=$3
fail() { echo "FAILED: $*" >&2; exit 1; }
# The markers: the source's strings, and the decimal forms of the private inputs and expected
# values (37.28125 and 611.40625 print as 37.2812, 37.28125, 611.406, 611.406250, ...).
markers=(-e PRIVATE-MARKER -e 37.281 -e 611.40 -e '37,281' -e '611,40')
# leaks <file or folder>...: the files that hold a marker (none: status 1).
leaks() { grep -r -l -F -a "${markers[@]}" "$@"; }

rm -rf "$work" && mkdir -p "$work/autograder/source"
private="$work/private tests (the instructor's)"  # outside the workbook, with spaces (not a comma:
                                                  # doctest's file filter cannot take one)
mkdir -p "$private" && cp "$root/tests/grading/tests/private/rotation_test.cpp" "$private/"

# The two submissions: the reference, and one that passes every public test but fails the two
# private ones (its hat is wrong, and its vee throws, only on inputs as large as theirs), while
# it prints one private input and throws the other.
mkdir -p "$work/class/passes/exercises" "$work/class/fails/exercises"
cp "$root/solutions/rotation.cpp" "$work/class/passes/exercises/rotation.cpp"
sed -e '1i #include <cstdio>\n#include <stdexcept>\n#include <string>' \
    -e '0,/^    return W;$/s//    std::printf("hat was given %.17g and %g\\n", w.z(), w.z());\n    return w.z() > 30 ? Mat3(W.transpose()) : W;/' \
    -e 's/^\(    return 0.5 \* Vec3(W(2, 1) - W(1, 2).*\)$/    if (W(2, 1) > 600) throw std::runtime_error("vee was given " + std::to_string(W(2, 1)));\n\1/' \
    "$root/solutions/rotation.cpp" > "$work/class/fails/exercises/rotation.cpp"
grep -q 'w.z() > 30' "$work/class/fails/exercises/rotation.cpp" && grep -q 'vee was given' "$work/class/fails/exercises/rotation.cpp" ||
  fail "the failing submission was not made (solutions/rotation.cpp changed?)"

echo "== cmake/workbook gradescope --private-tests (a folder outside the workbook, with spaces)"
"$root/cmake/workbook" gradescope --private-tests "$private" --private-feedback names rotation
(cd "$work/autograder/source" && cmake -E tar xf "$root/build/gradescope/autograder.zip")
cmp -s "$private/rotation_test.cpp" "$work/autograder/source/private/rotation_test.cpp" || fail "the zip has no private/rotation_test.cpp"
grep -qx 'PRIVATE_TESTS="private"' "$work/autograder/source/gradescope.conf" || fail "gradescope.conf does not name private/"
cp "$work/autograder/source/run_autograder" "$work/autograder/run_autograder"
start=$(date +%s)
AUTOGRADER_ROOT=$work/autograder JOBS=${JOBS:-2} bash "$work/autograder/source/setup.sh" > "$work/setup.txt" 2>&1 ||
  { tail -n 30 "$work/setup.txt"; fail "setup.sh failed"; }
echo "   setup.sh built the graders and the private tests in $(( $(date +%s) - start )) s"
build=$work/autograder/source/workbook/build
awk -F'\t' '$1 == "private" && $3 == "hat" && $5 == "hat: a private case the students have not seen" { found = 1 } END { exit !found }' \
  "$build/grading/manifest.txt" || fail "the manifest does not list the private test of hat"
[[ $(stat -c %a "$work/autograder/source/private") == 700 ]] || fail "setup.sh left private/ readable by others"

# gradescope <case> <score>: run_autograder on class/<case>; its results.json in Gradescope's format.
gradescope() {
  local name=$1 score=$2 ag=$work/autograder
  rm -rf "$ag/submission" "$ag/results" && cp -R "$work/class/$name" "$ag/submission"
  AUTOGRADER_ROOT=$ag "$ag/run_autograder" > "$work/gradescope-$name.stdout.txt" 2>&1 || fail "$name: run_autograder failed"
  cp "$ag/results/results.json" "$work/gradescope-$name.json"
  "$class_tool" schema "$work/gradescope-$name.json" --score "$score" --max-score 11 || fail "$name: results.json is wrong"
}
fails_score=10.3332  # 11 points but the private tests' shares of hat's and vee's (0.3334 each: 3 tests)
gradescope passes 11
gradescope fails "$fails_score"
grep -q '"name": "hat: a private case the students have not seen"' "$work/gradescope-fails.json" ||
  fail "Gradescope's results.json does not name the private test (--private-feedback names)"
grep -q 'a private test: what it checks' "$work/gradescope-fails.json" || fail "the failed private test does not say why nothing is shown"
if leaks "$work/gradescope-fails.json" "$work/gradescope-passes.json"; then fail "a private marker reached Gradescope's results.json (above)"; fi
leaks "$work/gradescope-fails.stdout.txt" >/dev/null || fail "the autograder's output (staff only) has not the private detail"

# student_files <out>: every file of a grading run's out folder but the staff's (logs/, the lock,
# run.json and the manifest copy, which names the private file).
student_files() { find "$1" -type f ! -path "$1/logs/*" ! -path "$1/.*" ! -name run.json ! -name manifest.txt; }

echo "== the manual's commands as written (total), in the zip's copy of the workbook, on the same build"
marker="<!-- run by test: grading: private tests are graded, and nothing of their source or expected values reaches a student -->"
mapfile -t recipe < <(python3 "$root/cmake/checks/readme/readme.py" block "$root/tests/grading/README.md" "$marker")
[[ ${#recipe[@]} -eq 2 ]] || fail "tests/grading/README.md has not the two commands of private tests"
wb=$work/autograder/source/workbook
rm -rf "$wb/submissions" "$wb/grades" && cp -R "$work/class" "$wb/submissions"
(cd "$wb" && export PRIVATE=$private WORKBOOK_BUILD=$build WORKBOOK_GRADING_TOPICS=rotation JOBS=${JOBS:-2} &&
  eval "${recipe[0]}" > "$work/total.txt" 2>&1) || { tail -n 20 "$work/total.txt"; fail "${recipe[0]}: failed"; }
mapfile -t files < <(student_files "$wb/grades")
[[ ${#files[@]} -ge 8 ]] || fail "the run wrote ${#files[@]} student-visible files, not every one"
if leaks "${files[@]}"; then fail "a private marker reached a student-visible file (above)"; fi
leaks "$wb/grades/logs/fails/private.txt" >/dev/null || fail "the staff log has not the private detail"
for m in qz7-PRIVATE-MARKER-info 'hat was given 37.28125' 'vee was given 611.406250' 'Approx( 37.2812 )'; do
  grep -q -F "$m" "$wb/grades/logs/fails/private.txt" || fail "the staff log lacks '$m'"
done
# The item analysis (item_analysis.*, class_report.html and its report/) is the instructor's view
# of every test, the private ones by name: it is scanned for markers above, not for names.
mapfile -t named < <(printf '%s\n' "${files[@]}" | grep -v -e '/item_analysis\.' -e '/class_report\.html$' -e '/report/')
if grep -l -F -e 'a private case the students' -e 'a second private case' "${named[@]}"; then
  fail "--private-feedback total names a private test (above)"
fi
grep -q '"name": "hat: private tests"' "$wb/grades/results/fails.json" && grep -q '0 of 1 private tests pass' "$wb/grades/results/fails.json" ||
  fail "--private-feedback total gives no total for hat's private tests"
"$class_tool" schema "$wb/grades/results/fails.json" --score "$fails_score" --max-score 11 || fail "the total's results.json is wrong"
(cd "$wb" && export PRIVATE=$private && eval "${recipe[1]}" > "$work/pack.txt" 2>&1) || { cat "$work/pack.txt"; fail "${recipe[1]}: failed"; }
cmake -E tar tf "$wb/build/gradescope/autograder.zip" | grep -qx 'private/rotation_test.cpp' || fail "${recipe[1]}: no private/ in the zip"

echo "== workbook_grade grade, private tests by name"
"$build/grading/workbook_grade" grade --setup "$build/grading" -j "${JOBS:-2}" "$work/class" "$work/names" > "$work/names.txt" 2>&1 ||
  { cat "$work/names.txt"; fail "grade (names) failed"; }
mapfile -t files < <(student_files "$work/names")
if leaks "${files[@]}"; then fail "a private marker reached a student-visible file (above)"; fi
grep -q '"name": "vee: a second private case"' "$work/names/results/fails.json" || fail "results json does not name the private test"

echo "== the planted fault: a hook that leaves the private detail in the results is caught"
WORKBOOK_GRADING_PLANT=leak-private "$build/grading/workbook_grade" grade --setup "$build/grading" -j "${JOBS:-2}" \
  "$work/class" "$work/planted" > "$work/planted.txt" 2>&1 || { cat "$work/planted.txt"; fail "the planted run failed"; }
mapfile -t files < <(student_files "$work/planted")
leaks "${files[@]}" > "$work/planted-leaks.txt" || fail "the scan did not catch the planted leak: it proves nothing"
echo "   caught in: $(paste -sd' ' "$work/planted-leaks.txt" | sed "s|$work/planted/||g")"

echo "== a student's check never grades private tests: the file that fails only them passes"
"$build/grading/workbook_grade" check --setup "$build/grading" --folder "$work/class/fails/exercises" \
  --out "$work/check" > "$work/check.txt" 2>&1 || { cat "$work/check.txt"; fail "check failed a file that passes every public test"; }
grep -q 'All 11 exercises pass' "$work/check.txt" || { cat "$work/check.txt"; fail "check did not grade all of rotation"; }
if leaks "$work/check.txt" "$work/check/results.json" ||
   grep -F -e 'private case' -e 'a private test' -e 'private tests' "$work/check.txt" "$work/check/results.json"; then fail "check graded or named a private test (above)"; fi
[[ ! -e $work/check/logs/private.txt ]] || fail "check wrote a private log"
echo "== a private test the manifest refuses: on no exercise, a public test's name, failing the reference"
# bad <case> <listing line> <exit status> <words>: the manifest made with a stand-in for the private
# reference that lists that test and ends with that status must fail, saying the words.
bad() {
  local name=$1 listing=$2 status=$3 words=$4 fake=$work/bad-$1.sh
  printf '#!/bin/sh\ncase "$*" in *--list-test-cases*) echo '\''%s'\'' ; exit 0 ;; esac\nexit %s\n' "$listing" "$status" > "$fake"
  chmod +x "$fake"
  sed "s|^private\t.*|private\t$fake|" "$build/grading/topics.txt" > "$work/bad-$name.topics.txt"
  grep -q "^private	$fake" "$work/bad-$name.topics.txt" || fail "$name: topics.txt has no private line to replace"
  if "$build/grading/workbook_grade" manifest --topics "$work/bad-$name.topics.txt" --points "$root/tests/grading/points.txt" \
       --out "$work/bad-$name.manifest.txt" > "$work/bad-$name.txt" 2>&1; then
    fail "$name: the manifest took it"
  fi
  grep -q -F "$words" "$work/bad-$name.txt" || { cat "$work/bad-$name.txt"; fail "$name: the build's error does not say '$words'"; }
}
bad no_exercise '{"test":"spin: not an exercise","file":"/p/rotation_test.cpp","line":3}' 0 'names no exercise of rotation'
bad public_name '{"test":"hat: entries follow the Levi-Civita form hat_ij = -eps_ijk w_k","file":"/p/rotation_test.cpp","line":3}' 0 "has a public test's name"
bad fails_reference '{"test":"hat: fine","file":"/p/rotation_test.cpp","line":3}' 1 'fails on the reference solution'

echo "== private tests: graded in Gradescope and in grade (names, total); no marker in any student-visible file; the planted leak caught; check never runs them; the manifest refuses the three bad ones"
