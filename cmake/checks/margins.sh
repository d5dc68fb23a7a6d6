#!/usr/bin/env bash
# The margins of the graders' tolerances on the reference solutions: every CHECK_NEAR,
# CHECK_MAT_NEAR and CHECK_SMALL logs tolerance / error (tests/checks.hpp) when WORKBOOK_MARGINS
# names a file. Prints, per check site, the smallest margin over its runs, tightest first.
#
#   cmake/checks/margins.sh [build/solutions] [how many lines, default 30]
set -euo pipefail
build=${1:-build/solutions}
lines=${2:-30}
log=$(mktemp)
trap 'rm -f "$log"' EXIT
for grader in "$build"/graders/grade_*; do
  case $grader in *_stubs) continue ;; esac
  WORKBOOK_MARGINS=$log "$grader" --no-version >/dev/null 2>&1 || echo "margins.sh: $grader failed" >&2
done
# site, error, tolerance, margin (inf where the error is 0 and the tolerance is not).
awk -F'\t' '{
  site = $1 ":" $2; sub(/.*\/tests\//, "tests/", site)
  m = ($3 == 0) ? ($4 == 0 ? "exact" : 1e300) : $4 / $3
  if (m == "exact") { exact[site] = 1; next }
  if (!(site in best) || m < best[site]) { best[site] = m; err[site] = $3; tol[site] = $4 }
}
END {
  for (s in best) printf "%.3g\t%s\terror %.3g\ttolerance %.3g\n", best[s], s, err[s], tol[s]
  for (s in exact) if (!(s in best)) printf "exact\t%s\terror 0\ttolerance 0\n", s
}' "$log" | sort -g | head -n "$lines"
