#!/usr/bin/env python3
"""Critical lattice stiffness of the explicit membrane coupling, per kernel and coupling
interval (issue 14, item 3).

For each (kernel, coupling interval) the script bisects, in log space, the largest
Reynolds number at which a case runs STEPS lattice steps without the node Mach guard
stopping it. At fixed Ca the membrane moduli in lattice units grow in proportion to Re
(G_s,lu = Re nu^2 / (a Ca)), so the critical Re gives the critical area modulus
K_s,lu = G_s,lu (1 + 2 C) of the Skalak law. The prediction it checks: the explicit
update is stable while K_s,lu x k x (sum_j phi_j^2)^3 stays below one bound, the same
for every kernel (docs/performance.md, "Why the narrower kernels blow up").

Usage: kernel_stability.py CASE.json WORKDIR [--steps N] [--rbcal PATH]
                           [--config KERNEL:K:LOW:HIGH ...] [--iterations N]
Each config's LOW must run stably and HIGH must blow up; both are checked first.
Output: one markdown table on stdout, run logs in WORKDIR.
"""
import argparse
import json
import math
import os
import re
import subprocess
import sys

# Largest per-step self-mobility (sum_j phi_j^2)^3 over node positions:
# Peskin 4-point 3/8 for every r (Peskin 2002, eq. 6.25), Roma 3-point 1/2 for every r
# (Roma et al. 1999), the linear hat (1-t)^2 + t^2, largest (1) on a lattice node.
SELF_MOBILITY = {"peskin4": (3 / 8) ** 3, "roma3": (1 / 2) ** 3, "linear2": 1.0}


def lattice_moduli(case, reynolds):
    """G_s and the Skalak area modulus K_s in lattice units at this Re."""
    n = case["numerics"]
    a = n["N_a"]
    nu = (n.get("tau_out", 1.0) - 0.5) / 3.0
    g = reynolds * nu * nu / (a * case["params"]["Ca"])
    cells = case["cells"]
    # The C the membrane runs with (SimulationCase::effective_skalak_c: the area rule).
    c = max(cells.get("skalak_c", 100.0), cells.get("skalak_c_per_Ca", 0.0) * case["params"]["Ca"])  # solver default 100
    return g, g * (1.0 + 2.0 * c)


def runs_stably(case, kernel, interval, reynolds, steps, workdir, rbcal):
    """Runs the case for STEPS steps (or reads the log of an earlier run); returns
    (stable, the step it stopped at or None)."""
    name = f"{kernel}_k{interval}_Re{reynolds:.6g}_steps{steps}"
    log = os.path.join(workdir, name + ".log")
    if not os.path.exists(log):
        c = json.loads(json.dumps(case))
        c["numerics"].update({"kernel": kernel, "coupling_interval": interval, "Re": reynolds})
        path = os.path.join(workdir, name + ".json")
        with open(path, "w") as f:
            json.dump(c, f)
        out = os.path.join(workdir, name + ".out")
        p = subprocess.run([rbcal, "simulate", path, "-o", out, "-q", "--max-steps", str(steps)],
                           capture_output=True, text=True)
        with open(log + ".part", "w") as f:
            f.write(f"status {p.returncode}\n" + p.stdout + p.stderr)
        os.replace(log + ".part", log)
    with open(log) as f:
        text = f.read()
    if text.startswith("status 0\n"):
        return True, None
    if "Mach number" not in text and "blown up" not in text:
        sys.exit(f"{name}: failed for another reason:\n{text}")
    m = re.search(r"at step (\d+)", text)
    return False, int(m.group(1)) if m else None


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("case")
    ap.add_argument("workdir")
    ap.add_argument("--steps", type=int, default=2000)
    ap.add_argument("--iterations", type=int, default=5)
    ap.add_argument("--rbcal", default=os.path.join(os.path.dirname(__file__), "..", "..", "build", "bin", "rbcal"))
    ap.add_argument("--config", action="append", required=True, help="KERNEL:K:LOW_RE:HIGH_RE")
    args = ap.parse_args()
    with open(args.case) as f:
        case = json.load(f)
    os.makedirs(args.workdir, exist_ok=True)
    rows = []
    for spec in args.config:
        kernel, k, lo, hi = spec.split(":")
        k, lo, hi = int(k), float(lo), float(hi)
        ok_lo, _ = runs_stably(case, kernel, k, lo, args.steps, args.workdir, args.rbcal)
        ok_hi, step_hi = runs_stably(case, kernel, k, hi, args.steps, args.workdir, args.rbcal)
        if not ok_lo or ok_hi:
            sys.exit(f"{spec}: the bracket does not hold (low stable: {ok_lo}, high stable: {ok_hi})")
        for _ in range(args.iterations):
            mid = math.sqrt(lo * hi)
            ok, step = runs_stably(case, kernel, k, mid, args.steps, args.workdir, args.rbcal)
            if ok:
                lo = mid
            else:
                hi, step_hi = mid, step
            print(f"  {kernel} k {k}: Re {mid:.5g} {'stable' if ok else f'blew up at step {step}'}",
                  file=sys.stderr, flush=True)
        _, k_lo = lattice_moduli(case, lo)
        _, k_hi = lattice_moduli(case, hi)
        m = SELF_MOBILITY[kernel]
        rows.append((kernel, k, lo, hi, step_hi, k_lo, k_hi, m, k_lo * k * m, k_hi * k * m))
    print(f"Case {args.case}, {args.steps} steps per run, {args.iterations} bisections\n")
    print("| kernel | k | stable Re | unstable Re (step) | K_s,lu stable / unstable | (sum phi^2)^3 | K_s k (sum phi^2)^3 stable / unstable |")
    print("|---|---|---|---|---|---|---|")
    for kernel, k, lo, hi, step, klo, khi, m, blo, bhi in rows:
        print(f"| {kernel} | {k} | {lo:.4g} | {hi:.4g} ({step}) | {klo:.3g} / {khi:.3g} | {m:.4g} | {blo:.3g} / {bhi:.3g} |")


if __name__ == "__main__":
    main()
