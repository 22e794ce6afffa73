#!/usr/bin/env python3
"""Blind predictions of the dense anchor runs by the shipped model, written before the runs
finish: python3 studies/dense-anchors/blind_predictions.py [RBCAL] > blind_predictions.csv

A run at N_a 12 seeded at phi_actual stands for the continuum at phi_eff = g_c(12) phi_actual,
where g_c is the thickened-volume factor at offset c (docs/library.md). Both the mapping and the
family member depend on c, so the prediction is the mixture over c's prior (normal 0.75 +- 0.15
truncated to the family's 0.45-1.05), each member with its own sd. The anchors run in a 16a gap,
which the shipped family's box correction beta (ln eta_bulk = (1 + beta) ln eta_re, prior
0.102 +- 0.070) says is more viscous than the library's 8a gap: applied on top, its sd added.
"""
import glob, json, math, os, sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from shipped_family import BETA_MEAN as beta_mean, BETA_SD as beta_sd, ROOT as root, V, g
from shipped_family import member

offsets = [0.45 + 0.075 * k for k in range(9)]
weights = [math.exp(-0.5 * ((c - 0.75) / 0.15) ** 2) for c in offsets]
weights = [w / sum(weights) for w in weights]

print("case,N_a,phi_actual,Ca,lambda,phi_eff_c0.75,eta_re_c0.75,sd_c0.75,eta_re_8a_mixture,sd_8a_mixture,"
      "eta_re_bulk,sd_bulk")
for path in sorted(glob.glob(os.path.join(root, "data", "library", "anchors", "cases", "*.json"))):
    case = json.load(open(path))
    p, n_a = case["params"], case["numerics"]["N_a"]
    lx, ly, lz = case["numerics"]["box"]
    cells = round(p["phi"] * lx * ly * lz / V)  # the seeding's count (solver/simulation/cell_seeding.hpp)
    phi_actual = cells * V / (lx * ly * lz)
    preds = [member(g(c, n_a) * phi_actual, p["Ca"], p["lambda"], c) for c in offsets]
    mean = sum(w * m for w, (m, s) in zip(weights, preds))
    var = sum(w * (s * s + m * m) for w, (m, s) in zip(weights, preds)) - mean * mean
    m75, s75 = preds[4]
    # ln eta_bulk = (1 + beta) ln eta: mean and sd to first order in the two errors.
    ln_bulk = (1 + beta_mean) * math.log(mean)
    sd_ln_bulk = math.hypot((1 + beta_mean) * math.sqrt(var) / mean, beta_sd * math.log(mean))
    print(f"{os.path.basename(path)[:-5]},{n_a},{phi_actual:.4f},{p['Ca']:g},{p['lambda']:g},"
          f"{g(0.75, n_a) * phi_actual:.4f},{m75:.4f},{s75:.4f},{mean:.4f},{math.sqrt(var):.4f},"
          f"{math.exp(ln_bulk):.4f},{math.exp(ln_bulk) * sd_ln_bulk:.4f}")
