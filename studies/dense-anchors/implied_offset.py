#!/usr/bin/python3
"""The immersed-boundary offset c at which the shipped family reproduces each finished anchor.

A run at N_a 12 seeded at phi_actual stands for the continuum at g_c(12) phi_actual; the
family's member at offset c predicts eta_re there for the bulk (its box correction is part of
its predictions), and moved to the anchors' 16a gap (shipped_family.in_gap). The c that makes the prediction equal the run is found by scanning the
family's range 0.45-1.05 and interpolating linearly. Usage, from the repository root:
  python3 studies/dense-anchors/implied_offset.py [RBCAL]
"""
import json
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from shipped_family import ROOT, g, in_gap
from shipped_family import member_eta as member


def crossing(offsets, values, target):
    for (c0, v0), (c1, v1) in zip(zip(offsets, values), zip(offsets[1:], values[1:])):
        if (v0 - target) * (v1 - target) <= 0.0 and v1 != v0:
            return c0 + (target - v0) * (c1 - c0) / (v1 - v0)
    return float("nan")


offsets = [0.45 + 0.05 * k for k in range(13)]
print("| anchor | eta_re run | member at 0.45 / 0.75 / 1.05 (bulk) | c (16a gap) | c (bulk) |")
print("|---|---|---|---|---|")
results = os.path.join(ROOT, "data", "library", "anchors", "results")
for name in sorted(os.listdir(results)):
    if not name.endswith(".result.json"):
        continue
    j = json.load(open(os.path.join(results, name)))
    p, r = j["params"], j["result"]
    n_a = j["numerics"]["N_a"]
    phi_actual = r["phi_actual"]
    values = [member(g(c, n_a) * phi_actual, p["Ca"], p["lambda"], c) for c in offsets]
    gap = [in_gap(v)[0] for v in values]
    def shown(curve):  # the crossing, or beyond which end of the family's range
        c = crossing(offsets, curve, r["eta_re"])
        if not math.isnan(c):
            return f"{c:.3f}"
        return "> 1.05" if r["eta_re"] < min(curve) else "< 0.45"
    print(f"| {name[:-12]} | {r['eta_re']:.3f} +- {r['eta_re_sem']:.3f} | {values[0]:.3f} / {values[6]:.3f} / "
          f"{values[-1]:.3f} | {shown(gap)} | {shown(values)} |")
