#!/usr/bin/python3
"""The finer anchors' level and Ca shape against a family built on runs already moved to the
16a gap: each lambda 5 anchor at N_a 12 or 16, labelled at the family's offset c 0.75
(phi_eff = g_c(N_a) phi as run), gives the exponent eps = ln eta_run / ln eta_model - 1 with its
standard error (the run's sem and the model's sd); a weighted least-squares plane
eps = e0 + e1 ln Ca + e2 (phi_eff - 0.40) + e3 ln Ca (phi_eff - 0.40) through them is written to
OUT.json for trial_ca_box.py (LEVEL=OUT.json). LEAVE_OUT=phieff0.50 (a substring of the anchor
names) fits without those anchors, for a held-out check. Prints each anchor's eps and the fit.

Usage, from the repository root (seconds; one `rbcal surrogate predict` per anchor):
  python3 studies/dense-anchors/level_from_anchors/fit_level.py FAMILY OUT.json
"""
import json
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
sys.argv, args = sys.argv[:1], sys.argv[1:]
family_file, out = args
os.environ["RBCAL_FAMILY"] = family_file
import shipped_family as sf  # noqa: E402  (reads RBCAL_FAMILY at import)

leave_out = os.environ.get("LEAVE_OUT")
beta = json.load(open(family_file)).get("box_correction", {}).get("mean", 0.0)
rows, eps, se, names = [], [], [], []
print("| anchor | phi_eff | run | model (16a gap) | eps | se |")
print("|---|---|---|---|---|---|")
for point, by in sorted(sf.anchor_runs().items()):
    ca = float(point.split("_Ca")[1].split("_")[0])
    lam = float(point.split("_lambda")[1])
    if lam != 5.0 or (leave_out and leave_out in point):
        continue
    for n_a, (eta, sem, phi) in sorted(by.items()):
        if n_a < 12:
            continue
        phi_eff = sf.g(0.75, n_a) * phi
        bulk, sd = sf.member(phi_eff, ca, lam, 0.75)
        model = bulk ** (1.0 / (1.0 + beta))  # the family's box step beyond the 16a gap taken out
        e = math.log(eta) / math.log(model) - 1.0
        # eps's se: the run's sem only. The model's sd is the same for a neighbouring run (it is
        # the model's own error, which eps is to remove), so it does not weigh the anchors.
        s = sem / eta / math.log(model)
        rows.append([1.0, math.log(ca), phi_eff - 0.40, math.log(ca) * (phi_eff - 0.40)])
        eps.append(e)
        se.append(math.hypot(s, 0.01))  # a 1 % floor for the seed scatter a single run does not show
        names.append(f"n{n_a}_{point}")
        print(f"| n{n_a}_{point} | {phi_eff:.3f} | {eta:.3f} | {model:.3f} | {e:+.4f} | {s:.4f} |")
A = np.array(rows) / np.array(se)[:, None]
b = np.array(eps) / np.array(se)
coef, *_ = np.linalg.lstsq(A, b, rcond=None)
cov = np.linalg.inv(A.T @ A)
resid = b - A @ coef
chi2 = float(resid @ resid)
dof = len(b) - len(coef)
print(f"eps = {coef[0]:+.4f} {coef[1]:+.4f} ln Ca {coef[2]:+.4f} (phi_eff - 0.40) {coef[3]:+.4f} ln Ca (phi_eff - 0.40)")
print("se: " + " ".join(f"{math.sqrt(cov[k, k]):.4f}" for k in range(4)) + f"; chi^2 {chi2:.1f} for {dof} dof")
for n, r, e in zip(names, rows, eps):
    print(f"  {n}: eps {e:+.4f}, plane {float(np.dot(r, coef)):+.4f}")
# The grid form: each N_a 12 anchor's own eps at its point (phi_eff rows, Ca columns), for
# trial_ca_box.py's bilinear interpolation (the N_a 16 anchors are then the held-out check).
grid_phi = sorted({round(r[2] + 0.40, 3) for r, n in zip(rows, names) if n.startswith("n12_")})
grid_ca = sorted({round(math.exp(r[1]), 3) for r, n in zip(rows, names) if n.startswith("n12_")})
grid = [[None] * len(grid_ca) for _ in grid_phi]
for r, n, e in zip(rows, names, eps):
    if n.startswith("n12_"):
        grid[grid_phi.index(round(r[2] + 0.40, 3))][grid_ca.index(round(math.exp(r[1]), 3))] = e
json.dump({"about": "eps(phi_eff, Ca) = e0 = e0 + e1 ln Ca + e2 (phi_eff - phi0) + e3 ln Ca (phi_eff - phi0), "
                    "ln eta_anchor = (1 + eps) ln eta_model, fitted to the lambda 5 anchors at N_a 12 and 16"
                    + (f" without {leave_out}" if leave_out else ""),
           "e": [float(v) for v in coef], "cov": cov.tolist(), "phi0": 0.40, "ca_range": [0.1, 8.0],
           "phi_range": [0.30, 0.50],
           "grid": {"phi_eff": grid_phi, "ca": grid_ca, "eps": grid}, "chi2": chi2, "dof": dof, "anchors": names},
          open(out, "w"), indent=1)
