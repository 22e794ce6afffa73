#!/usr/bin/python3
"""The finished anchors against the shipped model's predictions for their 16a gap, one table per
resolution, with the z-scores' mean and root mean square: is the model's sd the right size for
runs it was not trained on? (The N_a 8 and 12 predictions are not blind: those anchors chose the
width of the offset's prior; the N_a 16 file was written before any N_a 16 run.) The prediction
files come from blind_predictions_gap.py N_A > FILE with the shipped family.
Usage (from the repository root): python3 studies/dense-anchors/shipped_model_z.py"""
import csv
import json
import math
import os

HERE = os.path.dirname(os.path.abspath(__file__))
RESULTS = os.path.join(HERE, "..", "..", "data", "library", "anchors", "results")
FILES = ["shipped_model_n8_gap.csv", "shipped_model_n12_gap.csv", "blind_predictions_n16_gap_shipped.csv"]

for name in FILES:
    with open(os.path.join(HERE, name)) as f:
        rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
    zs = []
    print(f"\n{name}\n\n| anchor | eta_re run | prediction, 16a gap | run / prediction | z |\n|---|---|---|---|---|")
    for r in rows:
        path = os.path.join(RESULTS, r["case"] + ".result.json")
        if not os.path.exists(path):
            continue
        res = json.load(open(path))["result"]
        pred, sd = float(r["eta_re_16a"]), float(r["sd_16a"])
        z = (res["eta_re"] - pred) / math.hypot(sd, res["eta_re_sem"])
        zs.append(z)
        print(f"| {r['case']} | {res['eta_re']:.3f} +- {res['eta_re_sem']:.3f} | {pred:.3f} +- {sd:.3f} | "
              f"{res['eta_re'] / pred:.3f} | {z:+.2f} |")
    if zs:
        print(f"\n{len(zs)} runs: mean z {sum(zs) / len(zs):+.2f}, "
              f"root mean square {math.sqrt(sum(z * z for z in zs) / len(zs)):.2f}")
