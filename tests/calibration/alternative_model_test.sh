#!/usr/bin/env bash
# --alternative-model: a model file ranked by ln Z with the --compare-models variants. The
# same file as the job's model, with the same seed, must give the same ln Z and G_s as the
# job's own variant with lambda as set (here held: the model covers lambda 5 only).
# Usage: alternative_model_test.sh RBCAL_EXE DATA.csv SURROGATE.json OUT
set -euo pipefail
rbcal=$1 data=$2 model=$3 out=$4
fail() { echo "FAIL: $*"; echo "$log"; exit 1; }
log=$("$rbcal" calibrate "$data" --surrogate "$model" --sample intact --method mcmc --mcmc-max-steps 300 --chains 2 \
  --walkers 8 --threads 1 --min-shear-rate 0 --no-plots --alternative-model "$model" -o "$out" 2>&1)
own=$(echo "$log" | grep -E '^ +lambda fixed at 5 +ln Z' | sed -E 's/.*ln Z ([-0-9.]+ \+- [0-9.]+ +G_s mcmc [0-9.]+).*/\1/')
alt=$(echo "$log" | grep -E '^ +model .*, lambda fixed ln Z' | sed -E 's/.*ln Z ([-0-9.]+ \+- [0-9.]+ +G_s mcmc [0-9.]+).*/\1/')
[ -n "$own" ] || fail "no line for the job's model"
[ -n "$alt" ] || fail "no line for the alternative model"
[ "$own" = "$alt" ] || fail "the same model ranked differently: '$own' against '$alt'"
grep -q '"alternative_models"' "$out/summary.json" || fail "summary.json does not record the option"
echo "PASS: the alternative model's line equals the job's own ($own)"
