#!/usr/bin/env bash
# `mpirun -np 2 rbcal library generate` on a three-case plan: every case finished exactly
# once by the two ranks together, nothing left in work/, the progress lines whole, and
# the series equal to those of a single-worker sweep. Skipped (exit 77) where OpenMPI's
# mpirun is missing or cannot start two processes on this machine.
# Usage: mpirun_generate_test.sh RBCAL_EXE PLAN.json WORK_DIR
set -euo pipefail
rbcal=$1 plan=$2 dir=$3

command -v mpirun >/dev/null || { echo "SKIP: no mpirun (Debian package openmpi-bin)"; exit 77; }
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1  # CI runs as root
launch=(mpirun --oversubscribe -np 2)
timeout 60 "${launch[@]}" true >/dev/null 2>&1 || { echo "SKIP: mpirun cannot start two processes here"; exit 77; }

rm -rf "$dir" && mkdir -p "$dir"
"${launch[@]}" "$rbcal" library generate "$plan" -l "$dir/ranks" --threads 1 2>"$dir/progress.txt"
"$rbcal" library generate "$plan" -l "$dir/single" --threads 1 -q

fail() { echo "FAIL: $*"; cat "$dir/progress.txt"; exit 1; }
cases=$(find "$dir/single/cases" -name '*.json' | wc -l)
[ "$cases" -eq 3 ] || fail "single-worker sweep finished $cases cases, expected 3"
for f in "$dir"/single/cases/*.csv; do
  cmp -s "$f" "$dir/ranks/cases/$(basename "$f")" || fail "$(basename "$f") differs from the single-worker sweep"
done
[ "$(find "$dir/ranks/cases" -name '*.json' | wc -l)" -eq 3 ] || fail "the ranks did not finish exactly 3 cases"
[ -z "$(ls -A "$dir/ranks/work")" ] || fail "work/ is not empty"
# Each case is started by exactly one rank, and both ranks took part.
[ "$(grep -c ': starting$' "$dir/progress.txt")" -eq 3 ] || fail "cases started other than once each"
grep -q '^\[rank 0\]' "$dir/progress.txt" || fail "no line from rank 0"
grep -q '^\[rank 1\]' "$dir/progress.txt" || fail "no line from rank 1"
# Whole lines: a worker's tag only ever opens a line.
if grep -E '.\[rank [01]\]' "$dir/progress.txt"; then fail "progress lines of the ranks interleave"; fi
echo "PASS: 3 cases by 2 ranks, series identical to a single worker"
