#!/usr/bin/python3
"""The shipped family with a box step that depends on Ca (a trial, not shipped): its box prior
(mean, sd) kept below Ca = KNEE, and beta(Ca) = mean + SLOPE ln(Ca / KNEE) above it, the slope
normal(SLOPE, SLOPE_SD) integrated out (surrogate/offset_family.hpp). Then judged as
evaluate_model.py judges a model. Usage, from the repository root (about a minute):
  python3 studies/dense-anchors/box_at_high_ca/family_with_ca_step.py OUT KNEE SLOPE SLOPE_SD
"""
import json
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from evaluate_model import ROOT, evaluate

out = os.path.abspath(sys.argv[1])
knee, slope, slope_sd = (float(v) for v in sys.argv[2:5])
os.makedirs(out, exist_ok=True)
family = json.load(open(os.path.join(ROOT, "data", "library", "default", "surrogate_family.json")))
family["box_correction"].update({"ca_knee": knee, "ca_slope": slope, "ca_slope_sd": slope_sd})
family["box_correction"]["source"] += f"; trial: Ca step above {knee}, slope {slope} +- {slope_sd}"
family_file = os.path.join(out, "surrogate_family.json")
json.dump(family, open(family_file, "w"))
evaluate(family_file, out)
