#!/usr/bin/python3
"""How far a dense run's sem says what its value would be in another window: each committed
anchor and twin run's averaging window [15, 40] split in halves, the halves' difference against
what the run's sem implies for a stationary series (each half's sem is about sqrt(2) times the
whole window's, so the difference has sd about 2 sem). Prints each run and the RMS of
diff / (2 sem) per group; no rbcal needed.

Usage, from the repository root: /usr/bin/python3 studies/box-prior-from-anchors/window_halves.py
"""
import glob
import json
import os

import numpy as np

groups = {"16a anchors": "data/library/anchors/results/*.series.csv",
          "8a twins": "data/library/anchors/twins/results/*.series.csv"}
for group, pattern in groups.items():
    ratios, drifts = [], []
    for f in sorted(glob.glob(pattern)):
        d = np.genfromtxt(f, delimiter=",", names=True)
        strain, eta = d["strain"], d["eta_re_stresslet"]
        r = json.load(open(f.replace(".series.csv", ".result.json")))["result"]
        lo, hi = r.get("window", [15.0, 40.0]) if isinstance(r.get("window"), list) else (15.0, 40.0)
        mid = 0.5 * (lo + hi)
        first = eta[(strain >= lo) & (strain < mid)].mean()
        second = eta[(strain >= mid) & (strain <= hi)].mean()
        ratio = (second - first) / (2.0 * r["eta_re_sem"])
        ratios.append(ratio)
        drifts.append(np.log(second / first))
        print(f"{os.path.basename(f)[:-11]:40s} eta_re {r['eta_re']:.3f} +- {r['eta_re_sem']:.3f}  halves "
              f"{first:.3f} / {second:.3f}  diff / (2 sem) {ratio:+.1f}")
    rms = float(np.sqrt(np.mean(np.square(ratios))))
    beyond = sum(abs(x) > 3 for x in ratios)
    print(f"{group}: {len(ratios)} runs, RMS of diff / (2 sem) {rms:.2f}, {beyond} beyond 3; "
          f"RMS of ln(second / first) {np.sqrt(np.mean(np.square(drifts))):.3f}\n")
