#!/usr/bin/env bash
# The browser test must be able to fail. Builds a two-page book, one page fine and one broken
# on purpose in the ways a real page could go wrong (a code block, a table and an equation wider
# than the text column, code that scrolls sideways), runs cmake/book/tests/browser_test.sh on it, and
# requires that it fails, naming the page and each element, and that the screenshots still
# show each page whole (the tall page is taller than any window).
#
#   cmake/book/tests/browser_selftest.sh <scratch folder>
#
# Exit status 0 when the browser test failed as it should, 1 when it missed something, 77
# (CTest: skipped) when no Chromium is installed and CI is not set.
set -uo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
work=$1
rm -rf "$work"
mkdir -p "$work/book"
work=$(cd "$work" && pwd)
book=$work/book
cp "$here/../web/book.css" "$book/book.css"

page() {  # page <file> <title> <body>
  printf '<!DOCTYPE html><html><head><meta charset="utf-8"><title>%s</title><link rel="stylesheet" href="book.css"></head>\n<body class="page"><main>\n%s\n</main></body></html>\n' "$2" "$3" >"$book/$1"
}
tall=""
for i in $(seq 1 120); do tall+="<p>Paragraph $i of a page taller than any window: the screenshot must hold all of it.</p>"; done
page fine.html "A page that is fine" "<h1>Fine</h1>$tall<pre><code>a long line of code that wraps inside its own box: $(printf 'word %.0s' $(seq 1 60))</code></pre><p>The end of the tall page.</p>"
page broken.html "A page broken on purpose" '<h1>Broken</h1>
<p>A paragraph that fits.</p>
<pre style="white-space: pre; overflow-x: visible">a code line that does not wrap and sticks out of the column: xxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxx</pre>
<pre style="white-space: pre; overflow-x: auto">a code line that scrolls sideways: yyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyyy</pre>
<table><tr><td>a table whose cell holds an equation, which cannot break:</td><td><math><mi>x</mi><mo>=</mo><mn>12345678901234567890123456789012345678901234567890123456789012345678901234567890</mn></math></td></tr></table>
<math display="block"><mrow><mi>E</mi><mo>=</mo><mn>1234567890123456789012345678901234567890123456789012345678901234567890123456789012345</mn></mrow></math>'
printf 'fine.html\tpage\tFine\nbroken.html\tpage\tBroken\n' >"$book/pages.txt"

out=$(bash "$here/browser_test.sh" "$book" "$work/browser" 2>&1)
status=$?
echo "$out"
echo "--- browser_test.sh exited with $status"
[[ $status -eq 77 ]] && exit 77
missed=()
[[ $status -eq 1 ]] || missed+=("exit status 1 (got $status)")
for pattern in \
  "FAIL broken.html: its content sticks out of the content column .*<pre> 'a code line that does not wrap" \
  "FAIL broken.html: scrolls sideways .*<pre> 'a code line that scrolls sideways" \
  "FAIL broken.html: (wider than|its content sticks out of) the content column .*<table>" \
  "FAIL broken.html: (wider than the content column|scrolls sideways) .*<math" \
  "screenshot: .*/fine.png \\([0-9]+ px, the whole page\\)" \
  "screenshot: .*/broken.png \\([0-9]+ px, the whole page\\)"; do
  grep -Eq "$pattern" <<<"$out" || missed+=("/$pattern/")
done
if grep -q "^FAIL fine.html" <<<"$out"; then missed+=("no complaint about fine.html"); fi
tall_px=$(grep -o '^HEIGHT fine.html [0-9]*' <<<"$out" | awk '{ print $3 }')
if [[ -z $tall_px || $tall_px -le 2000 ]]; then missed+=("fine.html taller than 2000 px (measured: ${tall_px:-nothing})"); fi
if (( ${#missed[@]} )); then
  printf 'The browser test missed damage done on purpose; expected:\n'
  printf '  %s\n' "${missed[@]}"
  exit 1
fi
echo "The browser test fails on the broken page, names each element, and shoots whole pages."
