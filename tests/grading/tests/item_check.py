#!/usr/bin/env python3
"""Checks a class run's item analysis against a count of its own (tests/grading/engine/item_analysis.hpp).

    item_check.py --out <grades> --manifest <build>/grading/manifest.txt --submissions <folder>
                  --stubs <build>/pristine/exercises [--plant-fault]

Reads nothing the item analysis wrote to count: the verdicts, scores and failure messages come
from results/<student>.json (Gradescope's format, written by the workers), the tests from the
manifest, the files from the submissions. Then it checks that item_analysis.csv has one row per
test of every graded topic, in the manifest's order, with the same verdict counts, pass rates of
the two thirds, discrimination and most common failing check; that item_analysis.md has every test
and exercise; that the "started" column agrees; that class_report.html uses only files of the out
folder (no script, nothing from the network) and that each plot it shows exists; and that every
result and run.json carry the same provenance. The thirds are computed here another way: each
student occupies an interval of the ranking, a tied group shares its intervals, and a third is the
overlap with [0, n/3).

--plant-fault flips the verdict of one test of one result (in memory) before counting; and
--plant-missing-provenance drops one result's provenance, and --plant-mistake names a likely mistake in
one result that item_analysis.md does not count: the check must then fail, and the script
exits 0 only when it did (the test of the test).
"""
import argparse
import csv
import json
import os
import re
import sys

VERDICTS = ["pass", "fail", "timeout", "crash", "build error", "missing", "not started"]
PROVENANCE = ["compiler", "eigen", "gsl", "doctest", "commit", "graders", "grader_sources", "limits", "limits_hash"]


def read_manifest(path):
    tests, exercises = [], []
    topic = exercise = None
    for line in open(path, encoding="utf-8"):
        f = line.rstrip("\n").split("\t")
        if f[0] == "topic":
            topic = f[1]
        elif f[0] == "exercise":
            exercise = f[2]
            exercises.append((topic, exercise))
        elif f[0] == "test":
            tests.append((topic, exercise, f[4]))
    return tests, exercises


def read_results(out):
    folder = os.path.join(out, "results")
    results = []
    for name in sorted(os.listdir(folder)):
        if name.endswith(".json"):
            with open(os.path.join(folder, name), encoding="utf-8") as f:
                results.append((name[:-5], json.load(f)))
    return results


def third(scores, top):
    """Each student's weight in the top or bottom third: the overlap of its place in the ranking with [0, n/3)."""
    n = len(scores)
    order = sorted(set(scores), reverse=top)
    weights, start = {}, 0.0
    for s in order:
        tied = [k for k, x in enumerate(scores) if x == s]
        lo, hi = start, start + len(tied)
        overlap = max(0.0, min(hi, n / 3) - lo)
        for k in tied:
            weights[k] = overlap / len(tied)
        start = hi
    return [weights[k] for k in range(n)]


def first_check(output):
    """The failing check of a Gradescope test output 'fail: <message>': the message's first line."""
    message = output[len("fail: "):] if output.startswith("fail: ") else output
    line = message.split("\n", 1)[0]
    at = line.find(") failed")
    return line[: at + 8] if at >= 0 else line.strip()


def count(results, tests, plant):
    rows = {t: {"counts": dict.fromkeys(VERDICTS, 0), "pass": [], "checks": [], "outputs": []} for t in tests}
    for k, (_, r) in enumerate(results):
        for t in r["tests"]:
            x = t["extra_data"]
            key = (x["topic"], x["exercise"], t["name"])
            verdict = "not started" if x["not_started"] else x["verdict"]
            if plant and k == 0 and key == tests[0]:
                verdict = "pass" if verdict != "pass" else "fail"
            rows[key]["counts"][verdict] += 1
            rows[key]["pass"].append((k, verdict == "pass"))
            if verdict == "fail":
                rows[key]["checks"].append(first_check(t["output"]))
                rows[key]["outputs"].append(t["output"])
    return rows


def compare(out, results, tests, rows, problems):
    scores = [r["score"] for _, r in results]
    n = len(scores)
    top, bottom = third(scores, True), third(scores, False)
    with open(os.path.join(out, "item_analysis.csv"), encoding="utf-8") as f:
        table = list(csv.DictReader(f))
    got = [(r["topic"], r["exercise"], r["test"]) for r in table]
    if got != tests:
        problems.append(f"item_analysis.csv has {len(got)} tests, the manifest {len(tests)} (or another order)")
        return
    ranked = n >= 6 and len(set(scores)) > 1
    for row, key in zip(table, tests):
        mine = rows[key]
        for v in VERDICTS:
            if int(row[v.replace(" ", "_")]) != mine["counts"][v]:
                problems.append(f"{key[2]}: {v} {row[v.replace(' ', '_')]} in the csv, {mine['counts'][v]} counted")
        t = sum(top[k] for k, ok in mine["pass"] if ok) / (n / 3)
        b = sum(bottom[k] for k, ok in mine["pass"] if ok) / (n / 3)
        d = row["discrimination"]
        if (d == "n/a") == ranked or (ranked and abs(float(d) - (t - b)) > 1e-4):
            problems.append(f"{key[2]}: discrimination {d} in the csv, {t - b:.4f} computed here")
        checks = mine["checks"]
        best = max(sorted(set(checks)), key=checks.count) if checks else ""
        if row["common_check"] != best:
            problems.append(f"{key[2]}: most common failing check {row['common_check']!r} in the csv, {best!r} here")
        if row["typical_value"] and not any("with values: " + row["typical_value"] in o for o in mine["outputs"]):
            problems.append(f"{key[2]}: the typical value {row['typical_value']!r} is in no failed test's output")
        if int(row["common_check_count"]) != (checks.count(best) if checks else 0):
            problems.append(f"{key[2]}: most common failing check seen {row['common_check_count']} times in the "
                            f"csv, {checks.count(best) if checks else 0} here ({best!r})")


def started_here(results, exercises, submissions, stubs):
    """How many submissions started each exercise, by the rule item_analysis.hpp states."""
    squash = lambda s: re.sub(r"\s", "", s)
    started = {e: 0 for e in exercises}
    for student, r in results:
        for topic, exercise in exercises:
            folder = os.path.join(submissions, student)
            sub = os.path.join(folder, "exercises") if os.path.isdir(os.path.join(folder, "exercises")) else folder
            path = os.path.join(sub, topic + ".cpp")
            if not os.path.isfile(path) or os.path.islink(path):
                continue
            text = open(path, encoding="utf-8", errors="replace").read()
            stub = open(os.path.join(stubs, topic + ".cpp"), encoding="utf-8").read()
            if squash(text) == squash(stub):
                continue
            ran = [t for t in r["tests"] if t["extra_data"]["exercise"] == exercise and
                   t["extra_data"]["verdict"] not in ("build error", "missing")]
            if any(not t["extra_data"]["not_started"] for t in ran) or \
                    (not ran and f'todo("{exercise}")' not in text):
                started[(topic, exercise)] += 1
    return started


def check_likely_mistakes(md, results, problems):
    """item_analysis.md counts each likely mistake the results name (extra_data.likely_mistakes),
    once per student, and has no such section when none is named."""
    named = {}
    for _, r in results:
        seen = set()
        for e in r.get("extra_data", {}).get("likely_mistakes", []):
            for m in e.get("mistakes", []):
                seen.add((e["topic"], e["exercise"], m if isinstance(m, str) else m.get("mistake", str(m))))
        for key in seen:
            named[key] = named.get(key, 0) + 1
    if not named and "Likely mistakes across the class" in md:
        problems.append("item_analysis.md lists likely mistakes that no result names")
    for (topic, exercise, mistake), n in named.items():
        row = f"| {n} | `{exercise}` ({topic}) | " + mistake.replace("|", "\\|") + " |"
        if row not in md:
            problems.append(f"item_analysis.md does not count {n} student(s) for the likely mistake {mistake[:60]!r}")


def check_pages(out, tests, exercises, started, results, problems):
    md = open(os.path.join(out, "item_analysis.md"), encoding="utf-8").read()
    for _, exercise, name in tests:
        if "| " + name.replace("|", "\\|") + " |" not in md:
            problems.append(f"item_analysis.md has no row for the test {name!r}")
    for (topic, exercise), n in started.items():
        m = re.search(r"\| `" + re.escape(exercise) + r"` \| [^|]+ \| \d+ \| (\d+) \|", md)
        if not m or int(m.group(1)) != n:
            problems.append(f"item_analysis.md: {exercise} started by {m.group(1) if m else '?'}, {n} counted here")
    page = open(os.path.join(out, "class_report.html"), encoding="utf-8").read()
    if re.search(r"<script|<link|@import|url\(|https?://", page):
        problems.append("class_report.html loads something (a script, a stylesheet, a URL)")
    images = re.findall(r'<img src="([^"]+)"', page)
    if not images and "No plots:" not in page:
        problems.append("class_report.html has no plot and does not say why")
    for src in images:
        if not os.path.isfile(os.path.join(out, src)):
            problems.append(f"class_report.html shows {src}, which is not in the out folder")
    topics = {t for t, _, _ in tests}
    if images and len(images) != 2 + len(topics):
        problems.append(f"class_report.html has {len(images)} plots, not {2 + len(topics)}")
    check_likely_mistakes(md, results, problems)
    run = json.load(open(os.path.join(out, "run.json"), encoding="utf-8"))
    for student, r in results:
        p = r.get("extra_data", {}).get("provenance")
        if p is None or any(not p.get(k) for k in PROVENANCE) or p != run.get("provenance"):
            problems.append(f"results/{student}.json: its provenance is missing, incomplete or not run.json's")
            break


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--out", required=True)
    ap.add_argument("--manifest", required=True)
    ap.add_argument("--submissions", required=True)
    ap.add_argument("--stubs", required=True)
    ap.add_argument("--plant-fault", action="store_true")
    ap.add_argument("--plant-missing-provenance", action="store_true")
    ap.add_argument("--plant-mistake", action="store_true")
    a = ap.parse_args()
    tests, exercises = read_manifest(a.manifest)
    results = read_results(a.out)
    if a.plant_missing_provenance:
        results[0][1].get("extra_data", {}).pop("provenance", None)
    if a.plant_mistake:  # a likely mistake the item analysis never saw
        results[0][1].setdefault("extra_data", {}).setdefault("likely_mistakes", []).append(
            {"topic": "rotation", "exercise": "hat", "mistakes": ["a mistake planted by item_check.py"]})
    rows = count(results, tests, a.plant_fault)
    problems = []
    compare(a.out, results, tests, rows, problems)
    started = started_here(results, exercises, a.submissions, a.stubs)
    check_pages(a.out, tests, exercises, started, results, problems)
    for p in problems[:40]:
        print("PROBLEM:", p)
    if a.plant_missing_provenance:
        caught = any("provenance" in p for p in problems)
        print("planted fault (one result without its provenance):", "caught" if caught else "NOT caught")
        return 0 if caught else 1
    if a.plant_mistake:
        caught = any("likely mistake" in p for p in problems)
        print("planted fault (a likely mistake not counted):", "caught" if caught else "NOT caught")
        return 0 if caught else 1
    if a.plant_fault:
        print("planted fault (one verdict flipped):", "caught" if problems else "NOT caught")
        return 0 if problems else 1
    print(f"{len(results)} results, {len(tests)} tests, {len(exercises)} exercises "
          f"({sum(started.values())} exercise starts): {'agree' if not problems else 'DISAGREE'}")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
