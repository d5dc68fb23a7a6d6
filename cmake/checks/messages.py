#!/usr/bin/env python3
"""Every failing check shows what it was given (issue 41, item 3).

  messages.py check --build B --root R          the graders' messages on the stubs and at every check
  messages.py planted --build B --root R --work W
                                                the messages of one planted wrong answer per exercise
  messages.py selftest --work W                 planted messages without inputs; each must be flagged

A grader's failing check must show its inputs by name (tests/inputs.hpp: INPUTS(A, UNIT(t, "s"))
prints "inputs: A = 1; t = 0.25 s"), beside the expected and actual values and the tolerance its
check prints. It is read three ways, each a grader's own failure output:

  * on the pristine stubs: grade_<topic>_stubs --reporters=workbook, every failed check;
  * at every check: the reference graders with --success, where the workbook reporter shows each
    check of a test case the first time it runs, with what its failure message would hold (so that
    a check no wrong answer reaches is read too);
  * on a planted wrong answer per exercise (`planted`): one mutant of the mutation gate per exercise
    graded by the grading run, and the first failure of each failing test as the student reads it.

A failing check offends when no line of its message starts with "inputs: " (a message that shows
only loop indices, "n := 0", or the expected and actual values alone), or when a line of it is a
bare number with no name ("80"). A check whose own expression spells its inputs in literals, as
CHECK_THROWS_AS(rigid::hat(Vec3(nan_, 0, 0)), ...) does, shows them. Offenders are counted per test;
the tests in messages_baseline.txt are known offenders, to be fixed: the check fails on an offender
the baseline does not list, and on a listed test that no longer offends (take it out).
"""
import argparse
import json
import pathlib
import re
import shutil
import subprocess
import sys

HERE = pathlib.Path(__file__).resolve().parent
BASELINE = HERE / "messages_baseline.txt"

NUMBER = r"[-+]?(?:\d+\.?\d*(?:[eE][-+]?\d+)?|nan|inf)"
BARE = re.compile(rf"^\s*[(\[]?\s*{NUMBER}(?:\s*[,; ]\s*{NUMBER})*\s*[)\]]?\s*$")
# Identifiers a self-describing expression may hold: the API's calls, Eigen's named vectors and the
# graders' named constants.
SPELLED = {"rigid", "Vec3", "Mat3", "VecX", "MatX", "UnitX", "UnitY", "UnitZ", "Zero", "Identity", "Ones",
           "nan_", "inf_", "tiny_", "pi", "std", "numbers", "numeric_limits", "double", "quiet_NaN", "infinity",
           "denorm_min", "min", "max", "lowest", "epsilon", "void", "checks", "Eigen", "true", "false", "e",
           "message_of", "find", "string", "npos", "size", "invalid_argument", "asDiagonal", "toDenseMatrix",
           "nextafter", "next_up", "sqrt", "pow", "abs"}
IDENT = re.compile(r"[A-Za-z_]\w*")


def spelled(expression):
    """Whether a check's expression spells its inputs: an API call on literals and named constants."""
    if "rigid::" not in expression:
        return False
    text = re.sub(r'"(?:[^"\\]|\\.)*"', '""', expression)
    calls = {m.group(1) for m in re.finditer(r"rigid::(\w+)\s*\(", text)}
    for m in IDENT.finditer(text):
        word = m.group(0)
        if word in SPELLED or word in calls or re.fullmatch(r"\d*e\d*", word):
            continue
        before = text[max(0, m.start() - 2):m.start()]
        if before == "::" or before.endswith(".") or re.match(r"\d", text[m.start() - 1:m.start()] or "x"):
            continue
        return False
    return True


def offence(lines, expression=""):
    """Why a failing check's message (its lines) does not show its inputs, or None."""
    if not any(line.strip().startswith("inputs: ") and " = " in line for line in lines) and not spelled(expression):
        return "no inputs by name"
    labelled = False  # numbers under CHECK_MAT_NEAR's "expected" / "actual" are labelled
    for line in lines:
        word = line.strip()
        if word in ("expected", "actual"):
            labelled = True
        elif word.startswith("max |diff|") or not word:
            labelled = False
        elif BARE.match(word) and not labelled:
            return f"a bare number with no name: '{word}'"
    return None


def context_lines(info):
    return [line for context in info for line in str(context).split("\n")]


def read_events(text, topic, kinds):
    """The checks of one run of a grader: (topic, test, file:line, why) for each offending one."""
    found, test = [], ""
    for raw in text.splitlines():
        try:
            event = json.loads(raw)
        except ValueError:
            continue
        kind = event.get("event")
        if kind == "start":
            test = event.get("name", "")
        elif kind in kinds or (kind == "message" and "message" in kinds and event.get("severity") != "WARNING"):
            why = offence(context_lines(event.get("info", [])), event.get("expression", ""))
            if why:
                where = f"{pathlib.Path(event.get('file', '?')).name}:{event.get('line', 0)}"
                found.append((topic, test, where, why))
    return found


def run_grader(binary, args):
    done = subprocess.run([str(binary), "--reporters=workbook", "--no-version", *args], capture_output=True,
                          text=True, errors="replace", timeout=600)
    return done.stdout


def topics(build):
    catalog = json.loads((build / "grading" / "catalog.json").read_text())
    return [t["name"] for t in catalog["topics"]]


def graders_run(build):
    """Every offending check of every grader, on the stubs and at every check of the reference."""
    found = []
    for topic in topics(build):
        graders = build / "graders"
        reference = graders / f"grade_{topic}_solutions"
        if not reference.exists():
            reference = graders / f"grade_{topic}"
        stubs = graders / f"grade_{topic}_stubs"
        for binary in (stubs, reference):
            if not binary.exists():
                sys.exit(f"messages.py: {binary} is not built (the target {binary.name})")
        found += read_events(run_grader(stubs, []), topic, {"assert", "message"})
        found += read_events(run_grader(reference, ["--success"]), topic, {"site"})
    return found


def read_baseline(path):
    listed = {}
    for n, line in enumerate(path.read_text().splitlines(), 1):
        if not line.strip() or line.startswith("#"):
            continue
        fields = [f.strip() for f in line.split(" | ")]
        if len(fields) != 2:
            sys.exit(f"{path}:{n}: expected 'topic | test name'")
        listed[(fields[0], fields[1])] = n
    return listed


def judge(found, baseline_path, stale=True):
    """Compares the offending tests with the baseline (and, with `stale`, finds listed tests that no
    longer offend: only a run that reads every check can); returns the exit status."""
    offenders = {}
    for topic, test, where, why in found:
        offenders.setdefault((topic, test), []).append(f"{where}: {why}")
    baseline = read_baseline(baseline_path)
    new = [k for k in offenders if k not in baseline]
    fixed = [k for k in baseline if k not in offenders] if stale else []
    for key in new:
        topic, test = key
        print(f"FAILED: a failing check of {topic}'s test \"{test}\" does not show its inputs "
              f"({len(offenders[key])} checks), e.g. {offenders[key][0]}")
    for key in fixed:
        print(f"FAILED: {baseline_path.name}:{baseline[key]} lists {key[0]} | {key[1]}, which no longer offends: "
              "take it out")
    print(f"{len(offenders)} tests with a check that does not show its inputs ({len(found)} checks), "
          f"{len(baseline)} listed in {baseline_path.name}")
    if new or fixed:
        return 1
    print("every failing check shows its inputs, but for the tests the baseline lists")
    return 0


def check(args):
    found = graders_run(pathlib.Path(args.build))
    if args.list:
        for key in sorted({(t, n) for t, n, _, _ in found}):
            print(f"{key[0]} | {key[1]}")
        return 0
    return judge(found, pathlib.Path(args.baseline))


# ---- One planted wrong answer per exercise, graded by the grading run. ----

# The mutation gate's operators in the order a planted answer is taken: those that always compile
# first (a mutant that does not compile is built alone and shows no check).
PREFERENCE = ["constant", "sign", "compare", "condition", "transpose", "index", "sincos", "return"]
FIRST_LINE = re.compile(r"^(?:fail: )?(\S+):(\d+): (\w+)\( (.*) \) failed$")


def exercises(grading):
    listed = []
    for line in (grading / "manifest.txt").read_text().splitlines():
        fields = line.split("\t")
        if fields[0] == "exercise":
            listed.append((fields[1], fields[2]))
    return listed


def picks(grading, solutions):
    """One mutant id per exercise: the first of its mutants by PREFERENCE, then by line."""
    listing = subprocess.run([str(grading / "workbook_mutants"), "list", "--setup", str(grading), "--solutions",
                              str(solutions)], capture_output=True, text=True, check=True).stdout
    best = {}
    for line in listing.splitlines():
        mid, function, op, number = line.split("\t")[:4]
        topic = mid.rsplit("-", 1)[0]
        rank = (PREFERENCE.index(op) if op in PREFERENCE else len(PREFERENCE), int(number), mid)
        if (topic, function) not in best or rank < best[(topic, function)]:
            best[(topic, function)] = rank
    return {key: best[key][2] for key in exercises(grading) if key in best}


def read_results(result, topic, exercise):
    """The offending first failures of an exercise's failing tests in one results.json."""
    found = []
    for test in json.loads(result.read_text()).get("tests", []):
        extra = test.get("extra_data", {})
        if extra.get("topic") != topic or extra.get("exercise") != exercise or extra.get("verdict") != "fail":
            continue
        lines = test.get("output", "").split("\n")
        first = FIRST_LINE.match(lines[0]) if lines else None
        if not first:
            continue  # not a failed check: an exception, a crash, a limit
        why = offence(lines[1:], first.group(4))
        if why:
            found.append((topic, test["name"], f"{pathlib.Path(first.group(1)).name}:{first.group(2)}", why))
    return found


def planted(args):
    build, root, work = pathlib.Path(args.build), pathlib.Path(args.root), pathlib.Path(args.work)
    grading = build / "grading"
    chosen = picks(grading, root / "solutions")
    shutil.rmtree(work, ignore_errors=True)
    command = [str(grading / "workbook_mutants"), "run", "--setup", str(grading), "--solutions",
               str(root / "solutions"), "--out", str(work), "--allow", str(root / "tests/grading/mutants/allowed.txt"),
               "-j", str(args.jobs)]
    for mid in chosen.values():
        command += ["--mutant", mid]
    done = subprocess.run(command, capture_output=True, text=True)
    if not (work / "mutants.json").exists():
        sys.exit(f"messages.py: the mutation gate did not run ({done.returncode}):\n{done.stderr[-3000:]}")
    status = {m["id"]: m["status"] for m in json.loads((work / "mutants.json").read_text())}
    found, shown = [], 0
    for (topic, exercise), mid in chosen.items():
        if status.get(mid) != "killed":
            continue
        shown += 1
        found += read_results(work / "checks" / mid / "results.json", topic, exercise)
    print(f"{len(chosen)} exercises, a planted wrong answer each: {shown} caught by a failing test "
          f"(the rest equivalent or not compiling)")
    # A planted answer reaches some checks of a test, not all: a listed test it does not show offending
    # may still offend elsewhere (the check above reads every check).
    return judge(found, pathlib.Path(args.baseline), stale=False)


# ---- The self-test: planted messages, each of which must be flagged. ----

def selftest(args):
    work = pathlib.Path(args.work)
    shutil.rmtree(work, ignore_errors=True)
    work.mkdir(parents=True)
    index = ["n := 0", "k := 2", "expected 2, actual 6, |diff| 4, tolerance 1e-12"]
    events = [{"event": "start", "name": "planted: only loop indices"},
              {"event": "assert", "file": "t.cpp", "line": 1, "expression": "x <= tol", "info": index},
              {"event": "start", "name": "planted: a bare number"},
              {"event": "site", "file": "t.cpp", "line": 2, "expression": "x <= tol", "info": ["inputs: A = 1", "80"]},
              {"event": "start", "name": "planted: shows its inputs"},
              {"event": "assert", "file": "t.cpp", "line": 3, "expression": "x <= tol",
               "info": ["inputs: A = 1; t = 0.5 s", "expected\n1\n2\nactual\n1\n3\nmax |diff| 1, tolerance 0"]},
              {"event": "assert", "file": "t.cpp", "line": 4, "expression": "rigid::hat(Vec3(nan_, 0, 0))", "info": []}]
    found = read_events("\n".join(json.dumps(e) for e in events), "planted", {"assert", "site"})
    result = work / "results.json"
    result.write_text(json.dumps({"tests": [{"name": "planted: a result without inputs", "output":
                                             "fail: t.cpp:5: CHECK( a <= b ) failed\n  with values: 3 <= 1\n  n := 0",
                                             "extra_data": {"topic": "planted", "exercise": "x", "verdict": "fail"}}]}))
    found += read_results(result, "planted", "x")
    flagged = {test for _, test, _, _ in found}
    wanted = {"planted: only loop indices", "planted: a bare number", "planted: a result without inputs"}
    problems = [f"not flagged: {t}" for t in sorted(wanted - flagged)]
    problems += [f"flagged, yet it shows its inputs: {t}" for t in sorted(flagged - wanted)]
    baseline = work / "baseline.txt"
    baseline.write_text("planted | planted: only loop indices\nplanted | planted: shows its inputs\n")
    print("-- the judgement against a baseline that misses two offenders and lists one that does not offend:")
    if judge(found, baseline) != 1:
        problems.append("the judgement passed a baseline that misses offenders")
    for p in problems:
        print(f"FAILED: {p}")
    if problems:
        return 1
    print("the planted messages without inputs were flagged, and the one with them was not")
    return 0


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    sub = parser.add_subparsers(dest="command", required=True)
    for name in ("check", "planted", "selftest"):
        p = sub.add_parser(name)
        if name != "selftest":
            p.add_argument("--build", required=True)
            p.add_argument("--root", required=True)
            p.add_argument("--baseline", default=str(BASELINE))
        if name != "check":
            p.add_argument("--work", required=True)
        if name == "check":
            p.add_argument("--list", action="store_true", help="print the offending tests as a baseline")
        if name == "planted":
            p.add_argument("--jobs", type=int, default=2)
    args = parser.parse_args()
    return {"check": check, "planted": planted, "selftest": selftest}[args.command](args)


if __name__ == "__main__":
    sys.exit(main())
