#!/usr/bin/env bash
# The front door's keys, every kind of each, in a scratch clone of the workbook with build folders
# of its own: what `cmake/workbook check KEY` and `scenes CHAPTER` take, and what they do with
# several topics started. The grammar is one program's (tests/grading/engine/catalog.hpp, asked
# through workbook_topics); this walks its doors.
#
#   keys.sh <root> <work> [--plant one-word]
#
# 1. check with a chapter as 1, 01, ch01 and 01_pure_rotations, a topic (rotation) and an exercise
#    (hat): each grades what it names; a key that names nothing is refused (exit 2) with the list.
# 2. Two topics of two chapters started, rotation (solved) and precession (solved, but
#    precession_rotation multiplies its factors in the wrong order): `check` grades both and says
#    which are not started; `check 2` fails precession_rotation.
# 3. `scenes 2`, `scenes ch02` and `scenes 02_regular_precession` with both started: each says it
#    runs rotation and precession from exercises/, and the scenes report the wrong order's error
#    (omega_circle's, far above the reference's 1e-13); `scenes 9` and `scenes hat` are refused.
# --plant one-word passes the topics to CMake as one word, as `scenes` once did ("rotation
# precession" for WORKBOOK_TOPICS with a CMake that took only ';'): the walk must then fail.
set -uo pipefail
root=$1 work=$2 plant=${3:-}
here=$(cd "$(dirname "$0")" && pwd)
source "$(dirname "$0")/walk.sh"  # fail, run

rm -rf "$work" && mkdir -p "$work"
python3 "$here/readme.py" scratch "$root" "$work/workbook" || fail "cannot make the scratch clone"
cd "$work/workbook" || fail "no scratch clone"
if [[ $plant == --plant ]]; then
  # The front door hands CMake the topics joined by a character CMake does not split a list at.
  sed -i 's|    WORKBOOK_TOPICS="$own" configure|    WORKBOOK_TOPICS="${own//;/+}" configure|' cmake/workbook
  sed -i 's|string(REGEX REPLACE "\[ ,;\]+" ";" names "${${variable}}")|set(names "${${variable}}")|' cmake/Workbook.cmake
  sed -i 's|message(FATAL_ERROR "${variable}: |message(STATUS "${variable}: |' cmake/Workbook.cmake
  grep -q 'own//;/+' cmake/workbook && grep -q 'set(names "${${variable}}")' cmake/Workbook.cmake &&
    grep -q 'message(STATUS "${variable}: ' cmake/Workbook.cmake ||
    fail "could not plant the one-word topic list"
  echo "== Planted: the topics reach CMake as one word"
fi


# 1. Every kind of key, on the untouched clone (nothing started: every exercise is "not started").
# (The planted walk goes to step 3, where the fault is.)
keys=(1 01 ch01 01_pure_rotations)
[[ $plant != --plant ]] || keys=()
for key in "${keys[@]}"; do
  run 1 "cmake/workbook check $key" "Checking Chapter 1 in exercises" "Chapter 1, Pure rotations: 0 of 11 exercises pass"
done
if [[ $plant != --plant ]]; then
  run 1 "cmake/workbook check rotation" "Checking exercises/rotation.cpp" "0 of 11 exercises pass"
  run 1 "cmake/workbook check hat" "Checking the exercise hat" "hat" "not started"
  run 2 "cmake/workbook check no_such_key" "'no_such_key' is not a chapter, topic or exercise" "rotation: hat vee"
fi

# 2. Two topics of two chapters: rotation solved, precession solved but for the order of its factors.
cp "$root/solutions/rotation.cpp" exercises/rotation.cpp
python3 - "$root/solutions/precession.cpp" <<'EOF' || fail "cannot write the wrong precession_rotation"
import sys
s = open(sys.argv[1]).read()
right = "return rotation_about(q.b, q.beta * t) * rotation_about(q.a, q.alpha * t);"
assert right in s, "the reference precession_rotation changed: update keys.sh"
open("exercises/precession.cpp", "w").write(s.replace(right, "return rotation_about(q.a, q.alpha * t) * rotation_about(q.b, q.beta * t);"))
EOF
if [[ $plant != --plant ]]; then
  run 1 "cmake/workbook check" "Not started (still the stub as committed, not graded): integrators free_body" \
    "Chapter 1, Pure rotations: 11 of 11 exercises pass" "First exercise to fix: precession_rotation"
  grep -q "Chapter 2, " "$last" || fail "'cmake/workbook check' did not grade Chapter 2"
  run 1 "cmake/workbook check 2" "precession_rotation"
fi

# 3. scenes with both topics started, every kind of chapter key: the scenes must show the wrong order.
for key in 2 ch02 02_regular_precession; do
  run any "cmake/workbook scenes $key" "Your code: rotation precession (exercises/); the rest from solutions/"
  python3 - build/student/figures/02_regular_precession/omega_circle.json <<'EOF' ||
import json, sys
r = json.load(open(sys.argv[1]))
assert r["error"] > 1e-3, f"omega_circle reported the error {r['error']}: the reference's, not the student's"
print(f"omega_circle's error on the student's precession: {r['error']:.3g}")
EOF
    fail "'cmake/workbook scenes $key' did not run the student's precession (omega_circle's error is the reference's)"
done
run 2 "cmake/workbook scenes 9" "'9' is not a chapter"
run 2 "cmake/workbook scenes hat" "'hat' is not a chapter"
echo "== Every kind of key, and two topics started: check and scenes graded and ran what they said"
