#!/usr/bin/env bash
# The book in a real browser: headless Chromium opens every page of the rendered book and
# checks that every image loaded, the math is laid out as MathML and no link is broken
# (cmake/book/browser_check.js); then it takes a screenshot of each chapter and of the other
# pages of prose into <book>/screenshots/ (a build artefact: look at them).
#
#   cmake/book/browser_test.sh <book folder> <scratch folder>
#
# Exit status 0 when all is well, 1 on a problem, 77 (CTest: skipped) when no Chromium is
# installed and CI is not set. `cmake/workbook test` installs Chromium (Debian: chromium).
set -euo pipefail

book=$(cd "$1" && pwd)
work=$2
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)

browser=""
for candidate in chromium chromium-browser google-chrome; do
  if command -v "$candidate" >/dev/null 2>&1; then browser=$(command -v "$candidate"); break; fi
done
if [[ -z $browser ]]; then
  echo "No Chromium here: install it (sudo apt-get install chromium) or run cmake/workbook test, which does."
  [[ ${CI:-} == true ]] && exit 1
  exit 77
fi
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
cat >"$work/broken-on-purpose.html" <<'EOF'
<!DOCTYPE html><html><head><meta charset="utf-8"><title>Broken on purpose</title></head><body>
<p>A figure that is not there: <img src="missing-figure.svg" alt="missing"></p>
<p><a href="missing-page.html">A page that is not there</a>; <a href="#no-such-anchor">an anchor that is not there</a>.</p>
<p>Math that was left as TeX: $\frac{a}{b}$.</p>
</body></html>
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

# Screenshots of every page of prose (not the source listings), two browsers at a time.
shots=$book/screenshots
rm -rf "$shots"
mkdir -p "$shots"
pids=()
while IFS=$'\t' read -r file kind _title; do
  [[ -z $file || $kind == code ]] && continue
  chrome --screenshot="$shots/${file%.html}.png" --window-size=1200,2000 "file://$book/$file" >/dev/null &
  pids+=($!)
  if (( ${#pids[@]} >= 2 )); then wait "${pids[0]}" || true; pids=("${pids[@]:1}"); fi
done <"$book/pages.txt"
for pid in "${pids[@]}"; do wait "$pid" || true; done
while IFS=$'\t' read -r file kind _title; do
  [[ -z $file || $kind == code ]] && continue
  png="$shots/${file%.html}.png"
  if [[ -s $png ]]; then
    echo "screenshot: $png"
  else
    echo "FAIL no screenshot of $file"
    status=1
  fi
done <"$book/pages.txt"
exit $status
