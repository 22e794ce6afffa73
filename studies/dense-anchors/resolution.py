#!/usr/bin/python3
"""The anchors at each resolution side by side, and their extrapolation in N_a.

Each point (phi as run, Ca) is run with the same cells at the same places at N_a 8, 12 and 16
(data/library/anchors/cases/n8_, n12_, n16_). The immersed boundary thickens the cells by about
c dx, so at first order eta_re(N_a) = eta_inf + b / N_a: two resolutions give
eta_inf = (N2 eta2 - N1 eta1) / (N2 - N1), its sem from the runs' sems. The model's number to
compare is the family at phi = phi as run (the continuum, no thickening), in the 16a gap (box
correction), at three of its offsets: each member is the library mapped with its own c. Usage, from the repository root:
  python3 studies/dense-anchors/resolution.py [RBCAL]
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from shipped_family import anchor_runs, first_order_extrapolation, member_in_gap, point_parameters

runs = anchor_runs()
print("| point | N_a 8 | N_a 12 | N_a 16 | extrapolated (first order in 1/N_a) | family at phi as run, 16a gap: c 0.55 / 0.75 / 0.95 |")
print("|---|---|---|---|---|---|")
for point in sorted(runs):
    by = runs[point]
    cells = [f"{by[n][0]:.3f} +- {by[n][1]:.3f}" if n in by else "-" for n in (8, 12, 16)]
    extrapolated = "-"
    if (e := first_order_extrapolation(by)) is not None:
        inf, sem, n1, n2 = e
        extrapolated = f"{inf:.3f} +- {sem:.3f} (N_a {n1}, {n2})"
    ca, lam = point_parameters(point)
    phi = next(iter(by.values()))[2]
    model = [member_in_gap(phi, ca, lam, c) for c in (0.55, 0.75, 0.95)]
    print(f"| {point} | " + " | ".join(cells) + f" | {extrapolated} | " + " / ".join(f"{m:.3f}" for m in model) + " |")
