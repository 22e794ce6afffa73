#!/usr/bin/python3
"""The finished anchors against the blind predictions: z = (run - prediction) / sqrt(sd^2 + sem^2).

Usage (from the repository root): python3 studies/dense-anchors/compare.py
"""
import csv
import json
import math
import os

HERE = os.path.dirname(os.path.abspath(__file__))
RESULTS = os.path.join(HERE, "..", "..", "data", "library", "anchors", "results")

rows = list(csv.DictReader(open(os.path.join(HERE, "blind_predictions.csv"))))
print("| anchor | eta_re run (stresslet) | wall | bulk prediction | z | 8a mixture | z | run / c 0.75 member | overlapping pairs |")
print("|---|---|---|---|---|---|---|---|---|")
for r in rows:
    path = os.path.join(RESULTS, r["case"] + ".result.json")
    if not os.path.exists(path):
        continue
    res = json.load(open(path))["result"]
    eta, sem, wall = res["eta_re"], res["eta_re_sem"], res["eta_re_wall"]
    bulk, sd_bulk = float(r["eta_re_bulk"]), float(r["sd_bulk"])
    mix, sd_mix = float(r["eta_re_8a_mixture"]), float(r["sd_8a_mixture"])
    member = float(r["eta_re_c0.75"])
    print(f"| {r['case']} | {eta:.3f} +- {sem:.3f} | {wall:.3f} | {bulk:.3f} +- {sd_bulk:.3f} | "
          f"{(eta - bulk) / math.hypot(sd_bulk, sem):+.2f} | {mix:.3f} +- {sd_mix:.3f} | "
          f"{(eta - mix) / math.hypot(sd_mix, sem):+.2f} | {eta / member:.3f} | {res.get('overlapping_cell_pairs')} |")
