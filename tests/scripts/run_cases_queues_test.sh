#!/usr/bin/env bash
# scripts/run-cases.sh: two queues over the same three cases in opposite orders, sharing one
# output folder, run every case exactly once between them (the per-case flock), and a
# third queue afterwards finds them all done. A stand-in for rbcal takes a second per
# case and writes result.json, so that both queues reach the middle case at the same time
# (without the lock both would run it).
# Usage: run_cases_queues_test.sh SOURCE_DIR WORK_DIR
set -euo pipefail
src=$1 dir=$2
command -v flock >/dev/null || { echo "SKIP: no flock (Debian package util-linux)"; exit 77; }
rm -rf "$dir" && mkdir -p "$dir/cases"
cat >"$dir/fake_rbcal" <<'FAKE'
#!/usr/bin/env bash
# fake rbcal: simulate CASE -o RUN ...
mkdir -p "$4"; sleep 1; echo '{}' >"$4/result.json"; echo "ran $(basename "$2")" >>"$(dirname "$4")/ran.txt"
FAKE
chmod +x "$dir/fake_rbcal"
for i in 1 2 3; do echo '{}' >"$dir/cases/c$i.json"; done
export RBCAL="$dir/fake_rbcal"
c=("$dir"/cases/c1.json "$dir"/cases/c2.json "$dir"/cases/c3.json)
bash "$src/scripts/run-cases.sh" "$dir/out" "${c[@]}" >"$dir/q1.log" 2>&1 &
bash "$src/scripts/run-cases.sh" "$dir/out" "${c[2]}" "${c[1]}" "${c[0]}" >"$dir/q2.log" 2>&1 &
wait
fail() { echo "FAIL: $*"; cat "$dir/q1.log" "$dir/q2.log" "$dir/out/ran.txt"; exit 1; }
[ "$(wc -l <"$dir/out/ran.txt")" -eq 3 ] || fail "$(wc -l <"$dir/out/ran.txt") runs for 3 cases"
[ "$(sort -u "$dir/out/ran.txt" | wc -l)" -eq 3 ] || fail "a case ran twice"
grep -q "start" "$dir/q1.log" || fail "queue 1 ran nothing"
grep -q "start" "$dir/q2.log" || fail "queue 2 ran nothing"
bash "$src/scripts/run-cases.sh" "$dir/out" "${c[@]}" >"$dir/q3.log" 2>&1
[ "$(grep -c "done before" "$dir/q3.log")" -eq 3 ] || fail "a third queue did not find all three done"
echo "PASS: 3 cases, each run once by two queues"
