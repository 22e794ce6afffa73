#!/usr/bin/env python3
"""eta_re over a strain window of a finished run's series.csv, with the same blocking
standard error as the solver (solver/simulation/detail/block_average.hpp: Flyvbjerg & Petersen
1989, the largest level that keeps at least 8 blocks).

    python3 scripts/window_average.py RUN/series.csv START END [COLUMN] [--blocks WIDTH]

COLUMN defaults to eta_re_stresslet. Used to compare averaging windows of one run
(studies/library-v2-development/README.md) without re-running it. With --blocks
WIDTH it also prints the
means of consecutive blocks of WIDTH strain units and the error from their scatter (sd of
the block means / sqrt(blocks)), which sees the slow excursions of dense runs that the
blocking error misses.
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
    args = list(sys.argv[1:])
    width = None
    if "--blocks" in args:
        i = args.index("--blocks")
        width = float(args[i + 1])
        del args[i:i + 2]
    if len(args) < 3:
        sys.exit(__doc__)
    path, start, end = args[0], float(args[1]), float(args[2])
    column = args[3] if len(args) > 3 else "eta_re_stresslet"
    with open(path) as f:
        rows = [r for r in csv.DictReader(f)]

    def window(a, b):
        return [float(r[column]) for r in rows if a - 1e-9 <= float(r["strain"]) <= b + 1e-9]

    values = window(start, end)
    if len(values) < 8:
        sys.exit(f"{path}: only {len(values)} rows in [{start}, {end}]")
    mean, sem, n = block_average(values)
    print(f"{path}: {column} over [{start:g}, {end:g}]: {mean:.5g} +- {sem:.2g} ({n} rows)")
    if width:
        means, a = [], start
        while a + width <= end + 1e-9:
            block = window(a, a + width)
            means.append(sum(block) / len(block))
            a += width
        if len(means) >= 2:
            m = sum(means) / len(means)
            sd = math.sqrt(sum((x - m) ** 2 for x in means) / (len(means) - 1))
            shown = ", ".join(f"{x:.4g}" for x in means)
            print(f"  blocks of {width:g}: {shown}; mean {m:.5g} +- {sd / math.sqrt(len(means)):.2g} (from their scatter)")


if __name__ == "__main__":
    main()
