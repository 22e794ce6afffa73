#!/usr/bin/env bash
# The v2 library from its background runs, in one go (issue 16; docs/library.md):
#   1. gather the finished runs into data/library/v2/n6 and n8 (scripts/collect-library.sh);
#   2. map them to the continuum into data/library/default, the shipped default library:
#      METHOD=effective-phi (the default since 2026-11-25): every run of both tiers moved
#      to the volume fraction its cells fill when thickened by OFFSET (0.75) lattice spacings
#      (at N_a 8; OFFSET_SLOPE, default 0, makes it OFFSET + OFFSET_SLOPE (1 / N_a - 1 / 8))
#      (rbcal library effective-phi; docs/library.md, "The effective volume fraction"); runs
#      beyond phi_eff 0.62 are left out. CASE_OFFSET_SD (default 0.15) adds the offset's
#      uncertainty to each run's sd as if independent, a smoothness prior on the surface (the
#      family carries the offset itself as one parameter; docs/library.md, "The runs' offset
#      sd");
#      METHOD=richardson (the default until then): Richardson extrapolation of the (6, 8)
#      pairs (rbcal library extrapolate, order 2.8 and P_LOW (--order-low) 1.5);
#   3. build its surrogate and check its trends (rbcal surrogate build / check);
#   4. (effective-phi) the surrogate family: the same runs mapped at FAMILY_OFFSETS (default
#      0.45 0.6 0.75 0.9 1.05, equally spaced, OFFSET among them) joined into
#      data/library/default/surrogate_family.json with the prior OFFSET +- OFFSET_SD
#      (rbcal surrogate family), the model the calibration uses by default: the offset is
#      then a nuisance parameter of every fit (docs/calibration.md). With BOX=auto (the
#      default) the family also carries the box correction
#      beta, its prior from the 8a/16a twin runs committed in data/cases/library_v2/results
#      (scripts/box_twins.py), integrated out in every fit (docs/calibration.md); BOX=none
#      leaves it out (docs/library.md, "The box twins"). SHARED_HYPERPARAMETERS=1 builds the
#      members with the central surrogate's hyper-parameters (rbcal surrogate build
#      --hyperparameters-of), and SAME_RUNS=1 with the central library's runs only (its phi_eff
#      cut), so that they differ only by the mapping.
# Usage: bash scripts/build-library-v2.sh [RUNS]   (RUNS: a folder of finished runs, RUNS/n6 and
#   RUNS/n8, collected into data/library/v2 first; without it the committed runs are used)
# Under either method:
#   N8_LEAVE_OUT="ID ..." leaves those N_a 8 cases out of the build, and
#   N8_USE_FILE=FILE uses only the N_a 8 cases FILE lists (one ID per line, # comments);
#   either way all cases stay in data/library/v2/n8. The default of 2026-11-24 is
#   reproduced by METHOD=richardson N8_USE_FILE=data/library/v2/default_n8_cases.txt (15 of
#   the maximin subset; that file says why the others are left out;
#   studies/library-v2-development/README.md, "Round 2 and the layers").
# It rewrites data/library/default/cases and surrogate.json (the default since 2026-11-24);
# review `git diff --stat data/library/default` and the trend check before committing.
set -euo pipefail
cd "$(dirname "$0")/.."
runs="${1:-}"
rbcal=./build/bin/rbcal
lib=data/library/v2
for tier in n6 n8; do
  [ -n "$runs" ] && [ -d "$runs/$tier" ] && bash scripts/collect-library.sh "$runs/$tier" "$lib/$tier"
done
count() { if [ -d "$1" ]; then find "$1" -name "*.json" | wc -l; else echo 0; fi; }
n6=$(count "$lib/n6/cases")
fine="$lib/n8"
if [ -n "${N8_LEAVE_OUT:-}" ] || [ -n "${N8_USE_FILE:-}" ]; then
  fine="$(mktemp -d)"
  trap 'rm -rf "$fine"' EXIT
  mkdir -p "$fine/cases"
  cp "$lib/n8/plan.json" "$fine/" 2>/dev/null || true
  if [ -n "${N8_USE_FILE:-}" ]; then
    [ -f "$N8_USE_FILE" ] || { echo "N8_USE_FILE: no such file: $N8_USE_FILE" >&2; exit 1; }
    for id in $(grep -v '^#' "$N8_USE_FILE"); do
      [ -f "$lib/n8/cases/$id.json" ] || { echo "$N8_USE_FILE: no N_a 8 case $id in $lib/n8/cases" >&2; exit 1; }
      cp "$lib/n8/cases/$id.json" "$lib/n8/cases/$id.csv" "$fine/cases/"
    done
  else
    cp -r "$lib/n8/cases/." "$fine/cases/"
  fi
  for id in ${N8_LEAVE_OUT:-}; do rm -f "$fine/cases/$id.json" "$fine/cases/$id.csv"; done
fi
n8=$(count "$fine/cases")
echo "v2: $n6 case(s) at N_a 6, $n8 at N_a 8"
if [ "${METHOD:-effective-phi}" = richardson ] && [ "$n8" -lt 3 ]; then
  echo "fewer than 3 cases at N_a 8: no extrapolation yet"
  exit 0
fi
# The seed-scatter floor (docs/library.md): 5.4 % from the phi 0.41 twins over [15, 40],
# ramped from phi 0.05, so that phi 0.21 gets 2.4 % (its three N_a 6 seeds scatter 3.0 %).
out=data/library/default
rm -rf "$out/cases"
mkdir -p "$out"
# Everything below is also written to $out/build_report.txt (extrapolation table, leave-one-out
# report, trend check), the record that docs/library.md quotes.
exec > >(tee "$out/build_report.txt") 2>&1
echo "rbcal $(git rev-parse --short HEAD)$(git diff --quiet || echo -dirty), $(date -u +%F)"
[ -n "${N8_LEAVE_OUT:-}" ] && echo "N_a 8 cases left out: $N8_LEAVE_OUT"
[ -n "${N8_USE_FILE:-}" ] && echo "N_a 8 cases used: those listed in $N8_USE_FILE"
if [ "${METHOD:-effective-phi}" = richardson ]; then
  "$rbcal" library extrapolate "$lib/n6" "$fine" -o "$out" --order "${ORDER:-2.8}" --order-low "${P_LOW:-1.5}" \
    --scatter-floor "${SCATTER_FLOOR:-0.054}" --scatter-phi "${SCATTER_PHI:-0.05,0.41}"
else
  "$rbcal" library effective-phi "$lib/n6" "$fine" -o "$out" --offset "${OFFSET:-0.75}" --offset-slope "${OFFSET_SLOPE:-0}" --offset-sd "${CASE_OFFSET_SD:-0.15}" \
    --phi-max "${PHI_MAX:-0.62}" --scatter-floor "${SCATTER_FLOOR:-0.054}" --scatter-phi "${SCATTER_PHI:-0.05,0.41}"
fi
"$rbcal" surrogate build "$out"
"$rbcal" surrogate check "$out/surrogate.json" || echo "trend check FAILED (see above)"
if [ "${METHOD:-effective-phi}" != richardson ]; then
  members=()
  work="$out/family_members"  # a fixed path, so the members' source_library is reproducible; removed below
  rm -rf "$work"
  for c in ${FAMILY_OFFSETS:-0.45 0.6 0.75 0.9 1.05}; do
    if [ "$c" = "${OFFSET:-0.75}" ]; then
      members+=(--member "$c=$out/surrogate.json")
      continue
    fi
    echo "family member at offset $c:"
    member_phi_max="${PHI_MAX:-0.62}"
    [ "${SAME_RUNS:-0}" = 1 ] && member_phi_max=0.75  # the cut is the central library's (below)
    "$rbcal" library effective-phi "$lib/n6" "$fine" -o "$work/c$c" --offset "$c" --offset-slope "${OFFSET_SLOPE:-0}" --offset-sd "${CASE_OFFSET_SD:-0.15}" \
      --phi-max "$member_phi_max" --scatter-floor "${SCATTER_FLOOR:-0.054}" --scatter-phi "${SCATTER_PHI:-0.05,0.41}" > /dev/null
    if [ "${SAME_RUNS:-0}" = 1 ]; then
      # The member keeps exactly the central library's runs: members then differ by the mapping
      # only, not by which runs pass the phi_eff cut (which moved the sparse dense corner).
      for f in "$work/c$c/cases"/*.json; do
        [ -f "$out/cases/$(basename "$f")" ] || rm -f "$f" "${f%.json}.csv"
      done
    fi
    shared=()
    [ "${SHARED_HYPERPARAMETERS:-0}" = 1 ] && shared=(--hyperparameters-of "$out/surrogate.json")
    "$rbcal" surrogate build "$work/c$c" "${shared[@]}" | grep -E "training cases|RMS relative error"
    members+=(--member "$c=$work/c$c/surrogate.json")
  done
  box=()
  if [ "${BOX:-auto}" = auto ]; then
    twins="$(python3 scripts/box_twins.py)"
    echo "$twins"
    prior="$(echo "$twins" | sed -n 's/^prior for the bulk: mean \([-0-9.]*\), sd \([0-9.]*\)$/\1 \2/p')"
    count="$(echo "$twins" | sed -n 's/^\([0-9]*\) twins:.*/\1/p')"
    read -r box_mean box_sd <<< "$prior"
    box=(--box-mean "$box_mean" --box-sd "$box_sd"
         --box-source "$count 8a/16a twin runs at phi_eff 0.41-0.55 (scripts/box_twins.py; docs/library.md, The box twins)")
  fi
  "$rbcal" surrogate family "${members[@]}" --prior-mean "${OFFSET:-0.75}" --prior-sd "${OFFSET_SD:-0.15}" \
    "${box[@]}" -o "$out/surrogate_family.json"
  rm -rf "$work"
fi
