#!/usr/bin/env python3
"""eta_re over a strain window of a finished run's series.csv, with the same blocking
standard error as the solver (solver/simulation/block_average.hpp: Flyvbjerg & Petersen
1989, the largest level that keeps at least 8 blocks).

    python3 scripts/window_average.py RUN/series.csv START END [COLUMN]

COLUMN defaults to eta_re_stresslet. Used to compare averaging windows of one run
(docs/library.md, issue 16) without re-running it.
"""
import csv
import math
import sys


def block_average(values):
    n0 = len(values)
    mean = sum(values) / n0
    level, best = list(values), 0.0
    while len(level) >= 8:
        n = len(level)
        var = sum((v - mean) ** 2 for v in level)
        best = max(best, math.sqrt(var / (n * (n - 1.0))))
        level = [0.5 * (level[2 * i] + level[2 * i + 1]) for i in range(n // 2)]
    return mean, best, n0


def main():
    if len(sys.argv) < 4:
        sys.exit(__doc__)
    path, start, end = sys.argv[1], float(sys.argv[2]), float(sys.argv[3])
    column = sys.argv[4] if len(sys.argv) > 4 else "eta_re_stresslet"
    with open(path) as f:
        rows = [r for r in csv.DictReader(f)]
    values = [float(r[column]) for r in rows if start - 1e-9 <= float(r["strain"]) <= end + 1e-9]
    if len(values) < 8:
        sys.exit(f"{path}: only {len(values)} rows in [{start}, {end}]")
    mean, sem, n = block_average(values)
    print(f"{path}: {column} over [{start:g}, {end:g}]: {mean:.5g} +- {sem:.2g} ({n} rows)")


if __name__ == "__main__":
    main()
