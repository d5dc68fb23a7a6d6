#!/usr/bin/env bash
# The instructor's manual's grading command, exactly as tests/grading/README.md writes it, in a
# scratch clone with a build folder of its own, on a small class in submissions/: the reference
# rotation.cpp, the untouched stub and a file that does not compile. It must write the class
# files and each student's results with the verdicts they deserve, record the seed in run.json
# and show it in no output.
#
#   instructor.sh <root> <work>
set -uo pipefail
root=$1 work=$2
here=$(cd "$(dirname "$0")" && pwd)
marker="<!-- run by test: readme: an instructor grades a small class -->"
fail() { echo "FAILED: $*" >&2; exit 1; }

rm -rf "$work" && mkdir -p "$work"
python3 "$here/readme.py" scratch "$root" "$work/workbook" || fail "cannot make the scratch clone"
cd "$work/workbook"
mapfile -t lines < <(python3 "$here/readme.py" block tests/grading/README.md "$marker")
[[ ${#lines[@]} -eq 1 ]] || fail "the manual's grading block has ${#lines[@]} lines; this test knows 1"
mkdir -p submissions/alice/exercises submissions/bob submissions/carol/exercises
cp solutions/rotation.cpp submissions/alice/exercises/
cp exercises/rotation.cpp submissions/bob/
sed 's/todo("hat");/todo("hat")/' exercises/rotation.cpp > submissions/carol/exercises/rotation.cpp
echo "\$ ${lines[0]}"
start=$SECONDS
bash -c "${lines[0]}" > "$work/grade.txt" 2>&1
status=$?
sed 's/^/  | /' "$work/grade.txt" | tail -n 15
echo "  (exit $status, $((SECONDS - start)) s)"
[[ $status -eq 0 ]] || fail "the grading command exited with status $status"
seed=$(grep -o -- '--seed [0-9]*' <<<"${lines[0]}" | cut -d' ' -f2)
for f in summary.md class.csv canvas.csv moodle.csv similarity.md run.json results/alice.json results/bob.json results/carol.json; do
  [[ -f grades/$f ]] || fail "grades/$f was not written"
done
python3 - "$seed" <<'PY' || fail "the results are not what the manual says"
import json, sys
seed = sys.argv[1]
score = lambda s: json.load(open(f"grades/results/{s}.json"))
def rotation(s):
    return [t for t in score(s)["tests"] if t["extra_data"]["topic"] == "rotation"]
alice, bob, carol = rotation("alice"), rotation("bob"), rotation("carol")
assert all(t["status"] == "passed" for t in alice), "alice's reference rotation.cpp does not pass"
assert all(t["extra_data"]["not_started"] for t in bob), "bob's stub is not 'not started'"
assert all(t["extra_data"]["verdict"] == "build error" for t in carol), "carol's file is not a build error"
assert abs(sum(t["score"] for t in alice) - 11) < 1e-9, "alice does not score 11 on rotation"
run = json.load(open("grades/run.json"))
assert run["seed"] == seed, f"run.json records the seed {run['seed']}, not {seed}"
print("alice 11/11 on rotation, bob not started, carol a build error; run.json records the seed")
PY
! grep -q -- "$seed" "$work/grade.txt" || fail "the seed shows in the run's output"
[[ -z $(git status --porcelain -- . ':!submissions' ':!grades') ]] || fail "the run changed the workbook: $(git status --porcelain)"
echo "== The manual's grading command graded the class as the manual says"
