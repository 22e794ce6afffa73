#!/usr/bin/env python3
"""Reads a report folder's SAMPLE_posterior.nc files (NetCDF-4, as ArviZ's InferenceData
writes them) with netCDF4 and checks them against chains.csv: the four groups, their
dimensions and variables, each value of chains.csv found again at (chain, step, walker),
finite point-wise log-likelihoods over the sample's points; and each group opened by xarray
(Debian's python3-xarray) as ArviZ's from_netcdf opens it, with its dimensions and coordinates.
Usage: posterior_netcdf_check.py REPORT_FOLDER"""
import csv
import glob
import math
import os
import sys

import netCDF4
import xarray

folder = sys.argv[1]
files = sorted(glob.glob(os.path.join(folder, "*_posterior.nc")))
if not files:
    sys.exit(f"FAIL: no *_posterior.nc in {folder}")
rows = {}
with open(os.path.join(folder, "chains.csv")) as f:
    for r in csv.DictReader(f):
        rows[(r["sample"], int(r["chain"]), int(r["step"]), int(r["walker"]))] = r


def close(a, b, rel=1e-6):
    return abs(a - b) <= rel * max(abs(a), abs(b), 1e-300)


checked = 0
for path in files:
    d = netCDF4.Dataset(path)
    sample = d.getncattr("sample")
    walkers = int(d.getncattr("walkers_per_chain"))
    groups = set(d.groups)
    if groups != {"posterior", "sample_stats", "log_likelihood", "observed_data"}:
        sys.exit(f"FAIL: {path}: groups {sorted(groups)}")
    post, stats, ll, obs = (d.groups[g] for g in ("posterior", "sample_stats", "log_likelihood", "observed_data"))
    for g in (post, stats, ll):
        if tuple(g.dimensions)[:2] != ("chain", "draw"):
            sys.exit(f"FAIL: {path}: group {g.name} dimensions {tuple(g.dimensions)}")
    for name in ("G_s", "lp"):
        if name not in (post.variables if name == "G_s" else stats.variables):
            sys.exit(f"FAIL: {path}: no variable {name}")
    if post.variables["G_s"].dimensions != ("chain", "draw"):
        sys.exit(f"FAIL: {path}: G_s dimensions {post.variables['G_s'].dimensions}")
    if ll.variables["eta"].dimensions != ("chain", "draw", "point"):
        sys.exit(f"FAIL: {path}: log_likelihood.eta dimensions {ll.variables['eta'].dimensions}")
    points = len(obs.dimensions["point"])
    if points != len(ll.dimensions["point"]) or points == 0:
        sys.exit(f"FAIL: {path}: {points} observed points, {len(ll.dimensions['point'])} in log_likelihood")
    steps = post.variables["draw"][:]
    columns = {"G_s": "G_s_uN_per_m", "lambda": "lambda", "eta0": "eta0_mPa_s"}
    values = {k: post.variables[k][:] for k in columns if k in post.variables}
    lp = stats.variables["lp"][:]
    loglik = ll.variables["eta"][:]
    n_chain = len(post.dimensions["chain"])
    for c in range(n_chain):
        for d_index, step in enumerate(steps):
            key = (sample, c // walkers, int(step), c % walkers)
            if key not in rows:
                sys.exit(f"FAIL: {path}: chain {c}, draw step {step} not in chains.csv as {key}")
            r = rows[key]
            for k, v in values.items():
                if r[columns[k]] and not close(float(v[c, d_index]), float(r[columns[k]])):
                    sys.exit(f"FAIL: {path}: {k} at {key}: {float(v[c, d_index])} against {r[columns[k]]}")
            if not close(float(lp[c, d_index]), float(r["log_posterior"])):
                sys.exit(f"FAIL: {path}: lp at {key}: {float(lp[c, d_index])} against {r['log_posterior']}")
            if not all(math.isfinite(float(x)) for x in loglik[c, d_index, :]):
                sys.exit(f"FAIL: {path}: a non-finite log-likelihood at {key}")
            checked += 1
    # The same draws as chains.csv, or (a sample of thousands of points) every m-th of its steps.
    in_csv = sum(1 for k in rows if k[0] == sample)
    if n_chain * len(steps) > in_csv or (n_chain * len(steps) < in_csv and len(obs.dimensions["point"]) * in_csv <= 500_000):
        sys.exit(f"FAIL: {path}: {n_chain * len(steps)} draws, chains.csv has {in_csv} for {sample}")
    d.close()
    expected = {"posterior": {"chain", "draw"}, "sample_stats": {"chain", "draw"},
                "log_likelihood": {"chain", "draw", "point"}, "observed_data": {"point", "phi", "shear_rate"}}
    for group, coords in expected.items():
        with xarray.open_dataset(path, group=group) as ds:
            if not coords <= set(ds.coords):
                sys.exit(f"FAIL: {path}: xarray reads group {group} with coordinates {sorted(ds.coords)}")
            if group == "posterior" and not math.isclose(float(ds["G_s"].max()), float(values["G_s"].max()), rel_tol=1e-12):
                sys.exit(f"FAIL: {path}: xarray's G_s differs from netCDF4's")
print(f"PASS: {len(files)} posterior file(s), {checked} draws equal to chains.csv")
