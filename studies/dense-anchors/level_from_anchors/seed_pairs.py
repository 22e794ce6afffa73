#!/usr/bin/python3
"""The N_a 12 anchors' second seeds against their blind predictions.

For each second seed with a result in data/library/anchors/results/, against the predictions
written before it ran (blind_predictions_n12_seed2.csv, from seed_predictions.py):
  - d = ln(seed 2 / seed 1), and z_noise = d / sd, sd from both runs' sems and a seed noise
    of 0.018 per run (|z_noise| > 2 says the seeds differ by more than that noise);
  - z_model: seed 2 against the model's prediction and sd at the point.
Then the seed noise the pairs measure: rms(d) / sqrt(2), and the same less the runs' sems;
and, where a point has further seeds (_seed3, ...), the noise pooled over every point's seeds
(the sample variance of ln eta_re per point, weighted by its degrees of freedom).
  python3 studies/dense-anchors/level_from_anchors/seed_pairs.py \
      studies/dense-anchors/blind_predictions_n12_seed2.csv
"""
import csv
import glob
import json
import math
import os
import sys

ROOT = os.path.abspath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", ".."))
RESULTS = os.path.join(ROOT, "data", "library", "anchors", "results")
SEED_NOISE = 0.018


def result(name):
    path = os.path.join(RESULTS, name + ".result.json")
    if not os.path.exists(path):
        return None
    r = json.load(open(path))["result"]
    return r["eta_re"], r["eta_re_sem"]


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    lines = [line for line in open(sys.argv[1]) if not line.startswith("#")]
    print("case,eta_seed1,sem1,eta_seed2,sem2,d,z_noise,eta_model,z_model")
    d_all, sem_sq = [], []
    for row in csv.DictReader(lines):
        second = result(row["case"])
        if second is None:
            continue
        first = result(row["case"][: -len("_seed2")])
        (e1, s1), (e2, s2) = first, second
        d = math.log(e2 / e1)
        runs_sq = (s1 / e1) ** 2 + (s2 / e2) ** 2
        z_noise = d / math.sqrt(runs_sq + 2 * SEED_NOISE ** 2)
        z_model = (e2 - float(row["eta_model"])) / float(row["sd_model"])
        d_all.append(d)
        sem_sq.append(runs_sq)
        print(f"{row['case']},{e1:.4f},{s1:.4f},{e2:.4f},{s2:.4f},{d:+.4f},{z_noise:+.2f},"
              f"{float(row['eta_model']):.4f},{z_model:+.2f}")
    if d_all:
        ms = sum(d * d for d in d_all) / len(d_all)
        beyond = max(ms - sum(sem_sq) / len(sem_sq), 0.0)
        print(f"# {len(d_all)} pairs: seed noise per run rms(d)/sqrt(2) = {math.sqrt(ms / 2):.4f}; "
              f"less the runs' sems {math.sqrt(beyond / 2):.4f} (in ln eta_re)")
    pooled(lines)


def seeds_of(base):
    """The results of a point's first seed and of its _seedN runs."""
    names = [base] + [os.path.basename(f)[: -len(".result.json")]
                      for f in sorted(glob.glob(os.path.join(RESULTS, base + "_seed*.result.json")))]
    return [r for r in map(result, names) if r is not None]


def pooled(lines):
    """The seed noise pooled over all seeds of each point that has a second one."""
    squares, dof, sems = 0.0, 0, 0.0
    for row in csv.DictReader(lines):
        base = row["case"][: -len("_seed2")]
        runs = seeds_of(base)
        if len(runs) < 2:
            continue
        logs = [math.log(e) for e, _ in runs]
        mean = sum(logs) / len(logs)
        if len(runs) > 2:
            var = sum((x - mean) ** 2 for x in logs) / (len(logs) - 1)
            print(f"# {base}: {len(runs)} seeds " + ", ".join(f"{e:.4f}" for e, _ in runs) +
                  f"; geometric mean {math.exp(mean):.4f}, sd of ln {math.sqrt(var):.4f}")
        squares += sum((x - mean) ** 2 for x in logs)
        dof += len(logs) - 1
        sems += sum((s / e) ** 2 for e, s in runs) * (len(logs) - 1) / len(logs)
    if dof:
        print(f"# all seeds, {dof} degrees of freedom: seed noise per run {math.sqrt(squares / dof):.4f}; "
              f"less the runs' sems {math.sqrt(max(squares - sems, 0.0) / dof):.4f} (in ln eta_re)")


if __name__ == "__main__":
    main()
