#!/usr/bin/python3
"""The anchors' windows, late half against early half, as `rbcal simulate` now reports it
(result.eta_re_drift and eta_re_drift_sd: solver/simulation/window_drift.hpp), computed here
from the committed series of the runs that predate the field.
  python3 studies/dense-anchors/level_from_anchors/window_drift.py [GLOB]
(default: every anchor at lambda 5 in data/library/anchors/results/). Prints per run the
drift in ln eta_re, its sd (twice the window's relative blocking error), z, and the
[30, 40] / [15, 25] block ratio; then the rms drift and the noise it implies for one
window's mean if the runs were stationary (rms drift / 2).
"""
import csv
import glob
import math
import os
import sys

ROOT = os.path.abspath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", ".."))
WINDOW = (15.0, 40.0)


def blocking_sem(x):
    """The largest naive standard error over the blocking levels that keep 8 blocks or more."""
    mean = sum(x) / len(x)
    best, level = 0.0, list(x)
    while len(level) >= 8:
        n = len(level)
        var = sum((v - mean) ** 2 for v in level)
        best = max(best, math.sqrt(var / (n * (n - 1))))
        level = [(level[2 * i] + level[2 * i + 1]) / 2 for i in range(n // 2)]
    return best


def main():
    pattern = sys.argv[1] if len(sys.argv) > 1 else os.path.join(
        ROOT, "data", "library", "anchors", "results", "n*_lambda5*.series.csv")
    print("run,eta_re,drift,sd,z,late_over_early_blocks")
    drifts = []
    for path in sorted(glob.glob(pattern)):
        rows = list(csv.DictReader(open(path)))
        strain = [float(r["strain"]) for r in rows]
        eta = [float(r["eta_re_stresslet"]) for r, s in zip(rows, strain)
               if WINDOW[0] - 1e-9 <= s <= WINDOW[1] + 1e-9]
        half = len(eta) // 2
        early, late = sum(eta[:half]) / half, sum(eta[-half:]) / half
        mean = sum(eta) / len(eta)
        drift, sd = math.log(late / early), 2 * blocking_sem(eta) / mean
        block = lambda lo, hi: [float(r["eta_re_stresslet"]) for r, s in zip(rows, strain) if lo < s <= hi]
        b15, b30 = block(15, 25), block(30, 40)
        ratio = (sum(b30) / len(b30)) / (sum(b15) / len(b15))
        drifts.append(drift)
        name = os.path.basename(path)[: -len(".series.csv")]
        print(f"{name},{mean:.4f},{drift:+.4f},{sd:.4f},{drift / sd:+.1f},{ratio:.3f}")
    rms = math.sqrt(sum(d * d for d in drifts) / len(drifts))
    print(f"# {len(drifts)} runs: rms drift {rms:.4f}; if stationary, one window's mean would carry "
          f"about {rms / 2:.4f} in ln eta_re")


if __name__ == "__main__":
    main()
