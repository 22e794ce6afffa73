#!/usr/bin/env python3
"""Side by side: rbcal's two samplers (independence, the default, and the stretch-move
ensemble) and emcee (Debian python3-emcee) on the same posterior, the log posterior of
rbcal.calibrate called through the Python module.

Posterior: by default the "intact" sample of tests/calibration/data/synthetic_rheometer.csv
on the surrogate of tests/surrogate/data/tiny_library; with --shipped, the shipped sample
(data/samples/kim2017_whole_blood.csv) on the shipped default surrogate with the CLI's
default point selection (its posterior is truncated at the model's largest Ca: an edge fit,
docs/calibration.md). Two parameters (ln G_s, ln eta0: the plasma viscosity as nuisance
parameter) as shipped, one (ln G_s) with eta0 fixed (the sample's plasma rows rewritten
with sd 0; not with --shipped, whose points are out of the model's reach once eta0 is fixed).

Both samplers: one thread, the same number of walkers in all (64: rbcal 4 ensembles x 16,
emcee one ensemble of 64), at most the same number of steps (rbcal stops earlier once
R-hat < 1.01 and ESS >= 1000), emcee's first half discarded (rbcal discards its own
burn-in: the first half for the ensemble, the pilot and 10 % after it for the independence
sampler). ESS of
ln G_s by one and the same estimator for both (rbcal.chain_diagnostics: bulk ESS, walkers
as chains). Usage (from the repository root, after the build):
    PYTHONPATH=build/python /usr/bin/python3 bench/python/emcee_comparison.py [--steps N] [--rounds R] [--shipped]
"""
import argparse
import os
import pathlib
import subprocess
import tempfile
import time

import emcee
import numpy as np

import rbcal

ROOT = pathlib.Path(__file__).resolve().parents[2]
SYNTHETIC = {"data": ROOT / "tests/calibration/data/synthetic_rheometer.csv", "sample": "intact",
             "min_shear_rate": 0.0}
SHIPPED = {"data": ROOT / "data/samples/kim2017_whole_blood.csv", "sample": "kim2017_whole_blood",
           "min_shear_rate": 40.0, "surrogate": ROOT / "data/library/default/surrogate.json"}
POSTERIOR = dict(SYNTHETIC)


def fixed_eta0_copy(folder):
    """The same CSV with every plasma row's sd set to 0: eta0 becomes a constant."""
    out = folder / "fixed_eta0.csv"
    lines = []
    for line in POSTERIOR["data"].read_text().splitlines():
        fields = line.split(",")
        if len(fields) == 7 and fields[1] == "plasma":
            fields[5] = "0"
        elif len(fields) == 7 and fields[1] == "plasma_assumed":  # as one measured plateau row, sd 0
            fields[1], fields[3], fields[5] = "plasma", "100", "0"
        lines.append(",".join(fields))
    out.write_text("\n".join(lines) + "\n")
    return out


def walker_chains(pooled, walkers):
    """rbcal's chains (ensembles x draws pooled step by step) as one series per walker."""
    return np.concatenate([c.reshape(-1, walkers).T for c in pooled], axis=0)


def quantiles(x):
    return np.quantile(x, [0.025, 0.5, 0.975])


def run_rbcal(data, surrogate, steps, seed, sampler, walkers, ensembles):
    t0 = time.perf_counter()
    name = POSTERIOR["sample"]
    cal = rbcal.calibrate(str(data), surrogate, method="mcmc", samples=[name], mcmc_max_steps=steps,
                          chains=ensembles, walkers=walkers, threads=1, min_shear_rate=POSTERIOR["min_shear_rate"],
                          seed=seed, sampler=sampler)
    seconds = time.perf_counter() - t0
    diagnostics = cal.samples[0]["methods"]["mcmc"]["diagnostics"]
    assert diagnostics["sampler"].startswith(sampler), diagnostics["sampler"]
    return cal, seconds, cal.chains(name), diagnostics["pilot_steps"] + diagnostics["steps"]


def run(data, surrogate, steps, seed):
    walkers, ensembles = 16, 4
    out = {}
    for who in ("independence", "ensemble"):
        cal, seconds, pooled, n = run_rbcal(data, surrogate, steps, seed, who, walkers, ensembles)
        out[f"{who}_seconds"] = seconds
        out[f"{who}_steps"] = n
        out[f"{who}_ess"] = rbcal.chain_diagnostics(walker_chains(pooled[:, :, 0], walkers))["bulk_ess"]
        out[f"{who}_q"] = quantiles(pooled[:, :, 0].ravel())
    out["sd"] = np.std(pooled[:, :, 0].ravel())
    names = cal.parameter_names(POSTERIOR["sample"])
    lp = cal.log_posterior(POSTERIOR["sample"])

    # emcee: 64 walkers started where rbcal's ensembles ended their burn-in's first draw.
    start = np.concatenate([c.reshape(-1, walkers, len(names))[0] for c in pooled], axis=0)
    sampler = emcee.EnsembleSampler(ensembles * walkers, len(names), lambda th: lp(np.ascontiguousarray(th)))
    t0 = time.perf_counter()
    sampler.run_mcmc(start, steps, progress=False)
    emcee_seconds = time.perf_counter() - t0
    chain = sampler.get_chain(discard=steps // 2)  # steps x walkers x dim
    ln_gs_emcee = chain[:, :, 0].T
    out.update({"emcee_steps": steps, "emcee_seconds": emcee_seconds,
                "emcee_ess": rbcal.chain_diagnostics(ln_gs_emcee)["bulk_ess"],
                "emcee_q": quantiles(ln_gs_emcee.ravel())})
    return out


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--steps", type=int, default=2000, help="steps per walker (both samplers)")
    parser.add_argument("--rounds", type=int, default=3, help="repetitions (medians are reported)")
    parser.add_argument("--shipped", action="store_true",
                        help="the shipped sample on the shipped default surrogate instead of the synthetic one")
    args = parser.parse_args()
    if args.shipped:
        POSTERIOR.update(SHIPPED)
    exe = os.environ.get("RBCAL_EXE", str(ROOT / "build/bin/rbcal"))
    with tempfile.TemporaryDirectory() as tmp:
        folder = pathlib.Path(tmp)
        if "surrogate" in POSTERIOR:
            surrogate = str(POSTERIOR["surrogate"])
        else:
            surrogate = str(folder / "tiny_surrogate.json")
            subprocess.run([exe, "surrogate", "build", str(ROOT / "tests/surrogate/data/tiny_library"), "-o",
                            surrogate], check=True, capture_output=True)
        cases = [("ln G_s, ln eta0", POSTERIOR["data"])]
        # With eta0 fixed at 1.45 mPa s no point of the shipped sample is within the model's
        # reach (their errors no longer carry eta0's): there only the two-parameter posterior exists.
        if not args.shipped:
            cases.insert(0, ("ln G_s (eta0 fixed)", fixed_eta0_copy(folder)))
        print(f"posterior: sample {POSTERIOR['sample']} of {POSTERIOR['data'].relative_to(ROOT)} on {surrogate}")
        print(f"at most {args.steps} steps x 64 walkers, {args.rounds} rounds (medians), 1 thread; steps: "
              "per walker, pilot included")
        print("| posterior | sampler | steps | seconds | bulk ESS of ln G_s | ESS / s | q2.5, q50, q97.5 of ln G_s |")
        print("|---|---|---|---|---|---|---|")
        for label, data in cases:
            results = [run(data, surrogate, args.steps, seed=100 + r) for r in range(args.rounds)]
            for who in ("independence", "ensemble", "emcee"):
                sec = np.median([r[f"{who}_seconds"] for r in results])
                ess = np.median([r[f"{who}_ess"] for r in results])
                rate = np.median([r[f"{who}_ess"] / r[f"{who}_seconds"] for r in results])
                q = results[0][f"{who}_q"]
                n = int(np.median([r[f"{who}_steps"] for r in results]))
                name = who if who == "emcee" else f"rbcal {who}"
                print(f"| {label} | {name} | {n} | {sec:.3f} | {ess:.0f} | {rate:.0f} | {q[0]:.4f}, {q[1]:.4f}, {q[2]:.4f} |")
            r0 = results[0]
            for who in ("independence", "ensemble"):
                ratio = np.median([(r[f"{who}_ess"] / r[f"{who}_seconds"]) / (r["emcee_ess"] / r["emcee_seconds"])
                                   for r in results])
                # Monte Carlo error of the difference of two medians: sqrt(pi / 2) sd / sqrt(ESS) each.
                mc_error = np.sqrt(np.pi / 2) * r0["sd"] * np.sqrt(1 / r0[f"{who}_ess"] + 1 / r0["emcee_ess"])
                print(f"|  | ratio rbcal {who} / emcee (ESS per second) | | | | {ratio:.2f} | medians differ by "
                      f"{abs(r0[f'{who}_q'][1] - r0['emcee_q'][1]) / mc_error:.2f} Monte Carlo errors |")


if __name__ == "__main__":
    main()
