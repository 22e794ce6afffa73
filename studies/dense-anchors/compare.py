#!/usr/bin/python3
"""The finished anchors against the blind predictions: z = (run - prediction) / sqrt(sd^2 + sem^2);
the N_a 12 anchors first, then (once any has finished) the N_a 16 tier against its three levels.

blind_predictions.csv is kept as written before the runs. Its column "eta_re_8a_mixture" is in
fact the bulk mixture (the family's predictions carry its box correction), and "eta_re_bulk"
applies the correction a second time; the prediction for the anchors' 16a gap is the mixture
moved from the bulk to that gap (shipped_family.in_gap) with the box correction it was written
with (BLIND_BETA, the family of that day).

Usage (from the repository root): python3 studies/dense-anchors/compare.py
"""
import csv
import json
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
RESULTS = os.path.join(HERE, "..", "..", "data", "library", "anchors", "results")

sys.path.insert(0, HERE)
from shipped_family import in_gap

BLIND_BETA = 0.102  # the shipped family's box correction when blind_predictions.csv was written

# The N_a 12 rows, then the N_a 8 rows of blind_predictions_n8_n16.csv (written the same way,
# the same day, before those runs; its N_a 16 rows are superseded by the gap files below).
rows = list(csv.DictReader(open(os.path.join(HERE, "blind_predictions.csv"))))
rows += [r for r in csv.DictReader(open(os.path.join(HERE, "blind_predictions_n8_n16.csv"))) if r["case"].startswith("n8_")]
print("| anchor | eta_re run (stresslet) | wall | 16a-gap prediction | z | bulk prediction (as written) | z | run / c 0.75 member in the gap | overlapping pairs |")
print("|---|---|---|---|---|---|---|---|---|")
for r in rows:
    path = os.path.join(RESULTS, r["case"] + ".result.json")
    if not os.path.exists(path):
        continue
    res = json.load(open(path))["result"]
    eta, sem, wall = res["eta_re"], res["eta_re_sem"], res["eta_re_wall"]
    bulk, sd_bulk = float(r["eta_re_8a_mixture"]), float(r["sd_8a_mixture"])
    gap, sd_gap = in_gap(bulk, sd_bulk, BLIND_BETA)
    member = in_gap(float(r["eta_re_c0.75"]), 0.0, BLIND_BETA)[0]
    print(f"| {r['case']} | {eta:.3f} +- {sem:.3f} | {wall:.3f} | {gap:.3f} +- {sd_gap:.3f} | "
          f"{(eta - gap) / math.hypot(sd_gap, sem):+.2f} | {bulk:.3f} +- {sd_bulk:.3f} | "
          f"{(eta - bulk) / math.hypot(sd_bulk, sem):+.2f} | {eta / member:.3f} | {res.get('overlapping_cell_pairs')} |")

# The N_a 16 tier against its three blind predictions, written for the 16a gap before any
# N_a 16 run (blind_predictions_gap.py): the shipped family, the wide-offset family shipped
# before it, and the measured-thickening level.
LEVELS = [("shipped", "blind_predictions_n16_gap_shipped.csv"),
          ("wide offset", "blind_predictions_n16_gap_wide_offset.csv"),
          ("measured level", "blind_predictions_n16_gap_measured_level.csv")]

def predictions(name):
    with open(os.path.join(HERE, name)) as f:
        return {r["case"]: r for r in csv.DictReader(line for line in f if not line.startswith("#"))}

def print_table(title, tables):
    """The finished cases of the first table's file against each table's prediction."""
    finished = [case for case in tables[0][1] if os.path.exists(os.path.join(RESULTS, case + ".result.json"))]
    if not finished:
        return
    print(f"\n| {title} | eta_re run (stresslet) | wall | " +
          " | ".join(f"{label}: prediction | z" for label, _ in tables) + " | overlapping pairs |")
    print("|---|---|---|" + "---|---|" * len(tables) + "---|")
    for case in finished:
        res = json.load(open(os.path.join(RESULTS, case + ".result.json")))["result"]
        eta, sem = res["eta_re"], res["eta_re_sem"]
        cols = []
        for _, table in tables:
            pred, sd = float(table[case]["eta_re_16a"]), float(table[case]["sd_16a"])
            cols.append(f"{pred:.3f} +- {sd:.3f} | {(eta - pred) / math.hypot(sd, sem):+.2f}")
        print(f"| {case} | {eta:.3f} +- {sem:.3f} | {res['eta_re_wall']:.3f} | " + " | ".join(cols) +
              f" | {res.get('overlapping_cell_pairs')} |")


print_table("N_a 16 anchor", [(label, predictions(name)) for label, name in LEVELS])
# The anchors beyond the first twelve points (lambda 2.5 and 10, Ca 0.03 and 18, lambda 1), against the
# shipped family's predictions for the 16a gap written before they ran.
print_table("anchor (extension)", [("shipped", predictions("blind_predictions_extension_shipped.csv"))])
