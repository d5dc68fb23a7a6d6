#!/usr/bin/env bash
# Likely mistakes are never given to a correct submission or to an unrelated failure
# (README.md, "Likely mistakes, named"):
#
#   no_false_naming.sh <root> <build> <work>
#
# grades, with an instructor's --seed, a class of rotation.cpp submissions that must get no likely
# mistake: the reference, the three honest solutions of tests/grading/tests/similarity/, the pristine
# stub, a file that does not compile, an empty folder, and the reference with axis_angle made to
# crash (cases/crash.cpp) and compose made to loop (cases/timeout.cpp); and failures that are no
# mistake of the catalogue's: an exit(0) in a test, fake success lines, a table of the public
# answers (fails the seeded tests) and an oracle that answers 0. (acos losing tiny angles,
# cases/partial.cpp, is graded too but may be named: a real wrong answer whose one failing scalar
# check looks, on some seeds, exactly like the catalogue's wrong constants; see README.md.) Then
# `workbook_mutants audit` matches every result against the committed catalogue (none may be
# named, in its file or matched again), and once more with a planted fault: an entry whose
# signature is one of these results' own, which the audit must report.
set -euo pipefail
root=$1 build=$2 work=$3
tool=$build/grading/workbook_mutants catalogue=$root/tests/grading/mutants/catalogue
fail() { echo "FAILED: $*" >&2; exit 1; }

rm -rf "$work" && mkdir -p "$work/class"
add() { mkdir -p "$work/class/$1/exercises" && cat > "$work/class/$1/exercises/rotation.cpp"; }
add reference < "$root/solutions/rotation.cpp"
for h in honest_eigen_geometry honest_levi_civita honest_rodrigues; do add "$h" < "$root/tests/grading/tests/similarity/$h.cpp"; done
add stub < "$build/pristine/exercises/rotation.cpp"
{ cat "$root/solutions/rotation.cpp"; echo 'int does_not_build = ;'; } | add compile_error
mkdir -p "$work/class/empty"
# The reference with one function renamed out of the way and the case's bad one appended.
replace() {
  local name=$1 function=$2 case=$3
  { sed -E "s/^([A-Za-z][A-Za-z0-9_:<>,&* ]* )${function}\(/\1${function}_reference_(/" "$root/solutions/rotation.cpp"
    grep -v '^// ' "$root/tests/grading/tests/cases/$case.cpp"; } | add "$name"
}
replace crash axis_angle crash
replace timeout compose timeout
replace exit0 geodesic_angle exit0
replace fake_success lab_angular_velocity fake_success
replace lookup_table hat lookup_table
replace oracle hat oracle_in_process
replace acos geodesic_angle partial

"$build/grading/workbook_grade" grade --setup "$build/grading" -j 2 --seed 7193 "$work/class" "$work/grades" \
  > "$work/grade.txt" 2>&1 || { cat "$work/grade.txt"; fail "the grading run failed"; }
verdicts() { grep -o '"verdict": *"[a-z ]*"' "$work/grades/results/$1.json" | sort | uniq -c; }
verdicts crash | grep -q '"crash"' || fail "the crash submission did not crash: $(verdicts crash)"
verdicts timeout | grep -q '"timeout"' || fail "the timeout submission did not time out: $(verdicts timeout)"
verdicts compile_error | grep -q '"build error"' || fail "the broken submission built"
for s in exit0 fake_success lookup_table oracle acos; do
  verdicts $s | grep -q '"fail"' || fail "$s does not fail a test: $(verdicts $s)"
done
verdicts reference | grep -vq '"pass"\|"missing"' && fail "the reference does not pass: $(verdicts reference)"

echo "== the audit: no result may name a likely mistake"
"$tool" audit --catalogue "$catalogue" --results "$work/grades/results" --may-name acos || fail "a result was given a likely mistake"

echo "== a planted fault: an entry with the signature of one of these results must be reported"
status=0
"$tool" audit --plant --catalogue "$catalogue" --results "$work/grades/results" --may-name acos || status=$?
[[ $status -eq 1 ]] || fail "the planted entry was not reported (audit exit $status)"
echo "no correct submission and no unrelated failure is given a likely mistake; the planted entry is reported"
