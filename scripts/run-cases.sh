#!/usr/bin/env bash
# Runs case files one after another into OUT/<stem>.out, resuming any that a killed run
# left with a checkpoint, skipping those already finished: `bash scripts/run-cases.sh OUT
# CASE.json...`. For long studies in the background (one per core, OMP_NUM_THREADS=1).
# RBCAL names the executable (default build/bin/rbcal); point it at a copy so that
# rebuilding the tree meanwhile does not change the solver half-way through a queue.
# A run that the node Mach guard stops at a coupling interval above 1 is continued at
# interval 1 from its last checkpoint (rbcal simulate --coupling-interval 1).
# Several queues may share OUT (say one per core over the same cases in opposite orders):
# each case runs under a lock (flock on OUT/<stem>.lock, released by the kernel when its
# holder ends, even if killed), and a queue skips a case that another one is running.
set -uo pipefail
out="$1"; shift
rbcal="${RBCAL:-$(cd "$(dirname "$0")/.." && pwd)/build/bin/rbcal}"
mkdir -p "$out"
# Continues a run at coupling interval 1 from its last checkpoint.
continue_at_interval_1() {
  "$rbcal" simulate "$1" -o "$2" -q --resume --coupling-interval 1 || echo "$3: FAILED (status $?)"
}
# Runs one case (the body of the loop; called with the lock held).
run_case() {
  local c="$1" name="$2" run="$3"
  echo "$name: start $(date -u +%FT%TZ)"
  # A run that went unstable at a coupling interval above 1 continues at 1 from its last
  # checkpoint (equivalent: docs/library.md); once switched, it stays at 1 on later resumes.
  if [ -f "$run/coupling_interval_changes.json" ]; then
    continue_at_interval_1 "$c" "$run" "$name"
  elif ! "$rbcal" simulate "$c" -o "$run" -q --resume; then
    if [ -f "$run/checkpoint_failed.bin" ] && [ -f "$run/checkpoint.bin" ] &&
       grep -Eq '"coupling_interval": *([2-9]|[1-9][0-9])' "$c"; then
      echo "$name: unstable at its coupling interval; continuing at 1 from the last checkpoint"
      continue_at_interval_1 "$c" "$run" "$name"
    else
      echo "$name: FAILED"
    fi
  fi
  echo "$name: end $(date -u +%FT%TZ)"
}
for c in "$@"; do
  name="$(basename "$c" .json)"
  run="$out/$name.out"
  if [ -f "$run/result.json" ]; then echo "$name: done before"; continue; fi
  (
    flock -n 9 || { echo "$name: running in another queue, skipped"; exit 0; }
    # Finished by another queue while this one waited for its turn?
    if [ -f "$run/result.json" ]; then echo "$name: done before"; exit 0; fi
    run_case "$c" "$name" "$run"
  ) 9>"$out/$name.lock"
done
