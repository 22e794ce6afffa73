#!/usr/bin/env python3
"""The box correction from twin runs: the same N_a 8 case in the library's 8a box and in a 16a
box (docs/library.md, "The box twins"). For each twin pair prints eta_re in both boxes and
beta = ln(eta_16 / eta_8) / ln(eta_8), the exponent in ln eta_bulk = (1 + beta) ln eta_re
(surrogate/offset_family.hpp), with its standard error from the two runs' SEMs; then the prior
the default surrogate family uses:
  mean = 1.5 m, sd = sqrt(s^2 + (0.5 m)^2 + se_m^2),
m the mean of the twins' beta, s their scatter (sd), se_m the mean's standard error from the
SEMs. Why 1.5 m +- 0.5 m: the 16a box is not yet the bulk; a gap effect that decays as 1 / H
(a wall layer of fixed width) leaves as much again between 16a and an infinite gap, one that
decays faster leaves nothing.
Usage: python3 scripts/box_twins.py [ID_h16.result.json ...]   (default: the committed twins in
data/cases/library_v2/results/; the 8a twin of ID is data/library/v2/n8/cases/ID.json)."""
import glob
import json
import math
import os
import sys

root = os.path.join(os.path.dirname(__file__), "..")
files = sys.argv[1:] or sorted(glob.glob(os.path.join(root, "data/cases/library_v2/results/*_h16.result.json")))
betas, ses = [], []
print(f"{'case':34s} {'phi_eff':>7s} {'eta_re 8a':>14s} {'eta_re 16a':>14s} {'ratio':>6s} {'beta':>15s}")
for f in files:
    case_id = os.path.basename(f).replace("_h16.result.json", "")
    eight = os.path.join(root, "data/library/v2/n8/cases", case_id + ".json")
    if not os.path.exists(eight):
        sys.exit(f"{f}: no 8a twin {eight}")
    r16 = json.load(open(f))["result"]
    r8 = json.load(open(eight))["result"]
    e16, s16, e8, s8 = r16["eta_re"], r16["eta_re_sem"], r8["eta_re"], r8["eta_re_sem"]
    beta = math.log(e16 / e8) / math.log(e8)
    # d beta / d e16 = 1 / (e16 ln e8); d beta / d e8 = -(1 + beta) / (e8 ln e8)
    se = math.hypot(s16 / (e16 * math.log(e8)), (1.0 + beta) * s8 / (e8 * math.log(e8)))
    betas.append(beta)
    ses.append(se)
    phi_eff = r8["phi_actual"] * 1.586
    print(f"{case_id:34s} {phi_eff:7.3f} {e8:7.3f} +- {s8:4.2f} {e16:7.3f} +- {s16:4.2f} {e16 / e8:6.3f} {beta:+7.3f} +- {se:5.3f}")
n = len(betas)
if n == 0:
    sys.exit("no twins")
m = sum(betas) / n
s = math.sqrt(sum((b - m) ** 2 for b in betas) / (n - 1)) if n > 1 else 0.0
se_m = math.sqrt(sum(e * e for e in ses)) / n
print(f"{n} twins: mean beta {m:+.3f}, scatter {s:.3f}, standard error of the mean {se_m:.3f}")
print(f"prior for the bulk: mean {1.5 * m:.3f}, sd {math.sqrt(s * s + (0.5 * m) ** 2 + se_m * se_m):.3f}")
