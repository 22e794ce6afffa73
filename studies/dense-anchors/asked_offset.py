#!/usr/bin/env python3
"""The offset c each anchor pair asks of a family: the c at which the family's member, at the
anchor's phi as run (the continuum, no thickening) and in the 16a gap (box correction at its
prior mean), equals the pair's first-order extrapolation in 1/N_a; bisection over the family's
offsets, with the c for the extrapolation +- its standard error. Run it against a family wider
than the shipped one:
    RBCAL_FAMILY=OUT/surrogate_family.json python3 studies/dense-anchors/asked_offset.py
(OUT built by `rbcal model build studies/dense-anchors/wide_family_recipe.json -o OUT`)."""
import json
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from shipped_family import FAMILY, anchor_runs, first_order_extrapolation, member_in_gap, point_parameters

family = json.load(open(FAMILY))
offsets = [m["offset"] for m in family["members"]]
lo_c, hi_c = offsets[0], offsets[-1]


def offset_for(target, phi, ca, lam):
    """c in [lo_c, hi_c] with the member in the gap = target (eta falls with c); None beyond the range."""
    if target > member_in_gap(phi, ca, lam, lo_c) or target < member_in_gap(phi, ca, lam, hi_c):
        return None
    a, b = lo_c, hi_c
    for _ in range(30):
        m = 0.5 * (a + b)
        if member_in_gap(phi, ca, lam, m) > target:
            a = m
        else:
            b = m
    return 0.5 * (a + b)


def shown(c):
    return f"{c:.3f}" if c is not None else f"beyond {lo_c:g}-{hi_c:g}"


print(f"family: {FAMILY} (offsets {lo_c:g} to {hi_c:g})")
print("| point | extrapolated | c asked | c at extrapolation + se / - se |")
print("|---|---|---|---|")
runs = anchor_runs()
for point in sorted(runs):
    by = runs[point]
    if (e := first_order_extrapolation(by)) is None:
        continue
    inf, sem, n1, n2 = e
    phi = by[n1][2]
    ca, lam = point_parameters(point)
    print(f"| {point} | {inf:.3f} +- {sem:.3f} (N_a {n1}, {n2}) | {shown(offset_for(inf, phi, ca, lam))} | "
          f"{shown(offset_for(inf + sem, phi, ca, lam))} / {shown(offset_for(inf - sem, phi, ca, lam))} |")
