#!/usr/bin/env bash
# The class report in a real browser: headless Chromium, offline (no network, a fresh profile),
# opens <grades>/class_report.html in a frame and checks that every image of the page loaded
# (complete, with a natural size), that it has at least the three kinds of plot (totals,
# exercises, tests) unless the page says there are none, and that the page is as it was written
# (a title). Then the same checks on a copy of the page with one plot's file removed, which must
# fail: the test of the test. Drives Chromium as cmake/book/tests/browser_test.sh does.
#
#   tests/grading/tests/report_browser.sh <grades folder> <scratch folder>
#
# Exit status 0 when all is well, 1 on a problem, 77 (CTest: skipped) when no Chromium is
# installed and CI is not set.
set -euo pipefail

grades=$(cd "$1" && pwd)
work=$2

source "$(dirname "${BASH_SOURCE[0]}")/../../../cmake/support/chromium.sh"
[[ -f $grades/class_report.html ]] || { echo "No $grades/class_report.html: run the class run first."; exit 1; }

rm -rf "$work"
mkdir -p "$work"
work=$(cd "$work" && pwd)

# A broken copy: the same page and plots, one plot's file gone.
mkdir -p "$work/broken"
cp -r "$grades/class_report.html" "$grades/report" "$work/broken/"
rm -f "$work/broken/report/totals.svg"

cat >"$work/check.js" <<'EOF'
"use strict";
const lines = [];
function check(name, url) {
  return new Promise((resolve) => {
    const frame = document.createElement("iframe");
    frame.style.width = "1200px";
    frame.style.height = "900px";
    const timer = setTimeout(() => { lines.push("FAIL " + name + ": did not load"); resolve(); }, 20000);
    frame.onload = () => {
      clearTimeout(timer);
      const doc = frame.contentDocument;
      if (!doc || !doc.title) lines.push("FAIL " + name + ": no document or no title");
      const images = doc ? [...doc.images] : [];
      let bad = 0;
      for (const img of images) {
        if (!img.complete || img.naturalWidth === 0) {
          lines.push("FAIL " + name + ": the image " + img.getAttribute("src") + " did not load");
          ++bad;
        }
      }
      const none = doc && doc.body.textContent.includes("No plots:");
      if (!none && images.length < 3) lines.push("FAIL " + name + ": " + images.length + " plots, and no note saying why");
      lines.push("PAGE " + name + ": " + images.length + " images, " + (images.length - bad) + " loaded" + (none ? " (no plots: the page says why)" : ""));
      resolve();
    };
    frame.src = url;
    document.body.appendChild(frame);
  });
}
(async () => {
  await check("class_report.html", PAGE);
  await check("broken-on-purpose", BROKEN);
  lines.push("DONE");
  document.getElementById("result").textContent = lines.join("\n");
})();
EOF
{
  echo '<!DOCTYPE html><html><head><meta charset="utf-8"><title>The class report in a browser</title></head><body>'
  echo '<pre id="result">the checks did not run</pre>'
  printf '<script>const PAGE = "file://%s/class_report.html"; const BROKEN = "file://%s/broken/class_report.html";</script>\n' "$grades" "$work"
  echo '<script src="check.js"></script></body></html>'
} >"$work/harness.html"

profile=$(mktemp -d "$work/profile.XXXXXX")
echo "Opening $grades/class_report.html with $("$browser" --version 2>/dev/null | head -1)"
timeout 120 "$browser" --headless --no-sandbox --disable-gpu --disable-quic --no-first-run \
  --disable-background-networking --disable-component-update --disable-sync --disable-dev-shm-usage \
  --user-data-dir="$profile" --allow-file-access-from-files --virtual-time-budget=30000 \
  --dump-dom "file://$work/harness.html" >"$work/harness.dom" 2>>"$work/chromium.log" || true
result=$(sed -n '/<pre id="result">/,/<\/pre>/p' "$work/harness.dom" |
         sed -e 's/.*<pre id="result">//' -e 's/<\/pre>.*//' -e 's/&lt;/</g' -e 's/&gt;/>/g' -e 's/&amp;/\&/g')
echo "$result"
grep -q '^DONE$' <<<"$result" || { echo "The checks did not finish (see $work/chromium.log)."; exit 1; }
page=$(grep -v 'broken-on-purpose' <<<"$result" || true)
broken=$(grep '^FAIL broken-on-purpose' <<<"$result" || true)
if grep -q '^FAIL' <<<"$page"; then
  echo "The class report has a problem in a browser."
  exit 1
fi
if [[ -z $broken ]]; then
  echo "The check passed a page with a plot removed on purpose: it cannot see a missing image."
  exit 1
fi
echo "PASSED: every plot of the class report loads; the page with a plot removed fails."
