#!/usr/bin/env bash
# The contributor's page (.github/CONTRIBUTING.md) as a contributor follows it, in a scratch clone
# of the workbook with build folders of its own: each recipe's edits exactly as the page shows
# them (contributor.py applies the files after its `<!-- example PART: ... -->` lines), then each
# command of the page's blocks marked for this test, exactly as written.
#
#   contributor.sh <root> <work> [--plant scene-cmake|hint|contents|topic|cmake-name|catalogue]
#
# 0. The page names only CMake functions that exist (contributor.py names).
# 1. A scene: hello_rotation builds, runs with exit 0 and a JSON report holding error and
#    run_time_s, lists its options, and its smoke, bad-input and corner tests pass.
# 2. An exercise: rotation_angle, once committed, has its Hint 1; `check rotation_angle` on the
#    stub says "not started"; the hint lint finds its ladder; its grader passes on solutions/ and
#    the stub gate of the topic passes (every test passes on solutions/ and fails on the stubs);
#    rotation's catalogue of likely mistakes made again as the page says, then not stale
#    (workbook_mutants stale, the check of the test "grading: the catalogue of likely mistakes ...").
# 3. A chapter: the skeleton Chapter 9 with its topic sandbox is read from the contents
#    (contents.json, scenes-09 builds and runs its scene), its grader passes on solutions/ and
#    its stub gate passes, the book's structure, names and numbers checks and the command-block
#    check pass, and its own Check your work runs as written on a finished workbook.
# Every C++ file the examples touch must already be laid out as .clang-format says.
# --plant leaves out one step of the page (the scene's CMake lines, the hint ladder, the row of
# the contents, the new topic's workbook_topic line, the catalogue made again: then only the
# exercise's edits and the staleness check run) or names a CMake function that is gone
# (cmake-name): the walk must then fail (the self-tests of this test).
set -uo pipefail
root=$1 work=$2 plant=${3:-} what=${4:-}
here=$(cd "$(dirname "$0")" && pwd)
page=.github/CONTRIBUTING.md
marker="<!-- run by test: readme: a contributor adds a scene, an exercise and a chapter as .github/CONTRIBUTING.md says -->"
source "$(dirname "$0")/walk.sh"  # fail, run

skip=()
if [[ $plant == --plant ]]; then
  case $what in
    scene-cmake) skip=(--skip chapters/01_pure_rotations/CMakeLists.txt) ;;
    hint) skip=(--skip exercises/hints.md) ;;
    contents) skip=(--skip chapters/README.md) ;;
    topic) skip=(--skip CMakeLists.txt) ;;
    cmake-name | catalogue) ;;
    *) fail "unknown planted fault '$what' (scene-cmake, hint, contents, topic, cmake-name or catalogue)" ;;
  esac
  [[ ${#skip[@]} -eq 0 ]] || echo "== Planted: the walk leaves out the page's edit of ${skip[1]}"
fi

rm -rf "$work" && mkdir -p "$work"
python3 "$here/readme.py" scratch "$root" "$work/workbook" || fail "cannot make the scratch clone"
cd "$work/workbook" || fail "no scratch clone"
export GIT_AUTHOR_NAME=contributor GIT_AUTHOR_EMAIL=contributor@localhost
export GIT_COMMITTER_NAME=contributor GIT_COMMITTER_EMAIL=contributor@localhost
[[ -f $page ]] || fail "$page is missing"
if [[ $what == cmake-name ]]; then
  echo "== Planted: the page names workbook_scene_fails(), removed from the CMake files"
  printf '\nA scene whose own check must fail: `workbook_scene_fails(<scene> <label> ARGS ...)`.\n' >>"$page"
fi
python3 "$here/contributor.py" names "$page" . || fail "$page names a CMake function that does not exist (above)"


# apply <part>: the page's edits of one recipe; the C++ files it touched must be formatted.
apply() {
  python3 "$here/contributor.py" apply "$page" "$1" . "${skip[@]}" || fail "cannot apply the page's $1 example"
  if command -v clang-format >/dev/null; then
    while read -r f; do
      [[ $f == *.cpp || $f == *.hpp ]] || continue
      [[ -f $f ]] || continue
      clang-format --dry-run --Werror "$f" 2>"$work/format.txt" ||
        fail "$f, as the page's $1 example leaves it, is not laid out as .clang-format says: $(head -3 "$work/format.txt")"
    done < <(python3 "$here/contributor.py" list "$page" "$1")
  fi
}

block() {
  mapfile -t lines < <(python3 "$here/readme.py" block "$page" "$marker" "$1")
  [[ ${#lines[@]} -ge 2 ]] || fail "$page: no block $1 marked for this test"
}

# The repository's own check that the catalogue of likely mistakes is not stale (what the test
# "grading: the catalogue of likely mistakes has the hash ..." runs), in build/solutions.
stale_check="build/solutions/grading/workbook_mutants stale --setup build/solutions/grading --solutions solutions --catalogue tests/grading/mutants/catalogue"

# The planted stale catalogue: the exercise's edits, committed, and the staleness check alone.
if [[ $what == catalogue ]]; then
  echo "== Planted: the exercise recipe without its catalogue step"
  apply exercise
  block 2
  run 0 "${lines[0]}"
  run 0 "${lines[1]}"
  run 0 "cmake -S . -B build/solutions >/dev/null && cmake --build build/solutions --target grading workbook_mutants >/dev/null"
  bash -c "$stale_check" >"$work/stale.txt" 2>&1 ||
    fail "the catalogue of likely mistakes is stale after the exercise recipe: $(head -3 "$work/stale.txt")"
  echo "== The planted stale catalogue was not seen"
  exit 0
fi

# 1. A scene.
start=$SECONDS
apply scene
block 1
for line in "${lines[@]}"; do
  case $line in
    *"--json"*)
      run 0 "$line"
      python3 -c 'import json,sys; r=json.load(open(sys.argv[1])); assert "error" in r and "run_time_s" in r' "$last" ||
        fail "'$line' printed no JSON report with error and run_time_s" ;;
    *"--list-options"*) run 0 "$line" '"samples"' '"axis"' ;;
    ctest*) run 0 "$line" "100% tests passed" "scene: hello_rotation" "bad input: hello_rotation" "corner: hello_rotation" ;;
    *) run 0 "$line" ;;
  esac
done
echo "== 1. The scene: every command of the page did what it says ($((SECONDS - start)) s)"

# 2. An exercise.
start=$SECONDS
apply exercise
block 2
for line in "${lines[@]}"; do
  case $line in
    *"check rotation_angle --hint 1"*) run 0 "$line" "Hint 1 of 3 for rotation_angle" ;;
    *"check rotation_angle"*) run 1 "$line" "rotation_angle" "not started" ;;
    *"workbook_hints lint"*) run 0 "$line" "0 problem(s)" ;;
    ctest*) run 0 "$line" "100% tests passed" "ch01:rotation_angle:" ;;
    *stub_gate*) run 0 "$line" ;;
    *) run 0 "$line" ;;
  esac
done
grep -q "^exercise	rotation	rotation_angle	" build/exercises/grading/manifest.txt ||
  fail "the grading manifest does not list rotation_angle"
# Its topic's catalogue of likely mistakes, made again as the page says; then not stale.
block 3
for line in "${lines[@]}"; do run 0 "$line"; done
run 0 "$stale_check"
echo "== 2. The exercise: hint, not started on the stub, passes on the reference, the stub gate, the catalogue ($((SECONDS - start)) s)"

# 3. A chapter.
start=$SECONDS
apply chapter
block 4
for line in "${lines[@]}"; do
  case $line in
    *"-R '^ch09:'"*) run 0 "$line" "100% tests passed" "ch09:quarter_turns:" ;;
    ctest*) run 0 "$line" "100% tests passed" "book: every chapter is a lesson" "readme: every command block" ;;
    *) run 0 "$line" ;;
  esac
done
python3 -c 'import json,sys; assert any(c["folder"] == "09_sandbox" and c["label"] == "ch09" for c in json.load(open(sys.argv[1]))["chapters"])' \
  build/solutions/contents.json || fail "CMake did not read Chapter 9 from the contents"
ls build/solutions/figures/09_sandbox/sandbox_spin.json >/dev/null 2>&1 || fail "scenes-09 did not run the chapter's scene"
# The new chapter's Check your work, as chapters.sh runs every chapter's: on a finished workbook.
cp solutions/sandbox.cpp exercises/sandbox.cpp
mapfile -t lines < <(python3 "$here/readme.py" block chapters/09_sandbox/README.md \
  "<!-- run by test: readme: every chapter's Check your work, on a finished workbook -->")
[[ ${#lines[@]} -ge 2 ]] || fail "chapters/09_sandbox/README.md: no Check your work block"
for line in "${lines[@]}"; do
  case $line in
    "cmake/workbook check "*) run 0 "$line" "Chapter 9, A sandbox chapter: 1 of 1 exercises pass" ;;
    "cmake/workbook scenes "*) run 0 "$line" "Your code: sandbox" "sandbox_spin" ;;
    *) run 0 "$line" ;;
  esac
done
git checkout -q exercises/sandbox.cpp
echo "== 3. The chapter: in the build, its graders and stub gate, the book's checks, its Check your work ($((SECONDS - start)) s)"
echo "== The contributor's walk: every recipe of $page did what the page says"
