# Sourced by the front doors' walks (student.sh, contributor.sh, keys.sh): how a walk runs a
# command exactly as a page writes it, and how it fails. The caller sets `work` (its scratch folder).
fail() { echo "FAILED: $*" >&2; exit 1; }

# run <expected status: 0, 1 (non-zero), 2 or any> <line> [what the output must hold]...: the line
# through bash, as a user types it; its output in $last.
n=0
run() {
  local want=$1 line=$2 status start=$SECONDS
  shift 2
  n=$((n + 1))
  local log=$work/step$n.txt
  echo "\$ $line"
  bash -c "$line" >"$log" 2>&1
  status=$?
  echo "  (exit $status, $((SECONDS - start)) s)"
  sed 's/^/  | /' "$log" | tail -n 20
  [[ $want == any || ($want == 0 && $status -eq 0) || ($want == 1 && $status -ne 0) || ($want == 2 && $status -eq 2) ]] ||
    fail "'$line' exited with status $status"
  for text in "$@"; do grep -qF -- "$text" "$log" || fail "'$line' did not say: $text"; done
  last=$log
}
