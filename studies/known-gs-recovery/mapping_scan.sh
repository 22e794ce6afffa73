#!/usr/bin/env bash
# Which mapping law c(N_a) = c8 + K (1 / N_a - 1 / 8) recovers a known G_s from the dense anchors
# at both N_a 8 and N_a 12? For each (c8, K) a model is built from the measured-thickening
# recipe with that mapping (members c8 - 0.2 .. c8 + 0.2, prior c8 +- 0.04, the central
# surrogate's runs and hyper-parameters), and `rbcal recover` runs on each resolution's anchors,
# labelled at the model's own c(N_a). Usage, from the repository root:
#   bash studies/known-gs-recovery/mapping_scan.sh OUT "C8,K ..." > table.md
# REPLICATES (default 3) sets the noise draws per true G_s: 4 x REPLICATES cases per tier.
set -eu
out=$1; shift
rbcal=${RBCAL:-build/bin/rbcal}
replicates=${REPLICATES:-3}
mkdir -p "$out"
echo "| c8 | K | c(6) | c(12) | N_a 8: direct / MCMC estimate / truth, coverage | N_a 12: direct / MCMC, coverage |"
echo "|---|---|---|---|---|---|"
for pair in $@; do
  c8=${pair%,*} k=${pair#*,}
  dir="$out/c${c8}_k${k}"
  python3 - "$c8" "$k" "$dir" <<'PY'
import json, os, sys
c8, k, d = float(sys.argv[1]), float(sys.argv[2]), sys.argv[3]
r = json.load(open("studies/ib-thickening/measured_level_recipe.json"))
r["about"] = f"mapping scan: c8 {c8}, slope {k}"
r["runs"] = [os.path.abspath(os.path.join("studies/ib-thickening", p)) for p in r["runs"]]
for t in r["box_correction"]["twins"]:
    for key in t:
        t[key] = os.path.abspath(os.path.join("studies/ib-thickening", t[key]))
r["mapping"]["offset"], r["mapping"]["offset_slope"] = c8, k
r["family"]["offsets"] = [round(c8 + 0.1 * i, 4) for i in range(-2, 3)]
r["family"]["prior"]["mean"] = c8
os.makedirs(d, exist_ok=True)
json.dump(r, open(os.path.join(d, "recipe.json"), "w"), indent=1)
PY
  "$rbcal" model build "$dir/recipe.json" -o "$dir/model" > "$dir/build.log" 2>&1
  cells=()
  for n in 8 12; do
    "$rbcal" recover data/library/anchors/results/n${n}_*.result.json --surrogate "$dir/model/surrogate_family.json" \
      --replicates "$replicates" -o "$dir/recover_n$n.json" > "$dir/recover_n$n.txt" 2>&1
    cells+=("$(python3 - "$dir/recover_n$n.json" <<'PY'
import json, sys
j = json.load(open(sys.argv[1]))
c = j["coverage"]
d, m = c['direct'], c['mcmc']
print(f"{d['bias_factor']:.2f} +- {d['bias_factor_se']:.2f} / {m['bias_factor']:.2f} +- {m['bias_factor_se']:.2f}, "
      f"{d['covered']}+{m['covered']} of {d['asked'] + m['asked']}")
PY
)")
  done
  c6=$(python3 -c "print(round($c8 + $k * (1/6 - 1/8), 3))"); c12=$(python3 -c "print(round($c8 + $k * (1/12 - 1/8), 3))")
  echo "| $c8 | $k | $c6 | $c12 | ${cells[0]} | ${cells[1]} |"
done
