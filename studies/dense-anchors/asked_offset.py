#!/usr/bin/env python3
"""The offset c each anchor pair asks of a family: the c at which the family's member, at the
anchor's phi as run (the continuum, no thickening) and in the 16a gap (box correction at its
prior mean), equals the pair's first-order extrapolation in 1/N_a; bisection over the family's
offsets, with the c for the extrapolation +- its standard error. Run it against a family wider
than the shipped one:
    RBCAL_FAMILY=OUT/surrogate_family.json python3 studies/dense-anchors/asked_offset.py
(OUT built by `rbcal model build studies/dense-anchors/wide_family_recipe.json -o OUT`)."""
import glob
import json
import math
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from shipped_family import BETA_MEAN as beta, FAMILY, ROOT
from shipped_family import member_eta as member

family = json.load(open(FAMILY))
offsets = [m["offset"] for m in family["members"]]
lo_c, hi_c = offsets[0], offsets[-1]

runs = {}
for path in glob.glob(os.path.join(ROOT, "data", "library", "anchors", "results", "n*_*.result.json")):
    name = os.path.basename(path)[: -len(".result.json")]
    n_a, point = re.match(r"n(\d+)_(.*)", name).groups()
    r = json.load(open(path))["result"]
    runs.setdefault(point, {})[int(n_a)] = (r["eta_re"], r["eta_re_sem"], r["phi_actual"])


def in_gap(phi, ca, lam, c):
    return math.exp((1.0 + beta) * math.log(member(phi, ca, lam, c)))


def offset_for(target, phi, ca, lam):
    """c in [lo_c, hi_c] with in_gap = target (eta falls with c); None beyond the range."""
    if target > in_gap(phi, ca, lam, lo_c) or target < in_gap(phi, ca, lam, hi_c):
        return None
    a, b = lo_c, hi_c
    for _ in range(30):
        m = 0.5 * (a + b)
        if in_gap(phi, ca, lam, m) > target:
            a = m
        else:
            b = m
    return 0.5 * (a + b)


def shown(c):
    return f"{c:.3f}" if c is not None else f"beyond {lo_c:g}-{hi_c:g}"


print(f"family: {FAMILY} (offsets {lo_c:g} to {hi_c:g})")
print("| point | extrapolated | c asked | c at extrapolation + se / - se |")
print("|---|---|---|---|")
for point in sorted(runs):
    by = runs[point]
    have = sorted(by)
    if len(have) < 2:
        continue
    n1, n2 = have[0], have[-1]
    (e1, s1, phi), (e2, s2, _) = by[n1], by[n2]
    inf = (n2 * e2 - n1 * e1) / (n2 - n1)
    sem = math.hypot(n2 * s2, n1 * s1) / (n2 - n1)
    ca = float(re.search(r"_Ca([0-9.]+)_", point).group(1))
    lam = float(re.search(r"_lambda([0-9.]+)", point).group(1))
    print(f"| {point} | {inf:.3f} +- {sem:.3f} (N_a {n1}, {n2}) | {shown(offset_for(inf, phi, ca, lam))} | "
          f"{shown(offset_for(inf + sem, phi, ca, lam))} / {shown(offset_for(inf - sem, phi, ca, lam))} |")
