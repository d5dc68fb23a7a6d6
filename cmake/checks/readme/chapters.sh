#!/usr/bin/env bash
# Every chapter's "Check your work" commands, exactly as the chapter writes them, on a finished
# workbook: a scratch clone whose exercises/*.cpp are the reference solutions (a student who
# has solved everything), with a build folder of its own. For each chapter: `check N` must
# pass every exercise, `scenes N` must build and run every scene of the chapter, and the
# chapter's example scene command must run. Prints each chapter's wall time.
#
#   chapters.sh <root> <work>
set -uo pipefail
root=$1 work=$2
here=$(cd "$(dirname "$0")" && pwd)
marker="<!-- run by test: readme: every chapter's Check your work, on a finished workbook -->"
fail() { echo "FAILED: $*" >&2; exit 1; }

rm -rf "$work" && mkdir -p "$work"
python3 "$here/readme.py" scratch "$root" "$work/workbook" || fail "cannot make the scratch clone"
cd "$work/workbook"
cp "$root"/solutions/*.cpp exercises/
chapters=$(ls -d chapters/[0-9][0-9]_*/ | sort)
for dir in $chapters; do
  page=${dir}README.md
  mapfile -t lines < <(python3 "$here/readme.py" block "$page" "$marker")
  [[ ${#lines[@]} -ge 2 ]] || fail "$page: no Check your work block marked for this test"
  start=$SECONDS
  for line in "${lines[@]}"; do
    echo "\$ $line"
    log=$work/last.txt
    bash -c "$line" >"$log" 2>&1
    status=$?
    sed 's/^/  | /' "$log" | tail -n 12
    [[ $status -eq 0 ]] || fail "$page: '$line' exited with status $status"
    case $line in
      "cmake/workbook check "*) grep -q "exercises pass\." "$log" && grep -q "^All " "$log" ||
                                  fail "$page: '$line' did not pass every exercise of the finished workbook" ;;
    esac
  done
  echo "== $page: every command of its Check your work ran as written ($((SECONDS - start)) s)"
done
echo "== Every chapter's Check your work ran as written on a finished workbook"
