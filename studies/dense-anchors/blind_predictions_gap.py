#!/usr/bin/env python3
"""Blind predictions of the anchors of one resolution for their 16a gap, by any family, written
before the runs: the mixture over the family's prior on c (at N_a 8), each run at
phi_eff = g(c(N_a) / N_a) phi_actual with c(N_a) = c + slope (1 / N_a - 1 / 8) (the slope of the
family's recipe), each member's bulk prediction moved to the 16a gap (shipped_family.in_gap,
with the family's own box correction). For N_a 16 the cells have 5120 triangles, whose volume
is 0.66 % above the 1280-triangle mesh's (phi_actual 0.2918 against 0.2899 at 107 cells); g is
taken from the 1280-triangle mesh (its S / V differs by well under 1 %).
    RBCAL_FAMILY=FAMILY python3 studies/dense-anchors/blind_predictions_gap.py N_A [RBCAL] > FILE.csv"""
import glob
import json
import math
import os
import sys

N_A = int(sys.argv.pop(1))  # before shipped_family reads its optional RBCAL argument
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from shipped_family import FAMILY, ROOT, V, g, in_gap, member

family = json.load(open(FAMILY))
prior_mean, prior_sd = family["prior"]["mean"], family["prior"]["sd"]
lo = min(m["offset"] for m in family["members"])
hi = max(m["offset"] for m in family["members"])
slope = family.get("provenance", {}).get("recipe", {}).get("mapping", {}).get("offset_slope", 0.0)
offsets = [lo + (hi - lo) * k / 8 for k in range(9)]
weights = [math.exp(-0.5 * ((c - prior_mean) / prior_sd) ** 2) for c in offsets]
weights = [w / sum(weights) for w in weights]
volume_scale = 0.2918 / 0.2899 if N_A == 16 else 1.0


def offset_at(c):
    return c + slope * (1.0 / N_A - 1.0 / 8.0)


print(f"# family {os.path.relpath(FAMILY, ROOT) if FAMILY.startswith(ROOT) else os.path.basename(FAMILY)}: "
      f"prior {prior_mean} +- {prior_sd} on {lo}-{hi}, slope {slope}; N_a {N_A}")
print("case,phi_actual,c_at_prior_mean,phi_eff_at_prior_mean,eta_re_16a,sd_16a")
for path in sorted(glob.glob(os.path.join(ROOT, "data", "library", "anchors", "cases", f"n{N_A}_*.json"))):
    case = json.load(open(path))
    p = case["params"]
    lx, ly, lz = case["numerics"]["box"]
    cells = round(p["phi"] * lx * ly * lz / V)
    phi_actual = cells * V / (lx * ly * lz) * volume_scale
    preds = [in_gap(*member(g(offset_at(c), N_A) * phi_actual, p["Ca"], p["lambda"], c)) for c in offsets]
    mean = sum(w * m for w, (m, s) in zip(weights, preds))
    var = sum(w * (s * s + m * m) for w, (m, s) in zip(weights, preds)) - mean * mean
    c0 = offset_at(prior_mean)
    print(f"{os.path.basename(path)[:-5]},{phi_actual:.4f},{c0:.3f},{g(c0, N_A) * phi_actual:.4f},{mean:.4f},"
          f"{math.sqrt(var):.4f}")
