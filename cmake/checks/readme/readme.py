#!/usr/bin/env python3
"""The commands the workbook's pages tell a user to type, and what runs them.

Every ```sh block of the front page (README.md), the instructor's manual
(tests/grading/README.md), the maintainers' page (cmake/README.md), the contributors' page
(.github/CONTRIBUTING.md) and each chapter's "Check your work" follows a marker line that says what runs it, exactly as written:

    <!-- run by test: NAME -->     the CTest test NAME runs it (cmake/checks/readme/*.sh read it from here)
    <!-- run by .ci/run -->        .ci/run runs each of its lines as written
    <!-- run by PATH ... -->       the script PATH (a file of the workbook) reads it from here
    <!-- not run: WHY -->          nothing runs it, and WHY says why

  readme.py check ROOT TESTS_JSON    every block has a marker, and every marker holds
                                     (TESTS_JSON: `ctest --show-only=json-v1`)
  readme.py block FILE MARKER [N]    the lines of the N-th block (1: the first) after the line
                                     MARKER, as a user types them (one per line)
  readme.py scratch ROOT DEST        a scratch clone of ROOT's working tree (tracked and new
                                     files, not ignored ones) in DEST, committed, so that its
                                     HEAD is what the tree holds now
  readme.py selftest WORK            proves `check` flags a block with no marker, a marker
                                     naming no test, and a .ci/run that does not run its block
"""
import json
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

MARKER = re.compile(r"^<!--\s*(run by|not run:)\s*(.*?)\s*-->$")


def unquote(line):
    """A line as written inside a blockquote or a list item: without '> ' and indentation."""
    s = line.rstrip("\n")
    while True:
        t = s.lstrip()
        if t.startswith(">"):
            s = t[1:]
            if s.startswith(" "):
                s = s[1:]
            continue
        return t


def blocks(path):
    """(line number of the fence, marker or None, [lines]) for every ```sh block of a page."""
    out = []
    lines = path.read_text(encoding="utf-8").split("\n")
    marker, inside, body, start = None, False, [], 0
    recent = []  # the last non-empty lines before a block
    for i, raw in enumerate(lines, 1):
        line = unquote(raw)
        if not inside and line in ("```sh", "```bash"):
            marker = next((m for m in reversed(recent[-2:]) if MARKER.match(m)), None)
            inside, body, start = True, [], i
        elif inside and line.startswith("```"):
            out.append((start, marker, body))
            inside, recent = False, []
        elif inside:
            body.append(line)
        elif line:
            recent.append(line)
    return out


def pages(root):
    found = [root / "README.md", root / "tests/grading/README.md", root / "cmake/README.md", root / ".github/CONTRIBUTING.md"]
    found += sorted((root / "chapters").glob("[0-9][0-9]_*/README.md"))
    return [p for p in found if p.exists()]


def check_chapter(path, body_blocks, problems):
    """In a chapter only the blocks of "Check your work" need a marker (its other blocks are
    the predict-then-run commands, checked by name by the snippet checker)."""
    text = path.read_text(encoding="utf-8").split("\n")
    start = next((i for i, l in enumerate(text, 1) if l.strip() == "## Check your work"), None)
    end = next((i for i, l in enumerate(text, 1) if start and i > start and l.startswith("## ")), len(text) + 1)
    if start is None:
        problems.append(f"{path}: no '## Check your work'")
        return []
    return [b for b in body_blocks if start < b[0] < end]


def check(root, tests_json):
    root = Path(root)
    names = {t["name"] for t in json.loads(Path(tests_json).read_text())["tests"]}
    ci = (root / ".ci/run").read_text(encoding="utf-8").split("\n") if (root / ".ci/run").exists() else []
    problems, counted = [], 0
    for page in pages(root):
        rel = page.relative_to(root)
        found = blocks(page)
        if rel.parts[0] == "chapters":
            found = check_chapter(page, found, problems)
        for start, marker, body in found:
            counted += 1
            where = f"{rel}:{start}"
            m = MARKER.match(marker) if marker else None
            if not m:
                problems.append(f"{where}: a ```sh block with no '<!-- run by ... -->' or '<!-- not run: ... -->' above it")
                continue
            kind, what = m.group(1), m.group(2)
            if kind == "not run:":
                if len(what) < 10:
                    problems.append(f"{where}: 'not run:' must say why")
            elif what.startswith("test:"):
                name = what[5:].strip()
                if name not in names:
                    problems.append(f"{where}: runs it the test '{name}', which CTest does not have")
            elif what == ".ci/run":
                for line in body:
                    command = line.split("#")[0].strip()
                    if command and not any(c.split("#")[0].strip() == command for c in ci):
                        problems.append(f"{where}: .ci/run does not run '{command}'")
            else:
                script = what.split()[0].rstrip(",")
                if not (root / script).is_file():
                    problems.append(f"{where}: runs it '{script}', which is not a file of the workbook")
    for p in problems:
        print("  " + p)
    print(f"{counted} command blocks checked in {len(pages(root))} pages: {len(problems)} problems")
    return 1 if problems else 0


def block(path, marker, n=1):
    seen = 0
    for start, m, body in blocks(Path(path)):
        if m == marker:
            seen += 1
            if seen == n:
                print("\n".join(body))
                return 0
    print(f"readme.py: {path} has no block {n} after '{marker}'", file=sys.stderr)
    return 1


def scratch(root, dest):
    root, dest = Path(root), Path(dest)
    if dest.exists():
        shutil.rmtree(dest)
    dest.mkdir(parents=True)
    listed = subprocess.run(["git", "-C", str(root), "ls-files", "-z", "--cached", "--others", "--exclude-standard"],
                            check=True, capture_output=True).stdout.decode().split("\0")
    for name in filter(None, listed):
        src = root / name
        if src.is_file() and not src.is_symlink():
            (dest / name).parent.mkdir(parents=True, exist_ok=True)
            shutil.copy2(src, dest / name)
    env = dict(os.environ, GIT_AUTHOR_NAME="readme", GIT_AUTHOR_EMAIL="readme@localhost",
               GIT_COMMITTER_NAME="readme", GIT_COMMITTER_EMAIL="readme@localhost")
    for args in (["init", "-q"], ["add", "-A"], ["commit", "-q", "-m", "scratch clone"]):
        subprocess.run(["git", "-C", str(dest)] + args, check=True, env=env)
    return 0


def selftest(work):
    """Plants each fault `check` hunts in a small tree; each must be flagged."""
    work = Path(work)
    if work.exists():
        shutil.rmtree(work)
    (work / ".ci").mkdir(parents=True)
    (work / ".ci/run").write_text("cmake/workbook test\n")
    tests = work / "tests.json"
    tests.write_text(json.dumps({"tests": [{"name": "readme: a real test"}]}))
    cases = {
        "no marker": "```sh\ncmake/workbook check 1\n```\n",
        "unknown test": "<!-- run by test: readme: no such test -->\n```sh\ncmake/workbook check 1\n```\n",
        "not in .ci/run": "<!-- run by .ci/run -->\n```sh\ncmake/workbook run\n```\n",
        "bare not run": "<!-- not run: -->\n```sh\ncmake/workbook run\n```\n",
    }
    good = "<!-- run by test: readme: a real test -->\n```sh\ncmake/workbook check 1\n```\n" \
           "> <!-- run by .ci/run -->\n> ```sh\n> cmake/workbook test   # the suite\n> ```\n"
    (work / "README.md").write_text(good)
    status = 0
    if check(work, tests) != 0:
        print("selftest: a page whose blocks all have true markers was flagged")
        status = 1
    for name, text in cases.items():
        (work / "README.md").write_text(good + text)
        if check(work, tests) == 0:
            print(f"selftest: the planted fault '{name}' was not flagged")
            status = 1
    print("selftest: " + ("every planted fault flagged" if status == 0 else "FAILED"))
    return status


def main(argv):
    if len(argv) >= 3 and argv[0] == "check":
        return check(argv[1], argv[2])
    if len(argv) in (3, 4) and argv[0] == "block":
        return block(argv[1], argv[2], int(argv[3]) if len(argv) == 4 else 1)
    if len(argv) == 3 and argv[0] == "scratch":
        return scratch(argv[1], argv[2])
    if len(argv) == 2 and argv[0] == "selftest":
        return selftest(argv[1])
    print(__doc__, file=sys.stderr)
    return 2


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
