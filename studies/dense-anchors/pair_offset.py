#!/usr/bin/env python3
"""The offset c that makes the anchors' resolutions one suspension: the runs at N_a 8, 12 and 16
(same cells, same 16a gap) are taken as one continuum curve eta_re(phi_eff) seen at
phi_eff = g_c(N_a) phi as run, and c is the value at which one curve fits both. The curve's form
is an assumption, so three are used, each with eta_re = 1 at phi_eff 0:
    exponential (two resolutions a, b at a time): ln eta = alpha x, so ln eta_a / ln eta_b = g_c(a) phi_a / (g_c(b) phi_b)
    log-quadratic (per Ca):           ln eta = a x + b x^2
    Krieger-Dougherty (per Ca):       ln eta = -k ln(1 - x / x_max)
Weights are the runs' standard errors (relative, on ln eta). Prints c per pair, then chi^2 over c
for all Ca together and the best c per Ca; no rbcal needed:
    python3 studies/dense-anchors/pair_offset.py"""
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from shipped_family import anchor_runs, g, point_parameters

def anchor_rows():
    """{Ca: [(N_a, phi as run, ln eta, sd of ln eta)]} of the committed anchors, only the Ca
    with both resolutions (the others carry no information on c)."""
    rows = {}
    for point, by in anchor_runs().items():
        ca, _ = point_parameters(point)
        for n_a, (eta, sem, phi) in by.items():
            rows.setdefault(ca, []).append((n_a, phi, math.log(eta), sem / eta))
    return {ca: r for ca, r in rows.items() if len({n for n, *_ in r}) > 1}


def pair_offsets():
    """[(point, (N_a a, N_a b), c, c with the ratio moved by +-1 standard error)] under the
    exponential law, for every two resolutions run at a point (the N_a 16 runs' phi as run
    differs from the others' by up to 0.7 %, so the law carries each run's own phi)."""
    out = []
    for point, by in sorted(anchor_runs().items()):
        tiers = sorted(by)
        for i, a in enumerate(tiers):
            for b in tiers[i + 1:]:
                (ea, sa, pa), (eb, sb, pb) = by[a], by[b]
                ya, yb, sa, sb = math.log(ea), math.log(eb), sa / ea, sb / eb
                solve = lambda ratio: solve_ratio(ratio * pb / pa, a, b)
                shifted = [solve((ya + z * sa) / (yb - z * sb)) for z in (1.0, -1.0)]
                out.append((point, (a, b), solve(ya / yb), shifted))
    return out


def solve_ratio(ratio, a=8, b=12):
    """c with g_c(a) / g_c(b) = ratio (bisection on 0-5; None outside)."""
    f = lambda c: g(c, a) / g(c, b) - ratio
    lo, hi = 0.0, 5.0
    if f(lo) * f(hi) > 0:
        return None
    for _ in range(60):
        m = 0.5 * (lo + hi)
        lo, hi = (lo, m) if f(lo) * f(m) <= 0 else (m, hi)
    return 0.5 * (lo + hi)


def weighted_fit(columns, y, sd):
    """Least squares of y on the columns with weights 1/sd; (chi^2, coefficients)."""
    a = np.column_stack(columns) / sd[:, None]
    coef, *_ = np.linalg.lstsq(a, y / sd, rcond=None)
    return float(np.sum((a @ coef - y / sd) ** 2)), coef


def chi2_log_quadratic(x, y, sd):
    return weighted_fit([x, x * x], y, sd)[0]


def chi2_krieger_dougherty(x, y, sd):
    """Best over x_max on a grid above the largest x (k by linear least squares)."""
    best = math.inf
    for x_max in np.geomspace(x.max() * 1.01, 20.0, 400):
        chi2, coef = weighted_fit([-np.log(1.0 - x / x_max)], y, sd)
        if coef[0] > 0:
            best = min(best, chi2)
    return best


FORMS = {"log-quadratic": chi2_log_quadratic, "Krieger-Dougherty": chi2_krieger_dougherty}


def chi2_at(c, rows, form):
    n_a, phi, y, sd = (np.array(v, dtype=float) for v in zip(*rows))
    x = np.array([g(c, n) for n in n_a]) * phi
    return FORMS[form](x, y, sd)


def best_offset(offsets, chi2):
    """(c at the minimum of chi^2 over the grid, chi^2 there)."""
    i = int(np.argmin(chi2))
    return offsets[i], chi2[i]


def interval(offsets, chi2, rise):
    """The range of c where chi^2 lies within `rise` of its minimum."""
    inside = offsets[chi2 <= chi2.min() + rise]
    return inside.min(), inside.max()


def main():
    print("| point | resolutions (N_a) | c, exponential law | c with the ratio +- its standard error |")
    print("|---|---|---|---|")
    shown = lambda c: "-" if c is None else f"{c:.2f}"
    for point, (a, b), c, (lo, hi) in pair_offsets():
        print(f"| {point} | {a}, {b} | {shown(c)} | {shown(hi)}-{shown(lo)} |")
    print()
    rows = anchor_rows()
    offsets = np.arange(0.20, 2.501, 0.01)
    n_points = sum(len(r) for r in rows.values())
    print(f"Ca with runs at two resolutions: {sorted(rows)}; {n_points} runs")
    print("| curve | c (all Ca) | 68 % range | chi^2 / dof at the best c | c per Ca (68 % range, chi^2 / dof) |")
    print("|---|---|---|---|---|")
    for form in FORMS:
        per_ca = {ca: np.array([chi2_at(c, r, form) for c in offsets]) for ca, r in rows.items()}
        total = sum(per_ca.values())
        dof = n_points - 2 * len(rows) - 1
        c_best, chi2_min = best_offset(offsets, total)
        rise = max(1.0, chi2_min / dof) if dof > 0 else 1.0
        lo, hi = interval(offsets, total, rise)
        each = []
        for ca in sorted(per_ca):
            c_ca, chi2_ca = best_offset(offsets, per_ca[ca])
            lo_ca, hi_ca = interval(offsets, per_ca[ca], 1.0)
            each.append(f"Ca {ca:g}: {c_ca:.2f} ({lo_ca:.2f}-{hi_ca:.2f}, chi^2 {chi2_ca:.1f} / {len(rows[ca]) - 3})")
        each = "; ".join(each)
        print(f"| {form} | {c_best:.2f} | {lo:.2f}-{hi:.2f} | {chi2_min:.1f} / {dof} | {each} |")


if __name__ == "__main__":
    main()
