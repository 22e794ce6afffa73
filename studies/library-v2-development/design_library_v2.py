#!/usr/bin/env python3
"""Case files of the v2 library design (issue 16): a space-filling design over
phi in [0.05, 0.55], Ca in [0.01, 3.2] (log), lambda in [0.1, 10] (log): the 8 corners of
the box plus a maximin Latin hypercube of 52 points, 60 in all, each at N_a 6; a
maximin subset of 20 of them (corners included) also at N_a 8, for the resolution
extrapolation. Deterministic: rerunning writes the same files.

Numerics (docs/library.md, "The runs' numerics, and why"): Evans-Fung cells of 1280 elements, Skalak C 10,
kb_hat 0.0078, box 6a x 8a x 6a, tau_out 1, Euler, indicator tolerance 0.1, coupling
interval 2 (shown equivalent to 1 on two dense cases), gamma_dot t to 40 with the window
[15, 40]. Re 0.2, lowered where G_s in lattice units times the coupling interval would
exceed 0.05 min(1, (1 + lambda) / 2) (the stability cap of the v1 library,
studies/library-history/README.md, "Time-step limit").

The gap tier (n8_h16, from 2026-11-24): every point at phi >=
ROUND2_PHI again at N_a 8 in a 16a gap (box 6a x 16a x 6a), where the 8a box's layers
do not set eta_re (studies/library-v2-development/README.md, "Dense states in the 8a box
are layered"), with the
membrane moved by the interval's mean velocity (numerics.node_velocity, docs/performance.md).

Usage: python3 studies/library-v2-development/design_library_v2.py [OUT_DIR]   (default data/cases/library_v2)
writes OUT_DIR/design.csv, OUT_DIR/n6/ID.json, OUT_DIR/n8/ID.json and
OUT_DIR/n8_h16/ID.json, and the same design as sweep plans OUT_DIR/plan_n6.json,
plan_n8.json and plan_n8_h16.json (listed points) for `rbcal library generate` on a
larger machine. The plans cap Re exactly (max_shear_modulus_lattice 0.025
= 0.05 / coupling interval); the case files carry Re rounded to 4 digits (a relative
difference below 5e-4).
"""
import json
import math
import os
import random
import sys

PHI = (0.05, 0.55)
LOG_CA = (math.log10(0.01), math.log10(3.2))
LOG_LAMBDA = (-1.0, 1.0)
LHS_POINTS, SUBSET, RESTARTS, SEED = 52, 20, 3000, 20261123
# Round 2 of the N_a 8 tier (from 2026-11-24): every design point at
# phi >= ROUND2_PHI. With only the maximin subset at N_a 8, the correction model carried the
# large dense low-Ca drops of phi 0.55 down to phi 0.41 and flattened the shear thinning
# there (studies/library-v2-development/README.md, "Dense, low Ca to strain 40"); paired
# dense points leave the model
# only the semi-dilute range, where corrections are small. Run nearest phi 0.41 first.
ROUND2_PHI = 0.38
COUPLING_INTERVAL, CAP, RE = 2, 0.05, 0.2


def sig3(x):
    return float(f"{x:.3g}")


def unit_to_params(u):
    phi = PHI[0] + u[0] * (PHI[1] - PHI[0])
    ca = 10 ** (LOG_CA[0] + u[1] * (LOG_CA[1] - LOG_CA[0]))
    lam = 10 ** (LOG_LAMBDA[0] + u[2] * (LOG_LAMBDA[1] - LOG_LAMBDA[0]))
    return sig3(phi), sig3(ca), sig3(lam)


def min_distance(points, fixed=()):
    everything = list(fixed) + list(points)
    best = float("inf")
    for i in range(len(everything)):
        for j in range(max(i + 1, len(fixed)), len(everything)):
            d = sum((a - b) ** 2 for a, b in zip(everything[i], everything[j]))
            best = min(best, d)
    return math.sqrt(best)


def maximin_lhs(n, fixed, rng):
    best, best_d = None, -1.0
    for _ in range(RESTARTS):
        columns = []
        for _dim in range(3):
            strata = list(range(n))
            rng.shuffle(strata)
            columns.append([(s + rng.random()) / n for s in strata])
        points = list(zip(*columns))
        d = min_distance(points, fixed)
        if d > best_d:
            best, best_d = points, d
    return best


def greedy_subset(points, k, start):
    """Maximin subset: start with the given indices, add the point farthest from the chosen."""
    chosen = list(start)
    while len(chosen) < k:
        far = max((i for i in range(len(points)) if i not in chosen),
                  key=lambda i: min(sum((a - b) ** 2 for a, b in zip(points[i], points[c])) for c in chosen))
        chosen.append(far)
    return chosen


def case_file(phi, ca, lam, n_a, gap=8.0):
    nu = (1.0 - 0.5) / 3.0
    modulus = RE * nu * nu / (n_a * ca)  # G_s in lattice units at Re 0.2
    cap = CAP * min(1.0, 0.5 * (1.0 + lam)) / COUPLING_INTERVAL
    re = RE if modulus <= cap else float(f"{RE * cap / modulus:.4g}")
    case = {
        "schema": "rbcal.case/1",
        "params": {"phi": phi, "Ca": ca, "lambda": lam, "kb_hat": 0.0078},
        "cells": {"shape": "biconcave", "profile": "evans-fung", "triangles": 1280, "law": "skalak", "skalak_c": 10.0},
        "numerics": {"N_a": n_a, "tau_out": 1.0, "box": [6.0, gap, 6.0], "Re": re, "kernel": "peskin4",
                     "integrator": "euler", "indicator_tolerance": 0.1, "coupling_interval": COUPLING_INTERVAL,
                     "seed": 1},
        "run": {"strain_end": 40.0, "window": [15.0, 40.0], "record_interval": 0.05, "checkpoint_interval": 1.0},
    }
    if gap != 8.0:  # the gap tier, run after the interval mean existed
        case["numerics"]["node_velocity"] = "interval_mean"
    return case


# Tiers: folder, N_a, gap in a.
TIERS = (("n6", 6, 8.0), ("n8", 8, 8.0), ("n8_h16", 8, 16.0))


def case_id(phi, ca, lam):
    return f"phi{phi:g}_Ca{ca:g}_lambda{lam:g}"


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..", "..", "data", "cases", "library_v2")
    rng = random.Random(SEED)
    corners = [(a, b, c) for a in (0.0, 1.0) for b in (0.0, 1.0) for c in (0.0, 1.0)]
    lhs = maximin_lhs(LHS_POINTS, corners, rng)
    unit = corners + lhs
    subset = set(greedy_subset(unit, SUBSET, range(len(corners))))
    dense = {i for i in range(len(unit)) if unit_to_params(unit[i])[0] >= ROUND2_PHI}
    round2 = dense - subset
    # Run order: the N_a 8 subset first (the extrapolation needs both tiers), then the rest,
    # each in maximin order so that an unfinished library is still spread out.
    order = greedy_subset(unit, len(unit), [0])
    order = [i for i in order if i in subset] + [i for i in order if i not in subset]
    chosen_of = {"n6": order, "n8": [i for i in order if i in subset | round2],
                 # nearest phi 0.41 first (the acceptance point's neighbourhood)
                 "n8_h16": sorted((i for i in order if i in dense), key=lambda i: abs(unit_to_params(unit[i])[0] - 0.41))}
    for tier, _, _ in TIERS:
        os.makedirs(os.path.join(out, tier), exist_ok=True)
    with open(os.path.join(out, "design.csv"), "w") as design:
        design.write("# v2 library design (studies/library-v2-development/design_library_v2.py): run order, parameters, N_a 8 tier"
                     " (1: the maximin subset, 2: round 2, phi >= ROUND2_PHI)\n")
        design.write("order,phi,Ca,lambda,at_n8\n")
        for rank, i in enumerate(order):
            phi, ca, lam = unit_to_params(unit[i])
            design.write(f"{rank},{phi:g},{ca:g},{lam:g},{int(i in subset) + 2 * int(i in round2)}\n")
            for tier, n_a, gap in TIERS:
                if i not in chosen_of[tier]:
                    continue
                with open(os.path.join(out, tier, case_id(phi, ca, lam) + ".json"), "w") as f:
                    json.dump(case_file(phi, ca, lam, n_a, gap), f, indent=1)
                    f.write("\n")
    for tier, n_a, gap in TIERS:
        chosen = chosen_of[tier]
        base = case_file(0.1, 1.0, 1.0, n_a, gap)
        del base["params"]["phi"], base["params"]["Ca"], base["params"]["lambda"]
        base["numerics"]["Re"] = RE
        del base["schema"]
        plan = {"schema": "rbcal.plan/1",
                "description": f"Library v2 at N_a {n_a}{'' if gap == 8.0 else f' in a {gap:g}a gap'} (issue 16):"
                               " studies/library-v2-development/design_library_v2.py, docs/library.md",
                "points": [list(unit_to_params(unit[i])) for i in chosen],
                "max_shear_modulus_lattice": CAP / COUPLING_INTERVAL,
                "base": base}
        with open(os.path.join(out, f"plan_{tier}.json"), "w") as f:
            json.dump(plan, f, indent=1)
            f.write("\n")
    print(f"{len(unit)} points, {len(subset)} also at N_a 8 (+ {len(round2)} in round 2),"
          f" {len(dense)} in the 16a gap at N_a 8, in {out}")


if __name__ == "__main__":
    main()
