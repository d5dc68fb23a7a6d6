#!/usr/bin/env bash
# Blame through the call chain (grading.hpp, blame()): a failure that another exercise of the
# student's may cause names it first, in `check` and in the results .json, and only then.
#
#   blame.sh <workbook_grade> <build>/grading <solutions folder> <scratch folder>
#
# From the reference solutions, four students:
#   rk4      rk4_step's k3 built from k1: integrate_rk4 (correct, calls rk4_step) is blamed on it;
#            `check integrate_rk4` grades rk4_step too and says so in integrate_rk4's row.
#   euler    euler_rhs's first gap turned round (I3 - I2): free_body_equations is blamed on it (its lambda calls it).
#   steps    integrate_rk4 miscounts its steps, rk4_step right: integrate_rk4 fails, blamed on nothing.
#   inlined  rk4_step wrong, and an integrate_rk4 that does its own (wrong) step instead of calling
#            rk4_step: both fail, and nothing is blamed, since the student's code does not call it.
# The last two are the self-test: an engine that blamed every failure of an exercise with callees,
# or read the calls from the reference instead of the student's file, fails them; one that never
# blamed fails the first two.
set -euo pipefail
grade=$1 setup=$2 solutions=$3 work=$4
fail() { echo "FAILED: $*" >&2; exit 1; }
rm -rf "$work" && mkdir -p "$work"/class/{rk4,euler,steps,inlined}

python3 - "$solutions" "$work/class" <<'PY'
import sys
sol, out = sys.argv[1], sys.argv[2]
def write(student, topic, pairs):
    s = open(f"{sol}/{topic}.cpp").read()
    for old, new in pairs:
        assert s.count(old) == 1, f"blame.sh: the reference {topic}.cpp changed ({old!r}): update blame.sh"
        s = s.replace(old, new)
    open(f"{out}/{student}/{topic}.cpp", "w").write(s)
k3 = ("const VecX k3 = f(t + h / 2, y + (h / 2) * k2);", "const VecX k3 = f(t + h / 2, y + (h / 2) * k1);")
write("rk4", "integrators", [k3])
write("steps", "integrators", [("        steps += n;\n", "        steps += n + 1;\n")])
write("inlined", "integrators", [k3, ("y = rk4_step(f, t0 + double(j) * step, y, step);",
                                      "y = y + step * f(t0 + double(j) * step, y);")])
write("euler", "free_body", [("return Vec3((I(1) - I(2)) * W(1)", "return Vec3((I(2) - I(1)) * W(1)")])
PY

# check, one exercise: its callee graded with it, and named in its row and first.
"$grade" check --setup "$setup" --folder "$work/class/rk4" --out "$work/check-rk4" integrate_rk4 >"$work/rk4.txt" 2>&1 || true
cat "$work/rk4.txt"
grep -qE "^ *fail +rk4_step " "$work/rk4.txt" || fail "'check integrate_rk4' did not grade rk4_step, which it calls"
grep -qE "^ *fail +integrate_rk4 .*; it calls your rk4_step, which does not pass" "$work/rk4.txt" ||
  fail "'check integrate_rk4' did not name rk4_step in integrate_rk4's row"
"$grade" check --setup "$setup" --folder "$work/class/euler" --out "$work/check-euler" free_body_equations \
  >"$work/euler.txt" 2>&1 || true
grep -qE "free_body_equations .*; it calls your euler_rhs, which does not pass" "$work/euler.txt" ||
  { cat "$work/euler.txt"; fail "'check free_body_equations' did not name euler_rhs"; }
for s in steps inlined; do
  "$grade" check --setup "$setup" --folder "$work/class/$s" --out "$work/check-$s" integrate_rk4 >"$work/$s.txt" 2>&1 || true
  grep -qE "^ *fail +integrate_rk4 " "$work/$s.txt" || { cat "$work/$s.txt"; fail "$s: integrate_rk4 did not fail"; }
  ! grep -q "calls your" "$work/$s.txt" || { cat "$work/$s.txt"; fail "$s: a failure was blamed on an exercise"; }
done

# grade: the results .json of each.
"$grade" grade --setup "$setup" "$work/class" "$work/grades" -j 2 >"$work/grade.txt" 2>&1 ||
  { cat "$work/grade.txt"; fail "the grading run failed"; }
python3 - "$work/grades/results" <<'PY'
import json, sys
d = sys.argv[1]
def blamed(student):
    return json.load(open(f"{d}/{student}.json"))
want = {"rk4": ("integrate_rk4", "rk4_step", "integrate_rk4 calls your rk4_step, which fails "),
        "euler": ("free_body_equations", "euler_rhs", "free_body_equations calls your euler_rhs, which fails ")}
for student, (exercise, callee, text) in want.items():
    j = blamed(student)
    b = [x for x in j["extra_data"].get("blame", []) if x["exercise"] == exercise]
    assert b and b[0]["uses"] == [callee] and b[0]["text"].startswith(text), \
        f"FAILED: {student}.json does not blame {exercise} on {callee}: {j['extra_data'].get('blame')}"
    failed = [t for t in j["tests"] if t["extra_data"]["exercise"] == exercise and t["status"] == "failed"]
    assert failed, f"FAILED: {student}.json: {exercise} fails no test"
    for t in failed:
        assert t["output"].startswith(text), f"FAILED: {student}.json: a failing test of {exercise} does not say first {text!r}: {t['output'][:200]!r}"
    assert text in j["output"], f"FAILED: {student}.json: the summary does not blame {exercise}"
    print(f"{student}: {b[0]['text']}")
for student in ("steps", "inlined"):
    j = blamed(student)
    assert "blame" not in j["extra_data"], f"FAILED: {student}.json blames: {j['extra_data']['blame']}"
    assert not any("calls your" in t["output"] for t in j["tests"]), f"FAILED: {student}.json: a test says 'calls your'"
    print(f"{student}: nothing blamed")
PY
echo "== A failure another exercise of the student's may cause names it, in check and in results .json, and only then"
