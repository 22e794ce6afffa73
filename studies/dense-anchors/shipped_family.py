"""The shipped surrogate family as the anchor scripts ask it: its file, its box correction,
the thickened-volume factor g_c(N_a) of the 1280-triangle Evans-Fung mesh, and one member's
prediction through `rbcal surrogate predict` (the scripts' one optional argument names the
rbcal to call; default: this clone's build), and the finished anchors with their first-order
extrapolation in 1/N_a. Imported by blind_predictions.py, implied_offset.py, resolution.py and
asked_offset.py."""
import functools
import glob
import json
import math
import os
import re
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


def anchor_runs():
    """The committed anchors: {point: {N_a: (eta_re, sem, phi_actual)}}, point e.g.
    "phieff0.40_Ca0.5_lambda5"."""
    runs = {}
    for path in glob.glob(os.path.join(ROOT, "data", "library", "anchors", "results", "n*_*.result.json")):
        name = os.path.basename(path)[: -len(".result.json")]
        if "_seed" in name:  # a further seed of a point (its first seed stands for the point here)
            continue
        n_a, point = re.match(r"n(\d+)_(.*)", name).groups()
        r = json.load(open(path))["result"]
        runs.setdefault(point, {})[int(n_a)] = (r["eta_re"], r["eta_re_sem"], r["phi_actual"])
    return runs


def first_order_extrapolation(by):
    """(eta_inf, sem, n1, n2) from the coarsest and finest runs of one point, first order in
    1/N_a; None with fewer than two resolutions."""
    have = sorted(by)
    if len(have) < 2:
        return None
    n1, n2 = have[0], have[-1]
    (e1, s1, _), (e2, s2, _) = by[n1], by[n2]
    return (n2 * e2 - n1 * e1) / (n2 - n1), math.hypot(n2 * s2, n1 * s1) / (n2 - n1), n1, n2


# The family's predictions are for the bulk: its box correction (beta at its prior mean, ln
# eta_bulk = (1 + beta) ln eta_8a) is integrated into them. The anchors' 16a gap lies part of
# the way: the twins measured the step from the 8a gap to the 16a one directly, twin_step() (the
# same runs in both gaps; data/library/default/build_report.txt, "box correction from twin
# runs"), so ln eta_16a = (1 + twin_step()) / (1 + beta) ln eta_bulk.
# A family whose box prior comes from the anchors themselves is moved back to the 16a gap by
# the anchors' own mean step n instead, read from the build_report.txt beside the family file
# ("N anchors: mean beta +n"); the old twins' 0.068 applies only to a family whose prior came
# from the twins alone (using it for an anchor-based family puts the predictions about 6 %
# high). STEP_TO_16A=N overrides both. Found when first asked, so that the scripts that never
# move a prediction to the 16a gap need neither.
@functools.lru_cache(maxsize=None)
def twin_step():
    if "STEP_TO_16A" in os.environ:
        return float(os.environ["STEP_TO_16A"])
    if "anchor runs" not in BOX.get("source", ""):
        return 0.068
    report = os.path.join(os.path.dirname(os.path.abspath(FAMILY)), "build_report.txt")
    if os.path.exists(report):
        for line in open(report):
            found = re.search(r"\d+ anchors: mean beta ([-+0-9.]+)", line)
            if found:
                return float(found.group(1))
    sys.exit(f"{FAMILY}: its box prior comes from anchor runs, but no build_report.txt beside it gives "
             "their mean step: set STEP_TO_16A (the report's 'anchors: mean beta')")


def in_gap(eta_bulk, sd_bulk=0.0, beta=BETA_MEAN):
    """(eta, sd) in the 16a gap from a bulk prediction made with box correction beta (sd scaled
    to first order)."""
    exponent = (1.0 + twin_step()) / (1.0 + beta)
    eta = math.exp(exponent * math.log(eta_bulk))
    return eta, exponent * eta / eta_bulk * sd_bulk


def in_library_gap(eta_bulk, sd_bulk=0.0):
    """(eta, sd) in the library's 8a gap from the family's bulk prediction."""
    eta = math.exp(math.log(eta_bulk) / (1.0 + BETA_MEAN))
    return eta, eta / eta_bulk * sd_bulk / (1.0 + BETA_MEAN)


def member_in_gap(phi, ca, lam, c):
    """The member at offset c in the anchors' 16a gap."""
    return in_gap(member_eta(phi, ca, lam, c))[0]


def point_parameters(point):
    """(Ca, lambda) of an anchor point's name."""
    return (float(re.search(r"_Ca([0-9.]+)_", point).group(1)), float(re.search(r"_lambda([0-9.]+)", point).group(1)))
