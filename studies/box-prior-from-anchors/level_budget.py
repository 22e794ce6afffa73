#!/usr/bin/python3
"""What the shipped model's level is known to, part by part, from the committed runs.

Reads the table that `model_at_anchors.py` prints (each anchor against the shipped family in
the 16a gap) and the committed seeds and gap twins, and prints, in ln eta_re:

1. the runs' own noise: pairs of seeds of one point in the 16a gap;
2. the anchors' scatter about the model per tier, and what is left of it once that noise is
   taken out (the model's point-to-point error);
3. the mean level per tier and its standard error (the level at N_a 12 as a whole);
4. the step from N_a 12 to 16 at the points run at both, against the model;
5. the step from the 16a gap to the 32a gap at the points run in both.

Usage, from the repository root:
  python3 studies/dense-anchors/box_at_high_ca/model_at_anchors.py \
      data/library/default/surrogate_family.json STEP > AT.txt
  python3 studies/box-prior-from-anchors/level_budget.py AT.txt
(STEP: the anchors' mean beta from data/library/default/build_report.txt, as docs/ quote.)
"""
import glob
import json
import math
import os
import re
import sys

ANCHORS = "data/library/anchors/results"
GAP32 = "studies/dense-anchors/box_at_high_ca/results"


def eta(path):
    r = json.load(open(path))["result"]
    return r["eta_re"], r["eta_re_sem"]


def rms(values):
    return math.sqrt(sum(v * v for v in values) / len(values)) if values else float("nan")


def mean(values):
    return sum(values) / len(values)


# 1. Seeds in the 16a gap: each pair's ln ratio; one run's sd is |ln ratio| / sqrt(2). Points
# with further seeds (_seed3, ...) enter the pooled sd with all their seeds.
pairs, squares, dof = [], 0.0, 0
for seed in sorted(glob.glob(f"{ANCHORS}/*_seed2.result.json")):
    first = seed.replace("_seed2", "")
    if os.path.exists(first):
        (a, _), (b, _) = eta(first), eta(seed)
        pairs.append((os.path.basename(first).split(".result")[0], math.log(b / a)))
        logs = [math.log(eta(f)[0]) for f in [first] + sorted(glob.glob(first.replace(".result.json", "_seed*.result.json")))]
        squares += sum((x - mean(logs)) ** 2 for x in logs)
        dof += len(logs) - 1
print("## 1. Seeds of one point in the 16a gap")
for name, d in pairs:
    print(f"  {name}: ln(seed 2 / seed 1) {d:+.4f}")
noise = math.sqrt(squares / dof)
print(f"  one run's noise (RMS of the differences / sqrt 2): {rms([d for _, d in pairs]) / math.sqrt(2.0):.4f} over"
      f" {len(pairs)} pairs; over all seeds of those points ({dof} degrees of freedom): {noise:.4f}")
sems = [r["eta_re_sem"] / r["eta_re"] for r in
        (json.load(open(f))["result"] for f in glob.glob(f"{ANCHORS}/n*_lambda5.result.json"))]
noise_halves = 2.0 * rms(sems)
print(f"  or from the runs' sems, doubled as the window-halves test asks (window_halves.py): {noise_halves:.4f}"
      f" (RMS relative sem {rms(sems):.4f} over {len(sems)} anchors)")

# 2.-3. The anchors against the model, per tier (lambda 5 only).
rows = {}
for line in open(sys.argv[1]):
    m = re.match(r"\| n(\d+)_(phieff[\d.]+_Ca[\d.]+_lambda5) \| ([\d.]+) \| ([\d.]+) ", line)
    if m:
        rows.setdefault(int(m.group(1)), {})[m.group(2)] = math.log(float(m.group(3)) / float(m.group(4)))
print("\n## 2.-3. The anchors (lambda 5) against the model in the 16a gap, ln(run / model)")
for n_a, by in sorted(rows.items()):
    v = list(by.values())
    scatter = rms([x - mean(v) for x in v])
    apart = [math.sqrt(max(0.0, scatter ** 2 - n ** 2)) for n in (noise, noise_halves)]
    print(f"  N_a {n_a}: {len(v)} anchors, mean {mean(v):+.4f} +- {scatter / math.sqrt(len(v)):.4f} (standard error),"
          f" scatter {scatter:.4f}, of which not the runs' noise {apart[0]:.4f} (seeds) or {apart[1]:.4f} (halves)")

# 4. N_a 12 -> 16 at the same point, against the model.
print("\n## 4. From N_a 12 to 16 at the same point, against the model")
steps = [rows[16][p] - rows[12][p] for p in sorted(rows.get(16, {})) if p in rows.get(12, {})]
for p in sorted(rows.get(16, {})):
    if p in rows.get(12, {}):
        print(f"  {p}: {rows[16][p] - rows[12][p]:+.4f}")
if steps:
    print(f"  mean {mean(steps):+.4f} over {len(steps)} points")

# 5. 16a -> 32a gap at the same point (N_a 8).
print("\n## 5. From the 16a gap to the 32a gap (N_a 8, same point)")
gap = []
for path in sorted(glob.glob(f"{GAP32}/*_h32.result.json")):
    point = os.path.basename(path).replace("_h32.result.json", "")
    base = f"{ANCHORS}/{point}.result.json"
    if os.path.exists(base):
        # Against the 16a seeds' geometric mean where the point has several.
        seeds = [base] + sorted(glob.glob(f"{ANCHORS}/{point}_seed*.result.json"))
        a = math.exp(mean([math.log(eta(f)[0]) for f in seeds]))
        b, sb = eta(path)
        step = math.log(b / a)
        gap.append(step)
        runs = " / ".join(f"{eta(f)[0]:.3f}" for f in seeds)
        print(f"  {point}: 16a {runs} ({len(seeds)} seeds), 32a {b:.3f} +- {sb:.3f}, ln step {step:+.4f}")
if gap:
    print(f"  mean {mean(gap):+.4f}, RMS {rms(gap):.4f} over {len(gap)} points")
