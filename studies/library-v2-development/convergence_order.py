#!/usr/bin/env python3
"""Observed convergence order and Richardson estimates from three runs of one case at
N_a = n1 < n2 < n3 (studies/library-v2-development/README.md; issue 16, items 1 and 2).

    python3 studies/library-v2-development/convergence_order.py START END N1:SERIES1 N2:SERIES2 N3:SERIES3 [--orders 2,2.8,3]

Each SERIES is a run's series.csv; eta_re (stresslet) is averaged over [START, END] with
the solver's blocking error (scripts/window_average.py). Prints the ratio of successive
differences with its sd, the order p that the ratio implies for an error ~ h^p (h = 1 / N_a)
with the range from ratio +- sd, the Richardson estimate of both pairs for each order, and
what the pair (n1, n2) predicts at n3 for each order.
"""
import csv
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts"))
from window_average import block_average  # noqa: E402


def window_mean(path, start, end):
    with open(path) as f:
        values = [float(r["eta_re_stresslet"]) for r in csv.DictReader(f)
                  if start - 1e-9 <= float(r["strain"]) <= end + 1e-9]
    if len(values) < 8:
        sys.exit(f"{path}: only {len(values)} rows in [{start}, {end}]")
    mean, sem, _ = block_average(values)
    return mean, sem


def ratio_for(order, n):
    h = [x ** -order for x in n]
    return (h[0] - h[1]) / (h[1] - h[2])


def order_for(ratio, n):
    """The p with ratio_for(p) == ratio (ratio_for rises with p), by bisection."""
    lo, hi = 0.05, 12.0
    if not ratio_for(lo, n) < ratio < ratio_for(hi, n):
        return float("nan")
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if ratio_for(mid, n) < ratio:
            lo = mid
        else:
            hi = mid
    return 0.5 * (lo + hi)


def richardson(fine, coarse, r, p):
    return fine + (fine - coarse) / (r ** p - 1.0)


def main():
    args = list(sys.argv[1:])
    orders = [2.0, 2.8, 3.0]
    if "--orders" in args:
        i = args.index("--orders")
        orders = [float(x) for x in args[i + 1].split(",")]
        del args[i:i + 2]
    if len(args) != 5:
        sys.exit(__doc__)
    start, end = float(args[0]), float(args[1])
    runs = []
    for spec in args[2:]:
        n, path = spec.split(":", 1)
        runs.append((int(n), path) + window_mean(path, start, end))
    runs.sort()
    n = [r[0] for r in runs]
    eta = [r[2] for r in runs]
    sem = [r[3] for r in runs]
    for r in runs:
        print(f"N_a {r[0]:2d}: {r[2]:.4f} +- {r[3]:.3f}  ({r[1]})")
    d1, d2 = eta[0] - eta[1], eta[1] - eta[2]
    ratio = d1 / d2
    sd = abs(ratio) * math.sqrt((sem[0] ** 2 + sem[1] ** 2) / d1 ** 2 + (sem[1] ** 2 + sem[2] ** 2) / d2 ** 2)
    p = order_for(ratio, n)
    p_lo, p_hi = order_for(ratio - sd, n), order_for(ratio + sd, n)
    print(f"differences {d1:.4f}, {d2:.4f}; ratio {ratio:.3f} +- {sd:.3f}; order {p:.2f} ({p_lo:.2f} to {p_hi:.2f} within one sd)")
    for q in orders:
        a = richardson(eta[1], eta[0], n[1] / n[0], q)
        b = richardson(eta[2], eta[1], n[2] / n[1], q)
        predicted = a + (eta[1] - a) * (n[1] / n[2]) ** q
        print(f"order {q:g}: Richardson ({n[0]}, {n[1]}) {a:.4f}, ({n[1]}, {n[2]}) {b:.4f}; "
              f"({n[0]}, {n[1]}) predicts N_a {n[2]} as {predicted:.4f} (measured {eta[2]:.4f} +- {sem[2]:.3f})")


if __name__ == "__main__":
    main()
