#!/usr/bin/python3
"""Blind predictions for the N_a 12 anchors between the first rows (phi_eff 0.35 and 0.45), in two
forms, written before the runs:
  - the model's: its prediction for the 16a gap and sd (from blind_predictions_gap.py's CSV);
  - the rows': the model's shape with the level the two neighbouring rows measured at the same
    Ca, r = ln(eta_run / eta_model) at phi_eff 0.30 and 0.40 (or 0.40 and 0.50), interpolated
    linearly in phi_eff, and its sd from the two runs' sems and one run's seed noise (0.018 in
    ln eta: docs/library.md, "What the level is known to").
If the rows' form lands within about 2 % where the model's misses by 4-5 %, the level measured
at N_a 12 can be carried between rows, and a denser N_a 12 grid pins a single point's level.
  STEP_TO_16A=0.012 RBCAL_FAMILY=$PWD/data/library/default/surrogate_family.json python3 \
      studies/dense-anchors/blind_predictions_gap.py 12 > ALL12.csv
(STEP_TO_16A: the anchors' own mean step n from the model's build_report.txt, which moves the
family's bulk prediction back to the 16a gap; the script's default is an older twin step.)
  python3 studies/dense-anchors/level_from_anchors/row_predictions.py ALL12.csv > OUT.csv
"""
import csv
import json
import math
import os
import re
import sys

ROOT = os.path.abspath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", ".."))
RESULTS = os.path.join(ROOT, "data", "library", "anchors", "results")
SEED_NOISE = 0.018
NEIGHBOURS = {"0.35": ("0.30", "0.40"), "0.45": ("0.40", "0.50")}


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    lines = [line for line in open(sys.argv[1]) if not line.startswith("#")]
    model = {row["case"]: row for row in csv.DictReader(lines)}
    print("case,phi_eff,eta_model,sd_model,r_low,r_high,eta_rows,sd_rows")
    for case, row in sorted(model.items()):
        m = re.match(r"n12_phieff(0\.\d+)_Ca([0-9.]+)_lambda5$", case)
        if not m or m.group(1) not in NEIGHBOURS:
            continue
        label, ca = m.groups()
        phi = float(row["phi_eff_at_prior_mean"])
        levels = []
        for neighbour in NEIGHBOURS[label]:
            name = f"n12_phieff{neighbour}_Ca{ca}_lambda5"
            result = json.load(open(os.path.join(RESULTS, name + ".result.json")))["result"]
            eta, sem = result["eta_re"], result["eta_re_sem"]
            levels.append((float(model[name]["phi_eff_at_prior_mean"]),
                           math.log(eta / float(model[name]["eta_re_16a"])), sem / eta))
        (p0, r0, s0), (p1, r1, s1) = levels
        w = (phi - p0) / (p1 - p0)
        r = (1 - w) * r0 + w * r1
        sd = math.sqrt(((1 - w) * s0) ** 2 + (w * s1) ** 2 + SEED_NOISE ** 2)
        eta_model = float(row["eta_re_16a"])
        print(f"{case},{phi:.4f},{eta_model:.4f},{float(row['sd_16a']):.4f},{r0:+.4f},{r1:+.4f},"
              f"{eta_model * math.exp(r):.4f},{eta_model * math.exp(r) * sd:.4f}")


if __name__ == "__main__":
    main()
