#!/usr/bin/env bash
# Gradescope's setup step for the Grioli workbook's autograder (made by `cmake/workbook gradescope`).
# Gradescope runs it once, as root, when it builds the autograder's image from autograder.zip
# (unpacked in /autograder/source): it installs what the grading run needs with apt-get (the
# image is Ubuntu) and builds the graders of the assignment's topics. run_autograder then
# grades each submission with them.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
# shellcheck source=/dev/null
. "$here/gradescope.conf"   # TOPICS, PACKAGES and PRIVATE_TESTS, written by cmake/workbook gradescope

missing=()
for entry in $PACKAGES; do
  pkg=${entry%%:*} probe=${entry#*:}
  if [[ $probe == /* ]]; then [[ -e $probe ]] && continue
  else command -v "$probe" >/dev/null 2>&1 && continue
  fi
  missing+=("$pkg")
done
if [[ ${#missing[@]} -gt 0 ]]; then
  echo "setup.sh: installing ${missing[*]}"
  apt-get update -qq
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

build=$here/workbook/build
# The instructor's private tests (private/, when packed with --private-tests): built into the
# judges alone; their sources and objects readable by root alone, so that a student's process,
# which runs as a user of its own where bubblewrap is refused, cannot read them either.
private=""
if [[ -n ${PRIVATE_TESTS:-} ]]; then
  private=$here/$PRIVATE_TESTS
  chmod -R go-rwx "$private"
fi
cmake -S "$here/workbook" -B "$build" -DCMAKE_BUILD_TYPE=Release -DWORKBOOK_IMPL=solutions \
      -DWORKBOOK_GRADING_TOPICS="$TOPICS" -DWORKBOOK_STUB_GATE=OFF -DWORKBOOK_PRIVATE_TESTS="$private" >/dev/null
cmake --build "$build" -j "${JOBS:-$(nproc)}" --target grading >/dev/null
if [[ -n $private ]]; then
  chmod -R go-rwx "$build/grading/judge" "$build/grading/private"
  find "$build" -type d -name 'private_*_objects.dir' -exec chmod -R go-rwx {} +
fi
chmod +x "$here/run_autograder"
[[ -e ${AUTOGRADER_ROOT:-/autograder}/run_autograder ]] && chmod +x "${AUTOGRADER_ROOT:-/autograder}/run_autograder"
echo "setup.sh: the graders of $TOPICS are built in $build"
