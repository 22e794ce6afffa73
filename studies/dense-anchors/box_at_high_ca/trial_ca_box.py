#!/usr/bin/python3
"""A trial, not the shipped model: the library's runs moved from the 8a gap to the 16a gap by a
box step that depends on Ca, then the shipped recipe built on them and asked to recover a known
G_s from the N_a 8 and N_a 12 anchors, and to calibrate the shipped sample.

The step: ln eta_16a = (1 + beta(Ca)) ln eta_8a with beta(Ca) = LOW for Ca <= KNEE and
LOW + SLOPE ln(Ca / KNEE) above (from the twins: the library's own runs and the Ca 8 anchors
in both gaps). The model then stands for the 16a gap; the family file's box prior is set by
hand to the step beyond it, BEYOND +- SD (the shipped rule's 0.5 m over the twins' mean m,
with the shipped prior's sd), so that the trial differs from the shipped model in the Ca
dependence of the step only.

Usage, from the repository root (minutes: one model build, one recovery, one calibration):
  python3 studies/dense-anchors/box_at_high_ca/trial_ca_box.py OUT LOW KNEE SLOPE [BEYOND SD]
  python3 studies/dense-anchors/box_at_high_ca/trial_ca_box.py OUT CA:BETA,CA:BETA,... [BEYOND SD]
  python3 studies/dense-anchors/box_at_high_ca/trial_ca_box.py OUT GRID.json [BEYOND SD]
(the second form: measured steps, linear in ln Ca between them and constant beyond; the third:
measured steps over phi_eff and Ca, as in measured_steps.json, bilinear in phi_eff and ln Ca).
"""
import glob
import json
import math
import os
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from evaluate_model import RBCAL, ROOT, evaluate

out = os.path.abspath(sys.argv[1])
grid = None
if sys.argv[2].endswith(".json"):  # a grid over phi_eff and Ca (measured_steps.json's form)
    grid = json.load(open(sys.argv[2]))
    table = None
    rest = sys.argv[3:]
elif ":" in sys.argv[2]:  # a table CA:BETA,CA:BETA,... (linear in ln Ca, constant beyond its ends)
    table = sorted((float(a), float(b)) for a, b in (item.split(":") for item in sys.argv[2].split(",")))
    rest = sys.argv[3:]
else:
    low, knee, slope = (float(v) for v in sys.argv[2:5])
    table = None
    rest = sys.argv[5:]
beyond = float(rest[0]) if len(rest) > 0 else 0.034
# RESOLUTION_STEP=RHO also moves each run to the N_a 12 level, ln eta_12 = (1 + RHO) ln eta_8 per
# step from N_a 8 to 12 (compounded in 1/N_a: twice from N_a 6), and labels it N_a 12, the way
# the N_a 8 and N_a 12 anchors of one point relate (rho -0.13 to -0.19 over nine pairs). The
# N_a 6 runs are then left out: moved two such steps they break the model's trends.
RESOLUTION_STEP = float(os.environ["RESOLUTION_STEP"]) if "RESOLUTION_STEP" in os.environ else None
sd = float(rest[1]) if len(rest) > 1 else 0.059
# LEVEL=FILE.json (studies/dense-anchors/level_from_anchors/fit_level.py) also moves each run onto
# the finer anchors' level: ln eta = (1 + eps(phi_eff, Ca)) ln eta_16a, eps from the file's grid
# (bilinear, as the box step's) or, with LEVEL_FORM=plane, its fitted plane.
LEVEL = json.load(open(os.environ["LEVEL"])) if "LEVEL" in os.environ else None
LEVEL_FORM = os.environ.get("LEVEL_FORM", "grid")


# The library's thickened volume fraction, g(c / N_a) phi at its offset c 0.75 (Steiner's
# formula with the Evans-Fung cell's S, M, V in cell radii: studies/ib-thickening/).
def effective_phi(phi, n_a, c=0.75, S=8.716, M=10.680, V=1.5605):
    d = c / n_a
    return phi * (1.0 + (S * d + M * d * d + 4.0 * math.pi / 3.0 * d ** 3) / V)


def interpolate(xs, ys, x):  # linear, constant beyond the ends
    if x <= xs[0]:
        return ys[0]
    for x0, x1, y0, y1 in zip(xs, xs[1:], ys, ys[1:]):
        if x <= x1:
            return y0 + (y1 - y0) * (x - x0) / (x1 - x0)
    return ys[-1]


def grid_value(table, key, phi_eff, ca):
    """Bilinear in (phi_eff, ln Ca), constant beyond the grid's Ca ends and its densest row;
    below its first row the value falls linearly to 0 at phi_eff 0 (no cells, no correction)."""
    rows = [interpolate([math.log(c) for c in table["ca"]], row, math.log(ca)) for row in table[key]]
    phis = table["phi_eff"]
    if phi_eff < phis[0]:
        return rows[0] * phi_eff / phis[0]
    return interpolate(phis, rows, phi_eff)


def level_eps(phi_eff, ca):
    if LEVEL_FORM == "grid":
        return grid_value(LEVEL["grid"], "eps", phi_eff, ca)
    lo, hi = LEVEL["phi_range"]
    x = math.log(min(max(ca, LEVEL["ca_range"][0]), LEVEL["ca_range"][1]))
    y = min(max(phi_eff, lo), hi) - LEVEL["phi0"]
    e = LEVEL["e"]
    value = e[0] + e[1] * x + e[2] * y + e[3] * x * y
    return value * min(1.0, phi_eff / lo)


def beta(ca, phi_eff=None):
    if grid is not None:
        return grid_value(grid, "beta", phi_eff, ca)
    if table is None:
        return low if ca <= knee else low + slope * math.log(ca / knee)
    if ca <= table[0][0]:
        return table[0][1]
    for (c0, b0), (c1, b1) in zip(table, table[1:]):
        if ca <= c1:
            return b0 + (b1 - b0) * math.log(ca / c0) / math.log(c1 / c0)
    return table[-1][1]


os.makedirs(out, exist_ok=True)
recipe = json.load(open(os.path.join(ROOT, "data", "library", "default", "recipe.json")))
runs = []
for tier in ("n8",) if RESOLUTION_STEP is not None else ("n6", "n8"):
    src = os.path.join(ROOT, "data", "library", "v2", tier)
    dst = os.path.join(out, "runs", tier)
    shutil.rmtree(dst, ignore_errors=True)
    shutil.copytree(src, dst)
    for f in glob.glob(os.path.join(dst, "cases", "*.json")):
        case = json.load(open(f))
        r = case.get("result")
        if not r or "eta_re" not in r:
            continue
        phi_eff = effective_phi(case["params"]["phi"], case["numerics"]["N_a"])
        exponent = 1.0 + beta(case["params"]["Ca"], phi_eff)
        if LEVEL is not None:
            exponent *= 1.0 + level_eps(phi_eff, case["params"]["Ca"])
        if RESOLUTION_STEP is not None:  # to the N_a 12 level, labelled as an N_a 12 run
            steps = (1.0 / case["numerics"]["N_a"] - 1.0 / 12.0) / (1.0 / 8.0 - 1.0 / 12.0)
            exponent *= (1.0 + RESOLUTION_STEP) ** steps
            case["numerics"]["N_a"] = 12
        eta = r["eta_re"]
        r["eta_re"] = eta ** exponent
        r["eta_re_sem"] *= exponent * r["eta_re"] / eta
        json.dump(case, open(f, "w"), indent=1)
    runs.append(dst)
recipe["about"] = f"trial: runs moved to the 16a gap by beta(Ca) = {sys.argv[2:]}"
recipe["runs"] = runs
recipe.pop("box_correction", None)
json.dump(recipe, open(os.path.join(out, "recipe.json"), "w"), indent=1)
subprocess.run([RBCAL, "model", "build", os.path.join(out, "recipe.json"), "-o", os.path.join(out, "model")],
               check=True, stdout=open(os.path.join(out, "build.log"), "w"), stderr=subprocess.STDOUT)
family_file = os.path.join(out, "model", "surrogate_family.json")
family = json.load(open(family_file))
family["box_correction"] = {"mean": beyond, "sd": sd, "source": "trial: the step beyond the 16a gap, set by hand"}
json.dump(family, open(family_file, "w"), indent=1)

evaluate(family_file, out)
