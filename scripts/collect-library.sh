#!/usr/bin/env bash
# Gathers the finished runs of a case queue (scripts/run-cases.sh OUT ...) into a library
# folder: OUT/ID.out/result.json -> LIB/cases/ID.json and series.csv -> LIB/cases/ID.csv,
# the layout `rbcal library show`, `surrogate build` and `library extrapolate` read.
# Unfinished runs (no result.json) are skipped; existing files are replaced.
# Usage: bash scripts/collect-library.sh OUT LIB
set -euo pipefail
out="$1"; lib="$2"
mkdir -p "$lib/cases"
n=0
for result in "$out"/*.out/result.json; do
  [ -f "$result" ] || continue
  dir="$(dirname "$result")"; id="$(basename "$dir" .out)"
  cp "$result" "$lib/cases/$id.json"
  [ -f "$dir/series.csv" ] && cp "$dir/series.csv" "$lib/cases/$id.csv"
  n=$((n + 1))
done
echo "collected $n finished case(s) into $lib/cases"
