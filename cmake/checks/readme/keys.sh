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
# 3. `scenes 2` in every state a student's folder can be in, each time the error omega_circle
#    reports (its JSON) must be the code's that the door says it ran: nothing started (the
#    reference's, below 1e-9), one topic (precession alone, with the wrong order: far above), two
#    topics of two chapters (rotation and precession, through every kind of chapter key: 2, ch02,
#    02_regular_precession), every topic, a file that does not compile in a topic the chapter
#    does not need (heavy_top: the scenes still run the student's precession), and one in a topic
#    it needs (precession: refused, with the compiler's error naming the file). `scenes 9` and
#    `scenes hat` are refused.
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

# omega_error <above|below> <bound> <what>: omega_circle's reported error from the last `scenes 2`.
omega_error() {
  python3 - build/student/figures/02_regular_precession/omega_circle.json "$1" "$2" "$3" <<'EOF'
import json, sys
path, side, bound, what = sys.argv[1], sys.argv[2], float(sys.argv[3]), sys.argv[4]
error = json.load(open(path))["error"]
print(f"omega_circle's error, {what}: {error:.3g}")
sys.exit(0 if (error > bound if side == "above" else error < bound) else 1)
EOF
}

# 3a. Nothing started: the reference's scenes, and the reference's error.
run 0 "cmake/workbook scenes 2" "No exercises/*.cpp started yet: the scenes run on the reference solutions"
omega_error below 1e-9 "nothing started" || fail "'cmake/workbook scenes 2' with nothing started did not report the reference's error"

# 2. Two topics of two chapters: rotation solved, precession solved but for the order of its factors.
python3 - "$root/solutions/precession.cpp" <<'EOF' || fail "cannot write the wrong precession_rotation"
import sys
s = open(sys.argv[1]).read()
right = "return rotation_about(q.b, q.beta * t) * rotation_about(q.a, q.alpha * t);"
assert right in s, "the reference precession_rotation changed: update keys.sh"
open("exercises/precession.cpp", "w").write(s.replace(right, "return rotation_about(q.a, q.alpha * t) * rotation_about(q.b, q.beta * t);"))
EOF
# 3b. One topic, precession alone: its wrong order shows; rotation comes from solutions/.
run any "cmake/workbook scenes 2" "Your code: precession (exercises/); from solutions/: "
grep -qE "from solutions/: (.* )?rotation( |.\[0m|$)" "$last" || fail "'cmake/workbook scenes 2' did not say rotation comes from solutions/"
omega_error above 1e-3 "precession alone started" ||
  fail "'cmake/workbook scenes 2' did not run the student's precession (omega_circle's error is the reference's)"
cp "$root/solutions/rotation.cpp" exercises/rotation.cpp
if [[ $plant != --plant ]]; then
  run 1 "cmake/workbook check" "Not started (still the stub as committed, not graded): integrators free_body" \
    "Chapter 1, Pure rotations: 11 of 11 exercises pass" "First exercise to fix: precession_rotation"
  grep -q "Chapter 2, " "$last" || fail "'cmake/workbook check' did not grade Chapter 2"
  run 1 "cmake/workbook check 2" "precession_rotation"
fi

# 3c. Two topics of two chapters, every kind of chapter key: the scenes must show the wrong order.
for key in 2 ch02 02_regular_precession; do
  run any "cmake/workbook scenes $key" "Your code: rotation precession (exercises/); from solutions/: "
  omega_error above 1e-3 "rotation and precession started" ||
    fail "'cmake/workbook scenes $key' did not run the student's precession (omega_circle's error is the reference's)"
done

# 3d. Every topic started (the others solved): still the student's precession.
every=()
for f in "$root"/solutions/*.cpp; do
  t=$(basename "$f" .cpp)
  every+=("$t")
  [[ $t == precession ]] || cp "$f" exercises/
done
run any "cmake/workbook scenes 2" "(exercises/); every topic is yours"
for t in "${every[@]}"; do
  grep -qE "Your code: (.* )?$t( |$)" "$last" || fail "'cmake/workbook scenes 2' with every topic started did not name $t"
done
omega_error above 1e-3 "every topic started" ||
  fail "'cmake/workbook scenes 2' with every topic started did not run the student's precession"

# 3e. A file that does not compile, in a topic Chapter 2 does not need: the scenes still run.
printf '\nthis line is not C++\n' >> exercises/heavy_top.cpp
run any "cmake/workbook scenes 2" "Your code: "
omega_error above 1e-3 "heavy_top.cpp broken" ||
  fail "'cmake/workbook scenes 2' with a broken heavy_top.cpp did not run the student's precession"
# ... and in a topic it needs: refused, with the compiler's word on the file.
cp "$root/solutions/heavy_top.cpp" exercises/heavy_top.cpp
printf '\nthis line is not C++\n' >> exercises/precession.cpp
run 1 "cmake/workbook scenes 2" "exercises/precession.cpp" "error" "the scenes of 02_regular_precession did not build"
run 2 "cmake/workbook scenes 9" "'9' is not a chapter"
run 2 "cmake/workbook scenes hat" "'hat' is not a chapter"
echo "== Every kind of key, and scenes in every state of exercises/: check and scenes graded and ran what they said"
