# Sourced by the browser tests (cmake/book/tests/browser_test.sh, tests/grading/tests/report_browser.sh):
# sets `browser` to Chromium's path, or, when there is none, says how to install it and exits
# 77 (CTest: skipped), or 1 under CI=true.
browser=""
for candidate in chromium chromium-browser google-chrome; do
  if command -v "$candidate" >/dev/null 2>&1; then browser=$(command -v "$candidate"); break; fi
done
if [[ -z $browser ]]; then
  echo "No Chromium here: install it (sudo apt-get install chromium) or run cmake/workbook test, which does."
  [[ ${CI:-} == true ]] && exit 1
  exit 77
fi
