#!/usr/bin/python3
"""Blind predictions for the second seeds of the N_a 12 anchors, written before the runs.

A second seed of an anchor differs from the first only in where its cells start. If one
N_a 12 run in the 16a gap carries only its own noise (about 0.018 in ln eta per run, as the
N_a 8 seed pairs in the same gap measured: docs/library.md, "What the level is known to"),
the two seeds agree to about sqrt(2) x 0.018 = 2.5 %. If the 4-6 % deviations between
neighbouring N_a 12 rows are seed scatter, the seeds differ by about 6-8 %.
The model's prediction (its 16a-gap value and sd, from blind_predictions_gap.py's CSV) is
printed beside; the model holds the first seed in sample.
  STEP_TO_16A=0.012 RBCAL_FAMILY=$PWD/data/library/default/surrogate_family.json python3 \
      studies/dense-anchors/blind_predictions_gap.py 12 > ALL12.csv
  python3 studies/dense-anchors/level_from_anchors/seed_predictions.py ALL12.csv > OUT.csv
"""
import csv
import json
import math
import os
import sys

ROOT = os.path.abspath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", ".."))
RESULTS = os.path.join(ROOT, "data", "library", "anchors", "results")
SEED_NOISE = 0.018


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    lines = [line for line in open(sys.argv[1]) if not line.startswith("#")]
    model = {row["case"]: row for row in csv.DictReader(lines)}
    plan = json.load(open(os.path.join(ROOT, "data", "library", "anchors", "plan_n12_seed2.json")))
    print("case,eta_seed1,sem_seed1,low95_if_noise,high95_if_noise,eta_model,sd_model")
    for path in plan["case_files"]:
        case = os.path.basename(path)[: -len(".json")]
        first = case[: -len("_seed2")]
        result = json.load(open(os.path.join(RESULTS, first + ".result.json")))["result"]
        eta, sem = result["eta_re"], result["eta_re_sem"]
        # the difference of two runs: both runs' noise and the first run's sem
        sd = math.sqrt(2 * SEED_NOISE ** 2 + (sem / eta) ** 2)
        row = model[first]
        print(f"{case},{eta:.4f},{sem:.4f},{eta * math.exp(-1.96 * sd):.4f},"
              f"{eta * math.exp(1.96 * sd):.4f},{float(row['eta_re_16a']):.4f},"
              f"{float(row['sd_16a']):.4f}")


if __name__ == "__main__":
    main()
