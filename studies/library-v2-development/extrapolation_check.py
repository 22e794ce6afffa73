#!/usr/bin/env python3
"""The library's (N_a 6, 8) extrapolation against the points run finer
(studies/library-v2-development/README.md,
"The (6, 8) extrapolation against the finer runs"; issue 16, item 2).

    python3 studies/library-v2-development/extrapolation_check.py [--order 2.8] [--order-low 2,1.5,1]

For each reference point (Skalak C 10, runs in data/cases/resolution_v2/results/) it prints
the window means per N_a, the estimate `rbcal library extrapolate` would make from N_a 6
and 8 alone (Richardson of --order; sd from the two runs' errors and half the distance to
the estimate of each --order-low, as in surrogate/resolution_extrapolation), and the
Richardson estimates of the finest pair over orders 1 to 4, which bracket the continuum
value. Reference sequences that are not in the asymptotic range say so in the docs.
"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from convergence_order import window_mean  # noqa: E402

RESULTS = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "data", "cases", "resolution_v2", "results")
# (label, window start, window end, {N_a: series stem})
POINTS = [
    ("phi 0.05, Ca 3.2, lambda 0.1", 4, 10, {6: "phi0.05_Ca3.2_lambda0.1_n6_c10", 8: "phi0.05_Ca3.2_lambda0.1_n8_c10",
                                            10: "phi0.05_Ca3.2_lambda0.1_n10_c10", 12: "phi0.05_Ca3.2_lambda0.1_n12_c10"}),
    ("phi 0.21, Ca 0.2, lambda 5", 15, 40, {6: "phi0.21_Ca0.2_n6_t40", 8: "phi0.21_Ca0.2_n8", 10: "phi0.21_Ca0.2_n10"}),
    ("phi 0.55, Ca 0.8, lambda 5", 5, 10, {6: "phi0.55_Ca0.8_n6", 8: "phi0.55_Ca0.8_n8", 10: "phi0.55_Ca0.8_n10",
                                          12: "phi0.55_Ca0.8_n12_c10"}),
    ("phi 0.55, Ca 0.02, lambda 5 (to strain 10 only)", 5, 10, {6: "phi0.55_Ca0.02_n6", 8: "phi0.55_Ca0.02_n8",
                                                                10: "phi0.55_Ca0.02_n10"}),
]
FINEST_ORDERS = (1.0, 1.5, 2.0, 2.8, 4.0)


def richardson(fine, coarse, r, p):
    return fine + (fine - coarse) / (r ** p - 1.0)


def option(args, name, default):
    if name in args:
        i = args.index(name)
        value = args[i + 1]
        del args[i:i + 2]
        return value
    return default


def main():
    args = list(sys.argv[1:])
    order = float(option(args, "--order", "2.8"))
    lows = [float(x) for x in option(args, "--order-low", "2,1.5,1").split(",")]
    if args:
        sys.exit(__doc__)
    for label, start, end, stems in POINTS:
        runs = {n: window_mean(os.path.join(RESULTS, stem + ".series.csv"), start, end) for n, stem in stems.items()}
        print(f"{label}, window [{start:g}, {end:g}]: " +
              ", ".join(f"N_a {n} {m:.4f} +- {s:.4f}" for n, (m, s) in sorted(runs.items())))
        (e6, s6), (e8, s8) = runs[6], runs[8]
        g = 1.0 / ((8 / 6) ** order - 1.0)
        estimate = richardson(e8, e6, 8 / 6, order)
        for low in lows:
            spread = abs(estimate - richardson(e8, e6, 8 / 6, low)) / 2
            sd = math.sqrt((1 + g) ** 2 * s8 ** 2 + g ** 2 * s6 ** 2 + spread ** 2)
            print(f"  (6, 8) at order {order:g}, order_low {low:g}: {estimate:.4f} +- {sd:.4f}")
        coarse, fine = sorted(runs)[-2:]
        print(f"  finest pair ({coarse}, {fine}) at orders " + ", ".join(f"{p:g}" for p in FINEST_ORDERS) + ": " +
              ", ".join(f"{richardson(runs[fine][0], runs[coarse][0], fine / coarse, p):.4f}" for p in FINEST_ORDERS))


if __name__ == "__main__":
    main()
