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


def three_tier_extrapolation(by, draws=4000, seed=1):
    """Where N_a 8, 12 and 16 all ran: the apparent order p of eta(N_a) = eta_inf + b N_a^-p
    (from (eta8 - eta12) / (eta12 - eta16)) and eta_inf, with their spread over draws of the
    runs' sems (median, 16th and 84th percentiles); None where p leaves [0.25, 8]. A power law
    in eta_re is not what an offset makes: a thickening first order in 1/N_a moves phi_eff, and
    where eta_re is convex in phi_eff that falls faster than first order and extrapolates too
    high. pair_offset.py reads the tiers through the offset mapping instead."""
    import numpy as np
    rng = np.random.default_rng(seed)

    def solve(e8, e12, e16):
        r = (e8 - e12) / (e12 - e16) if e12 != e16 else np.inf
        ratio = lambda p: (8.0**-p - 12.0**-p) / (12.0**-p - 16.0**-p)
        lo, hi = 0.25, 8.0
        if not (ratio(lo) <= r <= ratio(hi)):
            return None
        for _ in range(60):
            mid = 0.5 * (lo + hi)
            lo, hi = (mid, hi) if ratio(mid) < r else (lo, mid)
        p = 0.5 * (lo + hi)
        return p, e16 - (e12 - e16) * 16.0**-p / (12.0**-p - 16.0**-p)

    central = solve(by[8][0], by[12][0], by[16][0])
    if central is None:
        return None
    samples = [solve(*(rng.normal(by[n][0], by[n][1]) for n in (8, 12, 16))) for _ in range(draws)]
    samples = np.array([s for s in samples if s is not None])
    spread = np.percentile(samples, [16, 84], axis=0)
    return central, spread, len(samples) / draws


print()
print("| point with three tiers | apparent order p (16-84 %) | eta_inf (16-84 %) | draws with p in [0.25, 8] |")
print("|---|---|---|---|")
for point in sorted(runs):
    by = runs[point]
    if not all(n in by for n in (8, 12, 16)):
        continue
    e = three_tier_extrapolation(by)
    if e is None:
        print(f"| {point} | not monotone | - | - |")
        continue
    (p, inf), spread, kept = e
    print(f"| {point} | {p:.2f} ({spread[0][0]:.2f}-{spread[1][0]:.2f}) | {inf:.3f} ({spread[0][1]:.3f}-{spread[1][1]:.3f}) | {kept:.0%} |")
