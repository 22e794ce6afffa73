#!/usr/bin/env python3
"""The box exponent beta that the N_a 8 anchors (16a gap) imply against the shipped family's
members in the library's 8a gap (the family's predictions, which are for the bulk, moved back
to that gap: shipped_family.in_library_gap). At N_a 8, the library's own resolution, a member at
offset c evaluated at the anchor's phi_eff = g_c(8) phi as run stands for the library's 8a-gap
runs at that phi as run, whatever c (the mapping moves both alike), so
    ln eta_16a = (1 + beta) ln eta_8a   gives   beta = ln eta_run / ln eta_member - 1,
with the member's sd (and the run's standard error) propagated. This is the step from the model to the
bigger gap: the gap itself and the model's own error at those points together (the twins see
the gap alone). Printed for the members at c 0.45, 0.75 and 1.05 to show how far the
c-independence holds (the N_a 6 runs, mapped differently, also inform each member). `rbcal
model build` reads it the same way from a recipe's "box_correction.anchors". Usage: python3 studies/dense-anchors/box_from_anchors.py [RBCAL]"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from shipped_family import BETA_MEAN, BETA_SD, anchor_runs, twin_step, g, in_library_gap, member, point_parameters

OFFSETS = (0.45, 0.75, 1.05)


def beta_of(eta_run, sem_run, eta_member, sd_member):
    """(beta, sd) from ln eta_run = (1 + beta) ln eta_member."""
    b = math.log(eta_run) / math.log(eta_member) - 1.0
    # d beta / d ln eta_run = 1 / ln m; d beta / d ln m = -ln r / (ln m)^2
    lm, lr = math.log(eta_member), math.log(eta_run)
    sd = math.hypot((sem_run / eta_run) / lm, (sd_member / eta_member) * lr / lm ** 2)
    return b, sd


def main():
    print(f"the family's box correction for the bulk: beta {BETA_MEAN:.3f} +- {BETA_SD:.3f}; "
          f"the twins' own step to the 16a gap {twin_step():.3f}")
    print("| N_a 8 anchor | eta_re run | " + " | ".join(f"member c {c:g} | beta" for c in OFFSETS) + " |")
    print("|---|---|" + "---|---|" * len(OFFSETS))
    sums = {c: [0.0, 0.0] for c in OFFSETS}
    for point, by in sorted(anchor_runs().items()):
        if 8 not in by:
            continue
        eta, sem, phi = by[8]
        ca, lam = point_parameters(point)
        cells = [f"{eta:.3f} +- {sem:.3f}"]
        for c in OFFSETS:
            m, s = in_library_gap(*member(g(c, 8) * phi, ca, lam, c))
            b, sd = beta_of(eta, sem, m, s)
            sums[c][0] += b / sd ** 2
            sums[c][1] += 1.0 / sd ** 2
            cells += [f"{m:.3f} +- {s:.3f}", f"{b:+.3f} +- {sd:.3f}"]
        print(f"| {point} | " + " | ".join(cells) + " |")
    # The members' errors at neighbouring points are correlated, so the weighted mean's sd is a
    # lower bound; the sd of a single point is the honest upper bound.
    for c in OFFSETS:
        w, n = sums[c]
        print(f"c {c:g}: weighted mean beta {w / n:+.3f} (sd {1 / math.sqrt(n):.3f} if the points were independent)")


if __name__ == "__main__":
    main()
