#!/usr/bin/env bash
# The book in a real browser: headless Chromium opens every page of the rendered book and
# checks that every image loaded, the math is laid out as MathML, no link is broken, and
# nothing is wider than the content column or hides part of itself (cmake/book/tests/browser_check.js);
# then it takes a full-page screenshot (the whole height of the page, 1200 px wide) of each
# chapter and of the other pages of prose into <book>/screenshots/ (a build artefact: look at
# them), and checks that each is as tall as its page; then the motion viewers, in
# cmake/book/tests/browser_motion.py.
#
#   cmake/book/tests/browser_test.sh <book folder> <scratch folder> [<chapters folder>]
#
# With the chapters' sources (<root>/chapters), every motion viewer they mark (a line
# <!-- motion: ... -->) must be in the book and pass: a viewer the renderer dropped fails.
#
# Exit status 0 when all is well, 1 on a problem, 77 (CTest: skipped) when no Chromium is
# installed and CI is not set. `cmake/workbook test` installs Chromium (Debian: chromium).
set -euo pipefail

book=$(cd "$1" && pwd)
work=$2
chapters=${3:-}
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)

source "$here/../../support/chromium.sh"
[[ -f $book/pages.txt ]] || { echo "No book in $book (pages.txt is missing): render it first."; exit 1; }

rm -rf "$work"
mkdir -p "$work"
work=$(cd "$work" && pwd)

# One fresh profile per run of the browser; no network, no first-run business.
chrome() {
  local profile
  profile=$(mktemp -d "$work/profile.XXXXXX")
  timeout 120 "$browser" --headless --no-sandbox --disable-gpu --disable-quic --no-first-run \
    --disable-background-networking --disable-component-update --disable-sync \
    --disable-dev-shm-usage --hide-scrollbars --user-data-dir="$profile" "$@" 2>>"$work/chromium.log"
}

# The harness: the list of pages, then the checks.
{
  echo '<!DOCTYPE html><html><head><meta charset="utf-8"><title>The book in a browser</title></head><body>'
  echo '<pre id="book-test-result">the checks did not run</pre>'
  echo '<script>const BOOK_PAGES = ['
  while IFS=$'\t' read -r file kind _title; do
    [[ -n $file ]] && printf '{"name": "%s", "kind": "%s", "url": "file://%s/%s"},\n' "$file" "$kind" "$book" "$file"
  done <"$book/pages.txt"
  echo '];'
  printf 'const SELFTEST_PAGE = {"name": "broken-on-purpose.html", "kind": "page", "url": "file://%s/broken-on-purpose.html"};\n' "$work"
  echo '</script><script src="browser_check.js"></script></body></html>'
} >"$work/harness.html"
cp "$here/browser_check.js" "$work/browser_check.js"
cp "$here/../web/book.css" "$work/book.css"
cat >"$work/broken-on-purpose.html" <<'EOF'
<!DOCTYPE html><html><head><meta charset="utf-8"><title>Broken on purpose</title>
<link rel="stylesheet" href="book.css"></head><body><main>
<p>A figure that is not there: <img src="missing-figure.svg" alt="missing"></p>
<p><a href="missing-page.html">A page that is not there</a>; <a href="#no-such-anchor">an anchor that is not there</a>.</p>
<p>Math that was left as TeX: $\frac{a}{b}$.</p>
<pre style="white-space: pre; width: 1500px">a line of code far too long for the column, and a box made as wide as it</pre>
<pre style="white-space: pre; overflow-x: auto">a scrolling line of code: xxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxx</pre>
<table style="width: 1400px"><tr><td>a table wider than the column</td></tr></table>
<math display="block"><mrow><mi>x</mi><mo>=</mo><mn>111111111111111111111111111111111111111111111111111111111111111111111111111111111111111111111111</mn></mrow></math>
<h1 style="overflow-wrap: normal">Averyveryveryveryveryveryveryveryveryveryveryveryveryveryveryverylongwordthatcannotbreakanywhereatallinthiscolumn</h1>
<nav class="toc" style="position: fixed; top: 4rem; left: -1.5rem; width: 14rem">On this page, cut off at the left edge</nav>
<div class="clip" style="overflow: hidden; width: 300px"><img alt="" style="max-width: none; width: 900px; height: 20px" src="data:image/svg+xml;utf8,<svg xmlns='http://www.w3.org/2000/svg' width='900' height='20'/>"></div>
</main></body></html>
EOF

echo "Checking $(wc -l <"$book/pages.txt") pages with $("$browser" --version 2>/dev/null | head -1)"
chrome --allow-file-access-from-files --virtual-time-budget=60000 --dump-dom "file://$work/harness.html" >"$work/harness.dom" || true
result=$(sed -n '/<pre id="book-test-result">/,/<\/pre>/p' "$work/harness.dom" |
         sed -e 's/.*<pre id="book-test-result">//' -e 's/<\/pre>.*//' \
             -e 's/&lt;/</g' -e 's/&gt;/>/g' -e 's/&quot;/"/g' -e 's/&amp;/\&/g')
echo "$result"
status=0
if ! grep -q '^DONE$' <<<"$result"; then
  echo "The checks did not finish (see $work/chromium.log)."
  status=1
elif grep -q '^FAIL' <<<"$result" || ! grep -q '^PASSED$' <<<"$result"; then
  status=1
fi

# Full-page screenshots of every page of prose (not the source listings), two browsers at a
# time: the window is as tall as the page, as the checks measured it.
shots=$book/screenshots
rm -rf "$shots"
mkdir -p "$shots"
declare -A height
while read -r _ name px; do height[$name]=$px; done < <(grep '^HEIGHT ' <<<"$result")
pids=()
while IFS=$'\t' read -r file kind _title; do
  [[ -z $file || $kind == code ]] && continue
  h=${height[$file]:-2000}
  chrome --screenshot="$shots/${file%.html}.png" --window-size=1200,"$h" "file://$book/$file" >/dev/null &
  pids+=($!)
  if (( ${#pids[@]} >= 2 )); then wait "${pids[0]}" || true; pids=("${pids[@]:1}"); fi
done <"$book/pages.txt"
for pid in "${pids[@]}"; do wait "$pid" || true; done
# The height of a PNG: bytes 20-23 of its header, big-endian.
png_height() { od -An -t u1 -j 20 -N 4 "$1" | awk '{ print $1 * 16777216 + $2 * 65536 + $3 * 256 + $4 }'; }
while IFS=$'\t' read -r file kind _title; do
  [[ -z $file || $kind == code ]] && continue
  png="$shots/${file%.html}.png"
  if [[ ! -s $png ]]; then
    echo "FAIL no screenshot of $file"
    status=1
  elif [[ -z ${height[$file]:-} ]]; then
    echo "FAIL $file: the checks did not measure its height, so its screenshot may not show the whole page"
    status=1
  elif (( $(png_height "$png") < ${height[$file]} )); then
    echo "FAIL $file: the screenshot is $(png_height "$png") px tall, the page ${height[$file]} px"
    status=1
  else
    echo "screenshot: $png ($(png_height "$png") px, the whole page)"
  fi
done <"$book/pages.txt"

# The motion viewers (cmake/book/tests/browser_motion.py): each page with one, driven over the DevTools
# protocol: no console error, a canvas that is not blank, that moves while playing and holds
# still when paused, a scrubber that moves the body; a screenshot of each viewer.
if [[ -n $chapters ]]; then
  markers=$(cat "$chapters"/*/*.md | grep -c '^<!-- motion: ' || true)
  python3 "$here/browser_motion.py" --expect "$markers" "$book" "$work/motion" || status=1
elif grep -lq 'class="motion"' "$book"/*.html 2>/dev/null; then
  python3 "$here/browser_motion.py" "$book" "$work/motion" || status=1
fi
exit $status
