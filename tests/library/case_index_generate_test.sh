#!/usr/bin/env bash
# Scheduler-array style: one `rbcal library generate --case-index I` per case of a
# three-case plan (as a Slurm array's tasks would run them) finishes each case once; a task
# run again for a finished case does nothing; an index past the plan is refused.
# Usage: case_index_generate_test.sh RBCAL_EXE PLAN.json WORK_DIR
set -euo pipefail
rbcal=$1 plan=$2 dir=$3
rm -rf "$dir" && mkdir -p "$dir"
fail() { echo "FAIL: $*"; exit 1; }
for i in 0 1 2; do "$rbcal" library generate "$plan" -l "$dir/lib" --case-index "$i" --threads 1 -q > "$dir/task$i.txt"; done
[ "$(find "$dir/lib/cases" -name '*.json' | wc -l)" -eq 3 ] || fail "three tasks did not finish the three cases"
for i in 0 1 2; do grep -q "1 cases finished now" "$dir/task$i.txt" || fail "task $i did not finish its case"; done
"$rbcal" library generate "$plan" -l "$dir/lib" --case-index 1 --threads 1 -q > "$dir/again.txt"
grep -q "0 cases finished now, 1 before" "$dir/again.txt" || fail "a rerun task ran its finished case again: $(cat "$dir/again.txt")"
if "$rbcal" library generate "$plan" -l "$dir/lib" --case-index 3 -q > "$dir/past.txt" 2>&1; then
  fail "--case-index 3 of a three-case plan was accepted"
fi
echo "PASS: three array tasks, three cases, each once"
