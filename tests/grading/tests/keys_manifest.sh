#!/usr/bin/env bash
# The exercises a key can name (the todo("<name>") of each stub as committed, which workbook_topics
# and `workbook_grade check` read: engine/catalog.hpp) are exactly the exercises the graders grade
# (grading/manifest.txt, listed from the reference graders): an exercise of one and not the other
# would be a key that grades nothing, or an exercise no key names.
#
#   keys_manifest.sh <workbook_topics> <build>/grading <scratch folder> [--plant]
#
# --plant: a copy of the catalogue whose rotation stub names one exercise more; the check must
# then fail, naming it (the self-test).
set -euo pipefail
tool=$1 setup=$2 work=$3 plant=${4:-}
catalog=$setup/catalog.json
rm -rf "$work" && mkdir -p "$work"
if [[ $plant == --plant ]]; then
  python3 - "$catalog" "$work" <<'PY'
import json, sys
c = json.load(open(sys.argv[1]))
for t in c["topics"]:
    if t["name"] == "rotation":
        stub = open(t["stub"]).read() + '\n// planted\nvoid planted() { todo("planted_exercise"); }\n'
        t["stub"] = sys.argv[2] + "/rotation.cpp"
        open(t["stub"], "w").write(stub)
json.dump(c, open(sys.argv[2] + "/catalog.json", "w"))
PY
  catalog=$work/catalog.json
fi
"$tool" exercises --catalog "$catalog" | sort >"$work/keys.txt"
awk -F'\t' '$1 == "exercise" { print $2 "\t" $3 }' "$setup/manifest.txt" | sort >"$work/graded.txt"
[[ -s $work/graded.txt ]] || { echo "FAILED: $setup/manifest.txt lists no exercise"; exit 1; }
if ! diff "$work/keys.txt" "$work/graded.txt" >"$work/diff.txt"; then
  echo "FAILED: the stubs' exercises (<) and the graders' (>) differ:"
  cat "$work/diff.txt"
  exit 1
fi
echo "the $(wc -l <"$work/keys.txt") exercises the stubs name are those the graders grade"
