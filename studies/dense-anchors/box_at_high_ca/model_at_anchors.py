#!/usr/bin/python3
"""A family file's level at the finished anchors, in the 16a gap: each anchor (N_a 8, 12, 16)
labelled at the family's offset c 0.75 (phi_eff = g_c(N_a) phi as run), the member at c 0.75
asked through `rbcal surrogate predict`, its box correction to the bulk taken back out to the
16a gap by STEP_TO_16A (the shipped model's twins' mean, 0.068, or 0 for a family built on runs
already moved to the 16a gap, whose box prior is then only the step beyond it). Prints the
ratio run / model and z per anchor and the RMS of ln(run / model) per tier.

Usage, from the repository root:
  python3 studies/dense-anchors/box_at_high_ca/model_at_anchors.py FAMILY STEP_TO_16A
"""
import json
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
sys.argv, args = sys.argv[:1], sys.argv[1:]  # shipped_family reads its optional argument
family_file, step = args[0], float(args[1])
os.environ["RBCAL_FAMILY"] = family_file
import shipped_family as sf  # noqa: E402  (reads RBCAL_FAMILY at import)

beta = json.load(open(family_file)).get("box_correction", {}).get("mean", 0.0)
by_tier = {}
print("| anchor | run | model (16a gap) | run / model | z |")
print("|---|---|---|---|---|")
for point, by in sorted(sf.anchor_runs().items()):
    ca = float(point.split("_Ca")[1].split("_")[0])
    lam = float(point.split("_lambda")[1])
    for n_a, (eta, sem, phi) in sorted(by.items()):
        bulk, sd = sf.member(sf.g(0.75, n_a) * phi, ca, lam, 0.75)
        scale = (1.0 + step) / (1.0 + beta)
        model, model_sd = bulk ** scale, scale * sd * bulk ** scale / bulk
        z = (eta - model) / math.hypot(sem, model_sd)
        by_tier.setdefault(n_a, []).append(math.log(eta / model))
        print(f"| n{n_a}_{point} | {eta:.3f} | {model:.3f} +- {model_sd:.3f} | {eta / model:.3f} | {z:+.2f} |")
for n_a, logs in sorted(by_tier.items()):
    mean = sum(logs) / len(logs)
    rms = math.sqrt(sum(v * v for v in logs) / len(logs))
    print(f"N_a {n_a}: {len(logs)} anchors, mean ln(run / model) {mean:+.3f}, RMS {rms:.3f}")
