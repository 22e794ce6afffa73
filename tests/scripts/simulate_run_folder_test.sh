#!/usr/bin/env bash
# `rbcal simulate` and its output folder: a folder that holds a run is refused without
# --resume or --overwrite (and its checkpoint kept byte for byte); a second run into a folder
# in use is refused; SIGINT and SIGTERM stop a run with a checkpoint and exit 130 / 143, and
# --resume finishes it.
# Usage: simulate_run_folder_test.sh RBCAL CASE WORK_DIR
set -uo pipefail
rbcal=$1 case=$2 dir=$3
rm -rf "$dir" && mkdir -p "$dir"
fail() { echo "FAIL: $*"; exit 1; }
long="$dir/long.json"  # the tiny capsule run 2000 times longer, so a signal finds it running
sed -e 's/"strain_end": 0.2/"strain_end": 400.0/' -e 's/, "vtk_interval": 0.1//' \
    -e 's/"record_interval": 0.01/"record_interval": 0.01, "checkpoint_interval": 0.05/' "$case" >"$long"
grep -q '"strain_end": 400.0' "$long" || fail "could not lengthen $case"

"$rbcal" simulate -q "$long" -o "$dir/run" --max-steps 40 >"$dir/first.log" 2>&1 || fail "first part: $(cat "$dir/first.log")"
before=$(md5sum <"$dir/run/checkpoint.bin")
"$rbcal" simulate -q "$long" -o "$dir/run" >"$dir/again.log" 2>&1
status=$?
[ "$status" -eq 2 ] || fail "a folder holding a run was not refused (exit $status): $(cat "$dir/again.log")"
grep -q "holds a run.*--resume.*--overwrite" "$dir/again.log" || fail "refusal does not say why: $(cat "$dir/again.log")"
[ "$(md5sum <"$dir/run/checkpoint.bin")" = "$before" ] || fail "the refused run changed the checkpoint"
"$rbcal" simulate -q "$long" -o "$dir/run" --overwrite --max-steps 20 >"$dir/over.log" 2>&1 || fail "--overwrite: $(cat "$dir/over.log")"
grep -q "stopped at strain" "$dir/over.log" || fail "--overwrite did not run"

for sig in INT TERM; do
  out="$dir/sig$sig"
  "$rbcal" simulate -q "$long" -o "$out" >"$out.log" 2>&1 &
  pid=$!
  for _ in $(seq 200); do [ -s "$out/series.csv" ] && [ "$(wc -l <"$out/series.csv")" -gt 3 ] && break; sleep 0.05; done
  # While it runs, the folder is in use.
  "$rbcal" simulate -q "$long" -o "$out" --resume >"$out.second.log" 2>&1
  [ $? -eq 2 ] && grep -q "in use by another run" "$out.second.log" || fail "a second run into a folder in use: $(cat "$out.second.log")"
  kill -"$sig" "$pid"
  wait "$pid"
  status=$?
  want=$([ "$sig" = INT ] && echo 130 || echo 143)
  [ "$status" -eq "$want" ] || fail "SIG$sig: exit $status, expected $want: $(cat "$out.log")"
  grep -q "stopped at strain .* by signal" "$out.log" || fail "SIG$sig: no stop message: $(cat "$out.log")"
  [ -f "$out/checkpoint.bin" ] || fail "SIG$sig: no checkpoint"
done
sed -i 's/"strain_end": 400.0/"strain_end": 0.4/' "$long"
"$rbcal" simulate -q "$long" -o "$dir/sigINT" --resume >"$dir/resume.log" 2>&1 || fail "resume after SIGINT: $(cat "$dir/resume.log")"
grep -q "eta_re (stresslet)" "$dir/resume.log" || fail "resume did not finish: $(cat "$dir/resume.log")"
echo "run folder guarded, signals exit 130/143, resumed"
