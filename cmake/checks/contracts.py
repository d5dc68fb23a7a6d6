#!/usr/bin/env python3
"""Contracts state every rule the graders check (issue 41, item 4).

  contracts.py check --root ROOT             every rejection a grader tests is in the contract
  contracts.py selftest --root ROOT --work W plants three faults in a copy; each must be flagged

A *rejection check* is a CHECK_THROWS / CHECK_THROWS_AS of a grader (tests/<topic>_test.cpp) whose
call is an exercise, a function declared in exercises/rigid/<topic>.hpp. Its *contract* is the
comment above that declaration (a declaration right below another shares the comment above the
first), the comment at the top of the header (its conventions), and the comment of a function it
points to ("as rotation_about does"). A student reads only that, so it must say:

  * the exception the check expects (std::invalid_argument, std::domain_error, ...);
  * "finite" or "NaN" when an argument of the call is NaN or infinite;
  * "empty", "no ...", "fewer than" or "at least" when a vector, a state or a list is passed empty;
  * "zero", "> 0" or "positive" when a vector argument is zero.

What is bad in a call is read from its arguments, each against its parameter's type in the
declaration (an empty `{}` is an empty list only where the parameter is a std::vector or a VecX,
not a struct of defaults). A line can say what it tests where the arguments do not show it, with
a comment `// contract: <words>`: the contract must then hold every one of those words.

Written by hand: no Debian package cross-checks C++ comments against doctest assertions. It
reads declarations with regular expressions, which is enough for the workbook's own headers (one
declaration a line, parameters on one or two lines) and fails loudly when a call cannot be
matched to a declaration.
"""
import argparse
import pathlib
import re
import shutil
import sys

NONFINITE = re.compile(r"\bnan_?\b|\bNAN\b|\binf_?\b|infinity|quiet_NaN|\bbad\b")
KINDS = {
    "a non-finite argument": (r"finite|NaN", "'finite' or 'NaN'"),
    "an empty argument": (r"empty|\bno \w+|none|fewer than|at least", "'empty', 'no ...', 'fewer than' or 'at least'"),
    "a zero vector": (r"zero|> ?0|positive", "'zero', '> 0' or 'positive'"),
}


def comment_lines(lines, k):
    """The comment block that ends on line k (0-based), and the line before it."""
    block = []
    while k >= 0 and lines[k].lstrip().startswith("//"):
        block.insert(0, lines[k])
        k -= 1
    return block, k


DECL = re.compile(r"^(?:template <[^>]*>\s*)?(?:inline |constexpr |\[\[nodiscard\]\] )*"
                  r"(?P<ret>[A-Za-z_][\w:<>, ]*?[\s*&]+)(?P<name>\w+)\((?P<params>[^;{]*?)\)\s*(?:const)?\s*;")


def declarations(text):
    """name -> [(parameter types, comment)] of a header's function declarations, and its head."""
    lines = text.split("\n")
    head = []
    for line in lines:
        if line.startswith("namespace"):
            break
        if line.startswith("//"):
            head.append(line)
    found = {}
    joined = []  # (first line, last line, text) of a declaration, which may span a few lines
    i = 0
    while i < len(lines):
        line = lines[i]
        if re.match(r"^[A-Za-z_\[]", line) and "(" in line and not line.startswith(("namespace", "struct", "using")):
            text = line
            j = i
            while ";" not in text and "{" not in text and j + 1 < len(lines) and j < i + 3:
                j += 1
                text += " " + lines[j].strip()
            joined.append((i, j, text))
            i = j + 1
        else:
            i += 1
    previous_end, previous_comment = -10, ""
    for start, end, text in joined:
        m = DECL.match(text)
        if not m:
            continue
        above = start - 1
        if above >= 0 and lines[above].strip() == "};":  # the struct it returns, declared right above
            while above > 0 and not lines[above].startswith("struct "):
                above -= 1
            above -= 1
        block, _ = comment_lines(lines, above)
        if block:
            comment = "\n".join(block)
        elif start - 1 == previous_end:  # right below another declaration: the comment above that one
            comment = previous_comment
        else:
            comment = ""
        found.setdefault(m.group("name"), []).append((split_top(m.group("params")), comment))
        previous_end, previous_comment = end, comment
    return "\n".join(head), found


def split_top(s):
    """Split at the commas outside brackets."""
    out, depth, cur = [], 0, ""
    for c in s:
        if c in "([{<":
            depth += 1
        elif c in ")]}>":
            depth -= 1
        if c == "," and depth == 0:
            out.append(cur.strip())
            cur = ""
        else:
            cur += c
    if cur.strip():
        out.append(cur.strip())
    return out


def load_contracts(root):
    contracts = {}
    for hpp in sorted((root / "exercises" / "rigid").glob("*.hpp")):
        head, found = declarations(hpp.read_text())
        for name, overloads in found.items():
            contracts[name] = (hpp.relative_to(root).as_posix(), head, overloads)
    return contracts


def balanced(src, open_at):
    depth = 0
    for i in range(open_at, len(src)):
        if src[i] == "(":
            depth += 1
        elif src[i] == ")":
            depth -= 1
            if depth == 0:
                return src[open_at + 1:i]
    return src[open_at + 1:]


def contract_text(contracts, name, params_count):
    path, head, overloads = contracts[name]
    comments = [c for p, c in overloads if len(p) >= params_count] or [c for _, c in overloads]
    text = head + "\n" + "\n".join(comments)
    for other in re.findall(r"as (\w+) does", text):
        if other in contracts and other != name:
            text += "\n" + "\n".join(c for _, c in contracts[other][2])
    return path, text, overloads


def kinds_of(args, overloads):
    """What is bad in a call's arguments, read against the declaration's parameter types."""
    kinds = set()
    params = max((p for p, _ in overloads), key=len, default=[])
    for k, arg in enumerate(args):
        ptype = params[k] if k < len(params) else ""
        if NONFINITE.search(arg):
            kinds.add("a non-finite argument")
        container = re.search(r"vector|VecX", ptype)
        if container and re.fullmatch(r"\{\s*\}|VecX\(\s*\)|VecX\(0\)|\w*::?VecX::Zero\(0\)", arg):
            kinds.add("an empty argument")
        if re.search(r"Vec3", ptype) and re.fullmatch(r"(rigid::)?Vec3::Zero\(\)|Vec3\(\s*-?0\.0,\s*-?0\.0,\s*-?0\.0\)", arg):
            kinds.add("a zero vector")
    return kinds


def check(root):
    contracts = load_contracts(root)
    problems, count, exercises = [], 0, set()
    for grader in sorted((root / "tests").glob("*_test.cpp")):
        src = grader.read_text()
        lines = src.split("\n")
        for m in re.finditer(r"CHECK_THROWS(?:_AS|_WITH_AS|_WITH)?\s*\(", src):
            body = balanced(src, m.end() - 1)
            line_no = src.count("\n", 0, m.start()) + 1
            call = None
            for c in re.finditer(r"rigid::(\w+)\s*(?:<[^<>]*>)?\s*\(", body):
                if c.group(1) in contracts:
                    call = c
                    break
            if not call:
                continue
            name = call.group(1)
            args = split_top(balanced(body, call.end() - 1))
            path, text, overloads = contract_text(contracts, name, len(args))
            where = f"{grader.relative_to(root).as_posix()}:{line_no}"
            count += 1
            exercises.add(name)
            missing = []
            exc = re.search(r",\s*(std::\w+)\s*$", body.strip())
            if exc and exc.group(1).split("::")[1] not in text:
                missing.append(f"the exception it expects, {exc.group(1)}")
            for kind in sorted(kinds_of(args, overloads)):
                pattern, words = KINDS[kind]
                if not re.search(pattern, text, re.I):
                    missing.append(f"that it rejects {kind} (it says none of {words})")
            stated = " ".join(lines[line_no - 1:line_no + body.count("\n")])
            said = re.search(r"//\s*contract:\s*(.+)$", stated) or (
                re.search(r"//\s*contract:\s*(.+)$", lines[line_no - 2]) if line_no >= 2 else None)
            if said:
                for word in said.group(1).split():
                    if word.lower() not in text.lower():
                        missing.append(f"the word '{word}' its comment says the contract holds")
            for what in missing:
                problems.append(f"{where}: rigid::{name} is tested to reject it, but the contract in {path} "
                                f"does not state {what}")
    return count, len(exercises), problems


def run_check(root):
    count, exercises, problems = check(root)
    if count == 0:
        print("FAILED: no rejection check of an exercise found (is --root the workbook?)")
        return 1
    for p in problems:
        print(p)
    if problems:
        print(f"FAILED: {len(problems)} rules the graders check are not in the contracts "
              f"({count} rejection checks of {exercises} exercises read)")
        return 1
    print(f"{count} rejection checks of {exercises} exercises: each rule is stated in the exercise's contract")
    return 0


def plant(work, root, what):
    tree = work / what
    if tree.exists():
        shutil.rmtree(tree)
    (tree / "exercises").mkdir(parents=True)
    shutil.copytree(root / "exercises" / "rigid", tree / "exercises" / "rigid")
    shutil.copytree(root / "tests", tree / "tests", ignore=shutil.ignore_patterns("grading", "include"))
    return tree


def selftest(root, work):
    """Each planted fault must be flagged, on the line it was planted; the copy itself is clean."""
    work.mkdir(parents=True, exist_ok=True)
    failures = 0
    clean = plant(work, root, "clean")
    if check(clean)[2]:
        print("FAILED: the unplanted copy is flagged")
        failures += 1
    plants = []
    # 1. The rule of an empty initial state taken out of integrators.hpp.
    t = plant(work, root, "empty")
    h = t / "exercises/rigid/integrators.hpp"
    text = re.sub(r"empty|no output times|fewer than|at least", "odd", h.read_text())
    h.write_text(text)
    plants.append(("integrators.hpp without its empty-state rule", t, "rigid::integrate_rk4", "an empty argument"))
    # 2. "finite" and "NaN" taken out of rotation.hpp.
    t = plant(work, root, "finite")
    h = t / "exercises/rigid/rotation.hpp"
    h.write_text(re.sub(r"[Nn]on-finite|finite|NaN", "odd", h.read_text()))
    plants.append(("rotation.hpp without 'finite'", t, "rigid::rotation_about", "a non-finite argument"))
    # 3. A grader that tests an exception the contract never names.
    t = plant(work, root, "exception")
    g = t / "tests/rotation_test.cpp"
    src = g.read_text()
    anchor = 'TEST_CASE("hat: hat(w) x equals the cross product w x x") {\n'
    if anchor not in src:
        print("FAILED: the self-test's anchor in tests/rotation_test.cpp moved")
        return 1
    g.write_text(src.replace(anchor, anchor + "CHECK_THROWS_AS(rigid::hat(Vec3(1, 2, 3)), std::domain_error);\n"))
    plants.append(("a grader expecting std::domain_error from hat", t, "rigid::hat", "std::domain_error"))
    for label, tree, function, needle in plants:
        flagged = [p for p in check(tree)[2] if function + " " in p and needle in p]
        if flagged:
            print(f"flagged, as it must be ({label}): {flagged[0]}")
        else:
            print(f"FAILED: the planted fault was not flagged: {label}")
            failures += 1
    return 1 if failures else 0


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("what", choices=["check", "selftest"])
    p.add_argument("--root", required=True, type=pathlib.Path)
    p.add_argument("--work", type=pathlib.Path)
    a = p.parse_args()
    if a.what == "check":
        return run_check(a.root)
    if not a.work:
        p.error("selftest needs --work")
    return selftest(a.root, a.work)


if __name__ == "__main__":
    sys.exit(main())
