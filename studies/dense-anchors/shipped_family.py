"""The shipped surrogate family as the anchor scripts ask it: its file, its box correction,
the thickened-volume factor g_c(N_a) of the 1280-triangle Evans-Fung mesh, and one member's
prediction through `rbcal surrogate predict` (the scripts' one optional argument names the
rbcal to call; default: this clone's build). Imported by blind_predictions.py,
implied_offset.py and resolution.py."""
import json
import math
import os
import subprocess
import sys

ROOT = os.path.abspath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
# RBCAL_FAMILY names another family file (e.g. one built from wide_family_recipe.json).
FAMILY = os.environ.get("RBCAL_FAMILY", os.path.join(ROOT, "data", "library", "default", "surrogate_family.json"))
BOX = json.load(open(FAMILY)).get("box_correction", {})
BETA_MEAN, BETA_SD = BOX.get("mean", 0.102), BOX.get("sd", 0.070)
RBCAL = sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, "build", "bin", "rbcal")

# Steiner's thickened volume of the 1280-triangle Evans-Fung mesh at radius 1 (S, V, M).
S, V, M = 8.716, 1.5605, 10.680


def g(c, n_a):
    d = c / n_a
    return 1.0 + (S * d + M * d * d + 4.0 * math.pi * d ** 3 / 3.0) / V


def member(phi, ca, lam, c):
    """(eta_re, sd) of the family's member at offset c."""
    out = subprocess.run([RBCAL, "surrogate", "predict", FAMILY, "--phi", repr(phi), "--ca", repr(ca), "--lambda",
                          repr(lam), "--offset", repr(c)], capture_output=True, text=True, check=True).stdout
    for line in out.splitlines():
        if line.strip().startswith("eta_re "):
            parts = line.split()
            return float(parts[1]), float(parts[3])
    raise RuntimeError(out)


def member_eta(phi, ca, lam, c):
    """eta_re of the family's member at offset c."""
    return member(phi, ca, lam, c)[0]
