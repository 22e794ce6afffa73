#!/usr/bin/env bash
# Runs case files one after another into OUT/<stem>.out, resuming any that a killed session
# left with a checkpoint, skipping those already finished: `bash scripts/run-cases.sh OUT
# CASE.json...`. For long studies in the background (one per core, OMP_NUM_THREADS=1).
# RBCAL names the executable (default build/bin/rbcal); point it at a copy so that
# rebuilding the tree meanwhile does not change the solver half-way through a queue.
set -uo pipefail
out="$1"; shift
rbcal="${RBCAL:-$(cd "$(dirname "$0")/.." && pwd)/build/bin/rbcal}"
mkdir -p "$out"
for c in "$@"; do
  name="$(basename "$c" .json)"
  if [ -f "$out/$name.out/result.json" ]; then echo "$name: done before"; continue; fi
  echo "$name: start $(date -u +%FT%TZ)"
  "$rbcal" simulate "$c" -o "$out/$name.out" -q --resume || echo "$name: FAILED (status $?)"
  echo "$name: end $(date -u +%FT%TZ)"
done
