#!/usr/bin/env bash
# The README's front door as a student walks through it, in a scratch clone of the workbook
# with a build folder of its own, every command exactly as the README writes it:
#
#   student.sh <root> <work> [--plant topic-list]
#
# On the untouched clone: `check 1` grades Chapter 1 (0 of 11, every exercise not started) and
# `check` says nothing is started; `check hat --hint 1` shows Hint 1. Then a correct hat and a
# wrong vee: `check` shows 1 of 11, vee's failing check with its expected and actual values and
# tolerance and Hint 1; `check 1`, `check vee`, `check vee --hint 2`; a level the ladder lacks
# is refused; `scenes 1` names an exercise a scene still needs. With rotation.cpp solved: `check`
# reports 11 of 11, `scenes 1` runs Chapter 1's scenes, and the self-study block's scene
# commands run as written. Prints the wall time of the first check and of the first scenes.
# --plant topic-list makes the clone's cmake/workbook lose the key it was given (as it once lost
# the list of topics): the walk must then fail (the self-test of this test).
set -uo pipefail
root=$1 work=$2 plant=${3:-}
here=$(cd "$(dirname "$0")" && pwd)
marker="<!-- run by test: readme: a student's first session -->"
source "$(dirname "$0")/walk.sh"  # fail, run

rm -rf "$work" && mkdir -p "$work"
python3 "$here/readme.py" scratch "$root" "$work/workbook" || fail "cannot make the scratch clone"
cd "$work/workbook"
if [[ $plant == --plant ]]; then
  # The front door loses the key it was given (check 1 then grades what is started: nothing).
  sed -i 's|    ask check --folder "$root/exercises" "${key\[@\]}" |    ask check --folder "$root/exercises" |' cmake/workbook
  grep -q '    ask check --folder "$root/exercises" || exit' cmake/workbook || fail "could not plant the lost key"
fi
mapfile -t student < <(python3 "$here/readme.py" block README.md "$marker" 1)
mapfile -t alone < <(python3 "$here/readme.py" block README.md "$marker" 2)
[[ ${#student[@]} -eq 4 ]] || fail "the README's student block has ${#student[@]} lines; this walk knows 4"
[[ ${student[0]} == "cmake/workbook check 1"* && ${student[1]} == "cmake/workbook check hat --hint 1"* &&
   ${student[2]} == "cmake/workbook check  "* && ${student[3]} == "cmake/workbook scenes 1"* ]] ||
  fail "the README's student block is not the one this walk knows: ${student[*]}"


start=$SECONDS
run 1 "${student[0]}" "Chapter 1, Pure rotations: 0 of 11 exercises pass" "not started"
echo "== The first check took $((SECONDS - start)) s of wall time (configure and build included)"
run 1 "${student[2]}" "Nothing started yet"
run 0 "${student[1]}" "Hint 1 of" "for hat"

# A student's first edits: a correct hat, a wrong vee (it forgets the factor 1/2).
python3 - <<'EOF' || fail "cannot edit exercises/rotation.cpp"
import re
p = "exercises/rotation.cpp"
s = open(p).read()
s = s.replace('Mat3 hat(const Vec3& w) { todo("hat"); }',
              'Mat3 hat(const Vec3& w) {\n    Mat3 m;\n    m << 0, -w.z(), w.y(), w.z(), 0, -w.x(), -w.y(), w.x(), 0;\n    return m;\n}')
s = s.replace('Vec3 vee(const Mat3& W) { todo("vee"); }',
              'Vec3 vee(const Mat3& W) { return Vec3(W(2, 1) - W(1, 2), W(0, 2) - W(2, 0), W(1, 0) - W(0, 1)); }')
assert 'todo("hat")' not in s and 'todo("vee")' not in s
open(p, "w").write(s)
EOF
run 1 "${student[2]}" "Chapter 1, Pure rotations: 1 of 11 exercises pass" "First exercise to fix: vee" "tolerance" \
  "Hint 1 of" "for vee"
grep -qE "expected|values:" "$last" || fail "check does not show vee's expected and actual values"
run 1 "cmake/workbook check 1" "1 of 11 exercises pass" "vee"
run 1 "cmake/workbook check vee" "vee" "fail"
run 0 "cmake/workbook check vee --hint 2" "Hint 2 of" "for vee"
run 1 "cmake/workbook check vee --hint 9" "from 1 to"
start=$SECONDS
run 1 "${student[3]}" "needs an exercise you have not written yet"
echo "== The first scenes 1 took $((SECONDS - start)) s of wall time (configure and build included)"

# Chapter 1 solved.
cp "$root/solutions/rotation.cpp" exercises/rotation.cpp
run 0 "${student[2]}" "Chapter 1, Pure rotations: 11 of 11 exercises pass"
start=$SECONDS
run 0 "${student[3]}" "Your code: rotation" "error"
echo "== scenes 1 after the edit took $((SECONDS - start)) s"
ls build/student/figures/01_pure_rotations/*.svg >/dev/null 2>&1 || fail "scenes 1 wrote no figure"

# The self-study block: each line as written.
[[ ${#alone[@]} -ge 3 ]] || fail "the README's self-study block is missing"
for line in "${alone[@]}"; do
  run 0 "$line"
  case $line in
    *--json*) python3 -c 'import json,sys; r=json.load(open(sys.argv[1])); assert "error" in r and "run_time_s" in r' "$last" ||
                fail "'$line' printed no JSON report with error and run_time_s" ;;
    *--list-options*) python3 -c 'import json,sys; json.load(open(sys.argv[1]))' "$last" || fail "'$line' printed no JSON" ;;
    *--help*) grep -q -- "--axis" "$last" || fail "'$line' does not list --axis" ;;
  esac
done
rm -rf /tmp/mine
echo "== The student's walk: every command of the README's student and self-study blocks did what the README says"
