#!/usr/bin/env python3
"""Writes synthetic_rheometer.csv: SYNTHETIC rheometer curves for the `rbcal calibrate` tests.

Not measurements. Two samples drawn from the analytic law that also made the tiny test
library (tests/surrogate/data/tiny_library): ln eta_re = phi (2.5 - 0.4 ln Ca), lambda = 5,
Ca = eta0 gamma_dot a / G_s with eta0 = 1.569 mPa s, a = 4 um; intact G_s = 0.5 uN/m,
hardened G_s = 1.0 uN/m. Each row is a mean of n = 3 repeats with a 2 % sd; the means
scatter by 2 % / sqrt(3) (plasma: 1 %). Some shear rates give Ca outside the library's
0.05 .. 0.5 on purpose (the command must warn). Re-run to regenerate: python3 make_synthetic_rheometer.py
"""
import math
import random

ETA0 = 1.569  # mPa s
A = 4e-6      # m
rng = random.Random(7)
lines = [
    "# SYNTHETIC data for tests, not measurements: ln eta_re = phi (2.5 - 0.4 ln Ca), lambda 5,",
    "# eta0 1.569 mPa s, a 4 um, intact G_s 0.5 uN/m, hardened G_s 1.0 uN/m, 2 % sd, n 3;",
    "# written by tests/calibration/data/make_synthetic_rheometer.py (seed 7)",
    "sample,kind,phi,shear_rate_per_s,viscosity_mPa_s,sd_mPa_s,n",
]
for name, gs in (("intact", 0.5e-6), ("hardened", 1.0e-6)):
    for rate in (1.0, 10.0, 31.6, 100.0, 316.0):
        eta = ETA0 * (1.0 + 0.01 * rng.gauss(0.0, 1.0))
        lines.append(f"{name},plasma,0,{rate:g},{eta:.5f},{0.02 * ETA0:.5f},3")
    for phi in (0.1, 0.2, 0.3, 0.4):
        for rate in (5.0, 8.0, 12.6, 20.0, 32.0, 50.0):
            ca = ETA0 * 1e-3 * rate * A / gs
            eta_re = math.exp(phi * (2.5 - 0.4 * math.log(ca)))
            eta = ETA0 * eta_re * (1.0 + 0.02 / math.sqrt(3.0) * rng.gauss(0.0, 1.0))
            lines.append(f"{name},suspension,{phi:g},{rate:g},{eta:.5f},{0.02 * eta:.5f},3")
with open("synthetic_rheometer.csv", "w") as f:
    f.write("\n".join(lines) + "\n")
