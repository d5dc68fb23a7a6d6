#!/usr/bin/env python3
"""The same answers on a busy machine (cmake/checks/load/, README there).

Runs a few of the workbook's doors twice, once as the machine is and once beside CPU hogs that
this script starts and stops itself (busy loops, killed by their own process ids), and fails
unless everything but run times is identical: the verdicts, points, messages and likely mistakes
of a small class graded with `workbook_grade grade`, the results of a student's `check` on the
chapter with the heaviest grader, and every report key of the default run of a few sweep scenes.

  load.py --build <build> --root <workbook> --work <folder> [--hogs 4] [--plant]

--plant adds a planted door whose output depends on the wall clock (it counts how many steps fit
in a quarter of a second, the shape of a sweep that stops on seconds): the run must then fail,
naming it. Processes are started from argument vectors, never through a shell.
"""

import argparse
import json
import os
import pathlib
import re
import shutil
import signal
import subprocess
import sys
import time

# A key whose value is a run time, or is decided by run times (which method is fastest, by how
# much): these may change with the load, and nothing else may. Matched against each part of a
# key's path, e.g. "work_precision.grioli_100_fastest_time_s".
TIME_KEY = re.compile(
    r"(^|_)(wall|time|times|seconds|elapsed|speedup|fastest|ns|finished|started)(_|$)|_s$|^t_|_time_|time_s"
    r"|_over_plain$"  # a ratio of two run times (Chapter 7's right-hand sides)
)


def is_time_key(name):
    return bool(TIME_KEY.search(name))


def strip_times(value, path=""):
    """The value with every time-like key removed, at any depth, and every time-like column of a
    report's table ({"columns": [...], "rows": [[...], ...]}); lists keep their order."""
    if isinstance(value, dict) and isinstance(value.get("columns"), list) and isinstance(value.get("rows"), list):
        keep = [i for i, c in enumerate(value["columns"]) if not is_time_key(str(c))]
        table = {k: strip_times(v, path + "." + k) for k, v in value.items() if k not in ("columns", "rows")}
        table["columns"] = [value["columns"][i] for i in keep]
        table["rows"] = [[r[i] for i in keep if i < len(r)] if isinstance(r, list) else r for r in value["rows"]]
        return table
    if isinstance(value, dict):
        return {k: strip_times(v, path + "." + k) for k, v in value.items() if not is_time_key(k)}
    if isinstance(value, list):
        return [strip_times(v, path) for v in value]
    return value


def null_keys(value, path=""):
    """The paths of null values (a report writes NaN and infinity as null), but for a slope that
    its report says it could not fit (work_precision's <key>_slope_points under 3)."""
    if isinstance(value, dict):
        def explained(k):
            head = k[: k.rfind("_slope_") + len("_slope_")] if "_slope_" in k else None
            return head is not None and isinstance(value.get(head + "points"), (int, float)) and value[head + "points"] < 3
        return [p for k, v in value.items() if not (v is None and explained(k)) for p in null_keys(v, f"{path}.{k}")]
    if isinstance(value, list):
        return [p for i, v in enumerate(value) for p in null_keys(v, f"{path}[{i}]")]
    return [path] if value is None else []


def differences(a, b, path=""):
    """Where two JSON values differ, as readable lines (at most a few per value)."""
    if type(a) is not type(b):
        return [f"{path}: {json.dumps(a)[:80]} against {json.dumps(b)[:80]}"]
    if isinstance(a, dict):
        out = []
        for k in sorted(set(a) | set(b)):
            if k not in a or k not in b:
                out.append(f"{path}.{k}: only in the {'first' if k in a else 'second'} run")
            else:
                out += differences(a[k], b[k], f"{path}.{k}")
        return out
    if isinstance(a, list):
        if len(a) != len(b):
            return [f"{path}: {len(a)} items against {len(b)}"]
        out = []
        for i, (x, y) in enumerate(zip(a, b)):
            out += differences(x, y, f"{path}[{i}]")
        return out
    return [] if a == b else [f"{path}: {json.dumps(a)[:80]} against {json.dumps(b)[:80]}"]


def run(argv, log, cwd=None):
    """Runs argv (no shell) with its output in `log`; returns (exit status, CPU s of the child, wall s)."""
    before = os.times()
    start = time.monotonic()
    with open(log, "w") as out:
        status = subprocess.run(argv, stdout=out, stderr=subprocess.STDOUT, cwd=cwd, check=False).returncode
    after = os.times()
    cpu = (after.children_user - before.children_user) + (after.children_system - before.children_system)
    return status, cpu, time.monotonic() - start


class Hogs:
    """CPU hogs: busy loops, each a process of its own, stopped by their process ids."""

    def __init__(self, count):
        self.count = count
        self.procs = []

    def __enter__(self):
        for _ in range(self.count):
            self.procs.append(subprocess.Popen([sys.executable, "-c", "while True:\n    pass\n"]))
        time.sleep(0.5)  # let them start spinning
        return self

    def __exit__(self, *exc):
        for p in self.procs:
            os.kill(p.pid, signal.SIGKILL)
        for p in self.procs:
            p.wait()
        self.procs = []
        return False


def make_class(root, folder):
    """A small class: an honest submission (the reference's rotation.cpp and grioli.cpp), one
    with the sign of the sine term flipped in rotation_about, and one whose lab_angular_velocity
    never ends (an endless loop: its test must end as a timeout within its budget, and cost
    nothing else)."""
    if folder.exists():
        shutil.rmtree(folder)
    solutions = root / "solutions"
    rotation = (solutions / "rotation.cpp").read_text()
    grioli = (solutions / "grioli.cpp").read_text()
    flipped = rotation.replace("+ s * hat(u)", "- s * hat(u)")
    assert flipped != rotation, "solutions/rotation.cpp no longer has '+ s * hat(u)'"
    looping = rotation.replace(
        "Vec3 lab_angular_velocity(const Mat3& R, const Mat3& R_dot) {",
        "Vec3 lab_angular_velocity(const Mat3& R, const Mat3& R_dot) {\n"
        "    for (volatile double spin = 0;;) spin = spin + 1;",
    )
    assert looping != rotation, "solutions/rotation.cpp no longer has lab_angular_velocity as expected"
    for name, files in {
        "honest": {"rotation.cpp": rotation, "grioli.cpp": grioli},
        "sign_flipped": {"rotation.cpp": flipped, "grioli.cpp": grioli},
        "endless_loop": {"rotation.cpp": looping},
    }.items():
        d = folder / name / "exercises"
        d.mkdir(parents=True)
        for f, text in files.items():
            (d / f).write_text(text)


def read_json_files(folder, pattern):
    return {str(p.relative_to(folder)): json.loads(p.read_text()) for p in sorted(folder.glob(pattern))}


def class_door(a, tag):
    """The class graded: every result file and the class's own files, times stripped."""
    out = a.work / f"grades-{tag}"
    if out.exists():
        shutil.rmtree(out)
    # A budget of 5 s of processor time per process: the endless loop costs that much, and the
    # heaviest honest test uses about a fifth of it (1.0 s, student and judge together, graded
    # with -j 2 on an idle 2-core machine; tests/grading/README.md, "Budgets").
    argv = [str(a.build / "grading" / "workbook_grade"), "grade", "--setup", str(a.build / "grading"),
            str(a.work / "class"), str(out), "-j", "2", "--timeout", "5"]
    status, cpu, wall = run(argv, a.work / f"grade-{tag}.log")
    if status != 0:
        raise SystemExit(f"FAILED: workbook_grade grade exited with {status}: see {a.work}/grade-{tag}.log")
    got = {}
    for p in sorted(out.rglob("*")):
        if not p.is_file() or "logs" in p.relative_to(out).parts or p.name.startswith("."):
            continue
        rel = str(p.relative_to(out))
        if p.suffix == ".json":
            got[rel] = strip_times(json.loads(p.read_text()))
        elif p.suffix in (".csv", ".tsv", ".md", ".txt", ".html"):
            got[rel] = p.read_text()
    heaviest = heaviest_test(out / "logs" / "honest" / "timing.tsv")
    return got, f"graded the class in {cpu:.1f} s of CPU (the harness's children), {wall:.1f} s of wall time; {heaviest}"


def heaviest_test(timing):
    """The test whose student's process and judge used the most processor time (timing.tsv)."""
    best = None
    for line in timing.read_text().splitlines() if timing.exists() else []:
        f = line.split("\t")
        if len(f) >= 7:
            cpu = float(f[5]) + float(f[6])
            if best is None or cpu > best[0]:
                best = (cpu, f[0], float(f[2]), f[7] if len(f) > 7 else "0")
    if best is None:
        return "no timing.tsv"
    return (f"heaviest test '{best[1]}': {best[0]:.2f} s of processor time, {best[2]:.2f} s of wall time"
            + (", run again alone" if best[3] == "1" else ""))


def class_problems(files, tag):
    """What the class's results must say, idle or loaded: the honest submission passes every test
    it has (the heaviest grader, integrate over 100 periods, among them), the flipped sign fails
    rotation_about, and the endless loop times out on lab_angular_velocity alone."""
    results = {k: v for k, v in files.items() if isinstance(v, dict) and "tests" in v}
    if not results:
        return [f"{tag}: no result files with tests were read (files: {', '.join(sorted(files))[:300]})"]
    verdicts = {}
    for name, r in results.items():
        student = next((s for s in ("honest", "sign_flipped", "endless_loop") if s in name), None)
        for t in r["tests"]:
            x = t.get("extra_data", {})
            if x.get("verdict") != "missing":
                verdicts.setdefault(student, {})[t.get("name", "")] = (x.get("verdict"), x.get("exercise"))
    problems = []
    honest = verdicts.get("honest", {})
    if not any(e == "euler_poisson_rhs_gaps" for _, e in honest.values()):
        problems.append(f"{tag}: the honest submission has no euler_poisson_rhs_gaps test")
    problems += [f"{tag}: honest: {n}: {v}" for n, (v, _) in honest.items() if v != "pass"]
    flipped = {e for v, e in verdicts.get("sign_flipped", {}).values() if v != "pass"}
    if "rotation_about" not in flipped:
        problems.append(f"{tag}: sign_flipped: rotation_about passed")
    loops = verdicts.get("endless_loop", {})
    bad = [f"{n}: {v}" for n, (v, e) in loops.items() if (v == "timeout") != (e == "lab_angular_velocity")]
    if bad or not loops:
        problems.append(f"{tag}: endless_loop: only lab_angular_velocity may time out, and it must: {bad[:4]}")
    return problems


def check_door(a, tag):
    """A student's check of Chapter 5 (whose graders include the heaviest test) on the reference."""
    out = a.work / f"check-{tag}"
    if out.exists():
        shutil.rmtree(out)
    argv = [str(a.build / "grading" / "workbook_grade"), "check", "--setup", str(a.build / "grading"),
            "--folder", str(a.root / "solutions"), "--out", str(out), "5"]
    status, cpu, wall = run(argv, a.work / f"check-{tag}.log")
    got = {"exit status": status, **{k: strip_times(v) for k, v in read_json_files(out, "**/*.json").items()}}
    heaviest = heaviest_test(next(iter(sorted(out.rglob("timing.tsv"))), out / "none"))
    return got, f"check 5 in {wall:.1f} s of wall time (exit {status}); {heaviest}"


def scene_door(a, tag, spec):
    """A scene's run, as `<scene> [its options]`, with --json and --no-figure."""
    scene, *options = spec.split()
    argv = [str(a.build / "scenes" / scene), *options, "--json", "--no-figure", "--out", str(a.work / f"figures-{tag}")]
    (a.work / f"figures-{tag}").mkdir(exist_ok=True)
    log = a.work / f"{scene}-{tag}.json"
    status, cpu, wall = run(argv, log)
    text = log.read_text()
    try:
        report = json.loads(text[text.index("{"):])
    except ValueError:
        report = {"unreadable output": text[-400:]}
    return {"exit status": status, "report": strip_times(report)}, f"{scene} in {cpu:.1f} s of CPU, {wall:.1f} s of wall time (exit {status})"


def planted_door(a, tag):
    """The planted fault: a sweep that stops on seconds (how many steps fit in 0.25 s of wall time)."""
    start, steps = time.monotonic(), 0
    while time.monotonic() - start < 0.25:
        for _ in range(2000):
            pass
        steps += 1
    return {"points": steps // 200}, f"planted: {steps // 200} points"


def all_doors(a, tag):
    doors = {}
    if not a.only_planted:
        doors = {"class": lambda: class_door(a, tag), "check 5": lambda: check_door(a, tag)}
        for scene in a.scenes:
            doors["scene " + scene] = lambda scene=scene: scene_door(a, tag, scene)
    if a.plant:
        doors["planted wall-clock sweep"] = lambda: planted_door(a, tag)
    got = {}
    for name, door in doors.items():
        got[name], said = door()
        print(f"  {tag:6} {name}: {said}", flush=True)
    return got


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--build", required=True, type=pathlib.Path)
    p.add_argument("--root", required=True, type=pathlib.Path)
    p.add_argument("--work", required=True, type=pathlib.Path)
    p.add_argument("--hogs", type=int, default=4)
    # Chapter 7's sweep on the scenario whose slopes went missing on a loaded machine (100 Grioli
    # periods; the whole default run is 36 s of CPU, and `cmake/workbook run` beside hogs covers
    # it), and the default runs of the sweeps of Chapters 3 and 8.
    p.add_argument("--scenes", default="work_precision --scenario grioli_100,free_body_work_precision,"
                                        "quantized_work_precision",
                   help="comma-separated scene runs, each '<scene> [options]'")
    p.add_argument("--plant", action="store_true")
    p.add_argument("--only-planted", action="store_true", help="with --plant: the planted door alone (the self-test)")
    a = p.parse_args()
    a.scenes = [s for s in a.scenes.split(",") if s]
    a.work.mkdir(parents=True, exist_ok=True)
    make_class(a.root, a.work / "class")
    print(f"== idle (load average {os.getloadavg()[0]:.1f}):", flush=True)
    idle = all_doors(a, "idle")
    with Hogs(a.hogs):
        print(f"== beside {a.hogs} CPU hogs:", flush=True)
        loaded = all_doors(a, "loaded")
    print(f"== the hogs are stopped (load average {os.getloadavg()[0]:.1f})")
    problems = []
    for door in idle:
        d = differences(idle[door], loaded[door])
        if d:
            problems.append(f"{door}: {len(d)} differences besides run times, e.g.\n      " + "\n      ".join(d[:6]))
    for door, got in loaded.items():
        nulls = null_keys(got)
        if nulls:
            problems.append(f"{door}: null beside the hogs (not finite, or not measured): {', '.join(nulls[:6])}")
    if not a.only_planted:
        problems += class_problems(idle["class"], "idle") + class_problems(loaded["class"], "loaded")
    if problems:
        print("FAILED: the load changed more than run times:\n  " + "\n  ".join(problems))
        return 1
    print(f"== the same answers idle and beside {a.hogs} CPU hogs: {', '.join(idle)}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
