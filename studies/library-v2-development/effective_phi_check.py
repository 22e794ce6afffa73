#!/usr/bin/env python3
"""Evidence for the effective volume fraction (docs/library.md, "The effective volume
fraction"; issue 16, item 2), for each offset c in lattice spacings:

    python3 studies/library-v2-development/effective_phi_check.py [--offsets 0,0.6,0.75,0.9,1.05] [--rbcal build/bin/rbcal]

1. Each tier of library v2 (data/library/v2/n6, n8) is moved to its effective volume
   fractions alone (`rbcal library effective-phi`) and its surrogate predicts the other
   tier's moved runs that lie inside its range: mean and RMS of ln(run / prediction) and
   the RMS standardised residual. c = 0 is the runs as they are. With the right c the two
   resolutions lie on one surface (mean near 0, z-RMS near 1).
2. Both tiers together give the continuum surrogate; it predicts the finer runs of item 1
   (N_a 10 and 12, data/cases/resolution_v2/results, not in the library) at phi g(N_a).
3. That surrogate's leave-one-out errors and its value at phi 0.41, Ca 0.8, lambda 5.
"""
import json
import math
import os
import re
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from convergence_order import window_mean  # noqa: E402

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
TIERS = {"n6": os.path.join(ROOT, "data/library/v2/n6"), "n8": os.path.join(ROOT, "data/library/v2/n8")}
RESULTS = os.path.join(ROOT, "data/cases/resolution_v2/results")
# Finer runs of item 1 (phi, Ca, lambda, window, {N_a: series stem}); C 10 like the library.
FINER = [
    (0.05, 3.2, 0.1, (4, 10), {10: "phi0.05_Ca3.2_lambda0.1_n10_c10", 12: "phi0.05_Ca3.2_lambda0.1_n12_c10"}),
    (0.21, 0.2, 5.0, (15, 40), {10: "phi0.21_Ca0.2_n10"}),
    (0.41, 0.8, 5.0, (15, 40), {10: "phi0.41_Ca0.8_n10_h8"}),
]


def run(args):
    return subprocess.run(args, capture_output=True, text=True, check=True).stdout


def effective_phi(rbcal, tiers, out, offset):
    # As the default library is built (offset sd 0.15); at offset 0, the runs as they are, none.
    text = run([rbcal, "library", "effective-phi", *tiers, "-o", out, "--offset", str(offset),
                "--offset-sd", "0.15" if offset > 0 else "0", "--scatter-floor", "0.054", "--scatter-phi", "0.05,0.41"])
    m = re.search(r"area ([0-9.]+), volume ([0-9.]+), mean-curvature integral ([0-9.]+)", text)
    area, volume, curvature = (float(x) for x in m.groups())
    run([rbcal, "surrogate", "build", out])
    return lambda n: 1 + (area * offset / n + curvature * (offset / n) ** 2 + 4 * math.pi / 3 * (offset / n) ** 3) / volume


def predict(rbcal, surrogate, phi, ca, lam):
    text = run([rbcal, "surrogate", "predict", surrogate, "--phi", str(phi), "--ca", str(ca), "--lambda", str(lam)])
    m = re.search(r"eta_re\s+([0-9.eE+-]+) \+- ([0-9.eE+-]+)", text)
    return float(m.group(1)), float(m.group(2))


def mapped_cases(folder):
    out = []
    for name in sorted(os.listdir(os.path.join(folder, "cases"))):
        if name.endswith(".json"):
            j = json.load(open(os.path.join(folder, "cases", name)))
            out.append((j["result"]["phi_actual"], j["params"]["Ca"], j["params"]["lambda"],
                        j["result"]["eta_re"], j["result"]["eta_re_sem"]))
    return out


def main():
    args = sys.argv[1:]
    offsets, rbcal = [0.0, 0.6, 0.75, 0.9, 1.05], os.path.join(ROOT, "build/bin/rbcal")
    while args:
        flag, value = args.pop(0), args.pop(0)
        if flag == "--offsets":
            offsets = [float(x) for x in value.split(",")]
        elif flag == "--rbcal":
            rbcal = value
        else:
            sys.exit(__doc__)
    with tempfile.TemporaryDirectory() as tmp:
        for c in offsets:
            print(f"offset {c:g} lattice spacings")
            lib = {}
            for name, folder in TIERS.items():
                lib[name] = os.path.join(tmp, f"{name}_{c}")
                effective_phi(rbcal, [folder], lib[name], c)
            for target, source in (("n6", "n8"), ("n8", "n6")):
                cases = mapped_cases(lib[source])
                lo, hi = min(x[0] for x in cases), max(x[0] for x in cases)
                logs, zs = [], []
                for phi, ca, lam, eta, sd in mapped_cases(lib[target]):
                    if lo <= phi <= hi:
                        m, s = predict(rbcal, os.path.join(lib[source], "surrogate.json"), phi, ca, lam)
                        logs.append(math.log(eta / m))
                        zs.append((eta - m) / math.hypot(s, sd))
                if logs:
                    print(f"  {target} from {source}'s surrogate: {len(logs)} runs, mean ln(run / prediction) "
                          f"{sum(logs) / len(logs):+.3f}, RMS {math.sqrt(sum(x * x for x in logs) / len(logs)):.3f}, "
                          f"z-RMS {math.sqrt(sum(z * z for z in zs) / len(zs)):.2f}")
            if c == 0.0:
                continue  # as run, the two tiers share their design points: no joint library
            both = os.path.join(tmp, f"both_{c}")
            g = effective_phi(rbcal, list(TIERS.values()), both, c)
            surrogate = os.path.join(both, "surrogate.json")
            for phi, ca, lam, (start, end), stems in FINER:
                for n, stem in sorted(stems.items()):
                    mean, sem = window_mean(os.path.join(RESULTS, stem + ".series.csv"), start, end)
                    # The surrogate's input is g phi_actual (the volume fraction the run seeded).
                    with open(os.path.join(RESULTS, stem + ".result.json")) as f:
                        phi_actual = json.load(f)["result"]["phi_actual"]
                    m, s = predict(rbcal, surrogate, phi_actual * g(n), ca, lam)
                    print(f"  finer run phi {phi:g}, Ca {ca:g}, lambda {lam:g}, N_a {n} [{start:g}, {end:g}]: "
                          f"{mean:.4f} +- {sem:.4f}; predicted at phi_eff {phi_actual * g(n):.3f}: {m:.4f} +- {s:.4f}")
            loo = run([rbcal, "surrogate", "build", both]).strip().splitlines()[-1].strip()
            m, s = predict(rbcal, surrogate, 0.41, 0.8, 5.0)
            print(f"  both tiers: {loo}\n  phi 0.41, Ca 0.8, lambda 5: {m:.3f} +- {s:.3f}")


if __name__ == "__main__":
    main()
