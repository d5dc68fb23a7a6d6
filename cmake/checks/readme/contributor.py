#!/usr/bin/env python3
"""The worked examples of the contributor's page (.github/CONTRIBUTING.md), applied to a tree.

Each file the page's examples touch is a fenced block right after a line

    <!-- example PART: new PATH -->                 create PATH with the block
    <!-- example PART: append PATH -->              add the block at the end of PATH
    <!-- example PART: before "TEXT" in PATH -->    insert the block, and a blank line, before the
                                                    last line of PATH that starts with TEXT
    <!-- example PART: above "TEXT" in PATH -->     insert the block right above that line (no blank
                                                    line: an #include joins its block)
    <!-- example PART: after "TEXT" in PATH -->     insert the block after that line

where PART is scene, exercise or chapter (the page's three recipes).

  contributor.py apply PAGE PART ROOT [--skip PATH]...   make PART's edits in ROOT, in the page's
                                                         order; --skip leaves out the edits of PATH
                                                         (a step a contributor forgot: the test's
                                                         planted faults)
  contributor.py list PAGE PART                          the files PART touches, one per line
  contributor.py names PAGE ROOT                         every CMake function the page names
                                                         (`workbook_...(`) is defined in ROOT's
                                                         CMake files; exit 1 naming each one not
"""
import re
import sys
from pathlib import Path

EXAMPLE = re.compile(r'^<!--\s*example (\w+):\s*(new|append|before|above|after)\s+(?:"([^"]*)"\s+in\s+)?(\S+)\s*-->$')


def examples(page):
    """(part, action, text, path, block lines) for every example block of the page, in order."""
    out, pending, fence, body = [], None, "", []
    for raw in Path(page).read_text(encoding="utf-8").split("\n"):
        if fence:  # a block ends at a line of its own fence: ```` holds a page that has ``` blocks
            if raw.strip() == fence:
                out.append(pending + (body,))
                pending, fence = None, ""
            else:
                body.append(raw)
            continue
        m = EXAMPLE.match(raw.strip())
        if m:
            pending = m.groups()
        elif pending and raw.startswith("```"):
            fence, body = raw[: len(raw) - len(raw.lstrip("`"))], []
        elif pending and raw.strip():
            raise SystemExit(f"contributor.py: {page}: the example for {pending[3]} is not followed by a code block")
    if pending:
        raise SystemExit(f"contributor.py: {page}: the example for {pending[3]} has no code block")
    return out


def last_line_starting(lines, text, path):
    found = [i for i, line in enumerate(lines) if line.startswith(text)]
    if not found:
        raise SystemExit(f"contributor.py: {path} has no line starting with '{text}'")
    return found[-1]


def apply(page, part, root, skip):
    root, done = Path(root), 0
    for p, action, text, rel, body in examples(page):
        if p != part or rel in skip:
            continue
        path = root / rel
        if action == "new":
            if path.exists():
                raise SystemExit(f"contributor.py: {rel} exists already; the example makes a new file")
            path.parent.mkdir(parents=True, exist_ok=True)
            path.write_text("\n".join(body) + "\n", encoding="utf-8")
        else:
            lines = path.read_text(encoding="utf-8").split("\n")
            if lines and lines[-1] == "":
                lines.pop()
            if action == "append":
                lines += body
            elif action == "before":
                at = last_line_starting(lines, text, rel)
                lines[at:at] = body + [""]
            elif action == "above":
                at = last_line_starting(lines, text, rel)
                lines[at:at] = body
            else:
                at = last_line_starting(lines, text, rel) + 1
                lines[at:at] = body
            path.write_text("\n".join(lines) + "\n", encoding="utf-8")
        print(f"{part}: {action} {rel}")
        done += 1
    if done == 0:
        raise SystemExit(f"contributor.py: {page} has no example for '{part}'")
    return 0


CMAKE_CALL = re.compile(r"\b(workbook_[a-z0-9_]+)\(")
CMAKE_DEFINITION = re.compile(r"^\s*(?:function|macro)\(\s*(workbook_[a-z0-9_]+)\b", re.M)


def names(page, root):
    """The CMake functions the page names that no CMake file of ROOT defines."""
    root = Path(root)
    defined = set()
    for path in list(root.glob("**/*.cmake")) + list(root.glob("**/CMakeLists.txt")):
        if "build" in path.relative_to(root).parts[:1]:
            continue
        defined |= set(CMAKE_DEFINITION.findall(path.read_text(encoding="utf-8", errors="replace")))
    named = dict.fromkeys(CMAKE_CALL.findall(Path(page).read_text(encoding="utf-8")))
    missing = [n for n in named if n not in defined]
    for n in missing:
        print(f"contributor.py: {page} names the CMake function {n}(), which no CMake file defines", file=sys.stderr)
    if not missing:
        print(f"{page}: the {len(named)} CMake functions it names are defined")
    return 1 if missing else 0


def main(argv):
    if len(argv) >= 4 and argv[0] == "apply":
        skip = [argv[i + 1] for i in range(4, len(argv) - 1) if argv[i] == "--skip"]
        return apply(argv[1], argv[2], argv[3], skip)
    if len(argv) == 3 and argv[0] == "names":
        return names(argv[1], argv[2])
    if len(argv) == 3 and argv[0] == "list":
        for rel in dict.fromkeys(e[3] for e in examples(argv[1]) if e[0] == argv[2]):
            print(rel)
        return 0
    print(__doc__, file=sys.stderr)
    return 2


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
