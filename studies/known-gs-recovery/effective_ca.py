#!/usr/bin/python3
"""Where along Ca does the shipped model meet each dense anchor? For each anchor run (phi as
run, N_a, Ca, eta_re in the 16a gap) the model's member at offset C (default 0.75, the prior's
centre), moved to the 16a gap, is searched over ln Ca for the value the run measured. Ca* / Ca
above 1 says the model needs a larger Ca (a softer cell) than the run had, which a calibration
reads as a G_s lower than the truth by that factor. Runs below the model at every Ca of its
range are marked "below".

Usage (from the repository root): python3 studies/known-gs-recovery/effective_ca.py [C]
"""
import math
import os
import sys

c = float(sys.argv[1]) if len(sys.argv) > 1 else 0.75
sys.argv = sys.argv[:1]  # shipped_family reads its own optional argument (the rbcal to call)
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "dense-anchors"))
import shipped_family as sf  # noqa: E402
CA_MIN, CA_MAX = 0.01, 18.0

def model_at(phi_eff, ca, lam):
    return sf.member_in_gap(phi_eff, ca, lam, c)

print(f"| anchor | N_a | phi_eff (c {c}) | Ca | eta_re run | model at Ca | model at Ca 18 | Ca* | Ca* / Ca |")
print("|---|---|---|---|---|---|---|---|---|")
runs = sf.anchor_runs()
for point in sorted(runs):
    ca, lam = sf.point_parameters(point)
    for n_a in sorted(runs[point]):
        eta, sem, phi = runs[point][n_a]
        phi_eff = sf.g(c, n_a) * phi
        at_ca, at_max = model_at(phi_eff, ca, lam), model_at(phi_eff, CA_MAX, lam)
        lo, hi = math.log(CA_MIN), math.log(CA_MAX)
        f = lambda x: model_at(phi_eff, math.exp(x), lam) - eta
        if f(hi) > 0:
            star, ratio = "below", "-"
        elif f(lo) < 0:
            star, ratio = "above", "-"
        else:
            for _ in range(22):  # the model thins with Ca: bisect in ln Ca
                mid = 0.5 * (lo + hi)
                if f(mid) > 0: lo = mid
                else: hi = mid
            s = math.exp(0.5 * (lo + hi))
            star, ratio = f"{s:.3g}", f"{s / ca:.2f}"
        print(f"| {point} | {n_a} | {phi_eff:.3f} | {ca:g} | {eta:.3f} | {at_ca:.3f} | {at_max:.3f} | {star} | {ratio} |")
