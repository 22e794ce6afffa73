"""rbcal.calibrate against the command line: the same options and seed give the same
summary (every method's numbers, the left-out points and the warnings; all but the MCMC's
wall-clock seconds), the chains come
as chains x draws x parameters, and the log posterior is a callable of theta."""
import json
import subprocess

import numpy as np
import pytest

import rbcal

OPTIONS = ["--method", "all", "--mcmc-max-steps", "300", "--chains", "2", "--walkers", "8", "--threads", "1",
           "--min-shear-rate", "0", "--seed", "7"]


@pytest.fixture(scope="module")
def surrogate(exe, source, scratch):
    path = scratch / "python_tiny_surrogate.json"
    subprocess.run([exe, "surrogate", "build", str(source / "tests/surrogate/data/tiny_library"), "-o", str(path)],
                   check=True, capture_output=True)
    return str(path)


@pytest.fixture(scope="module")
def data(source):
    return str(source / "tests/calibration/data/synthetic_rheometer.csv")


@pytest.fixture(scope="module")
def python_result(data, surrogate):
    return rbcal.calibrate(data, surrogate, method="all", mcmc_max_steps=300, chains=2, walkers=8, threads=1,
                           min_shear_rate=0.0, seed=7)


def test_python_equals_the_command_lines_summary(exe, data, surrogate, scratch, python_result):
    report = scratch / "python_cli_report"
    subprocess.run([exe, "calibrate", data, "--surrogate", surrogate, *OPTIONS, "-o", str(report), "--no-plots"],
                   check=True, capture_output=True)
    cli = json.loads((report / "summary.json").read_text())["samples"]
    assert [s["name"] for s in python_result.samples] == [s["name"] for s in cli]
    for mine, theirs in zip(python_result.samples, cli):
        for summary in (mine, theirs):  # wall-clock time: the one field that may differ
            summary["methods"]["mcmc"]["diagnostics"].pop("seconds")
        assert mine == theirs
    direct = python_result.samples[0]["methods"]["direct"]
    assert direct["G_s_uN_per_m"] > 0


def test_chains_are_chains_by_draws_by_parameters(python_result):
    name = python_result.samples[0]["name"]
    chains = python_result.chains(name)
    names = python_result.parameter_names(name)
    assert chains.ndim == 3 and chains.shape[0] == 2 and chains.shape[2] == len(names)
    assert names[0] == "ln_G_s"
    median = np.exp(np.median(chains[:, :, 0]))
    summary = python_result.samples[0]["methods"]["mcmc"]
    assert median * 1e6 == pytest.approx(summary["G_s_uN_per_m"], rel=1e-9)  # the posterior median


def test_the_log_posterior_is_a_callable_of_theta(python_result):
    name = python_result.samples[0]["name"]
    lp = python_result.log_posterior(name)
    chains = python_result.chains(name)
    theta = chains[0, -1, :]
    assert lp.dimension == chains.shape[2]
    assert np.isfinite(lp(theta))
    outside = theta.copy()
    outside[0] = np.log(1.0)  # G_s = 1 N/m: beyond the prior's 1e-3 N/m
    assert lp(outside) == -np.inf
    with pytest.raises(ValueError):
        lp(theta[:-1])


def test_a_surrogate_family_makes_the_offset_a_parameter(exe, data, surrogate, scratch):
    family = scratch / "python_tiny_family.json"
    subprocess.run([exe, "surrogate", "family", "--member", f"0.6={surrogate}", "--member", f"0.9={surrogate}",
                    "-o", str(family)], check=True, capture_output=True)
    result = rbcal.calibrate(data, str(family), method="all", mcmc_max_steps=300, chains=2, walkers=8, threads=1,
                             min_shear_rate=0.0, seed=7)
    name = result.samples[0]["name"]
    assert result.parameter_names(name)[-1] == "offset_c"
    mcmc = result.samples[0]["methods"]["mcmc"]
    c = mcmc["model_nuisances"]["offset_c"]
    assert 0.6 <= c["interval"]["lower"] <= c["value"] <= c["interval"]["upper"] <= 0.9
    assert "offset_c" in result.samples[0]["methods"]["direct"]["model_nuisances"]


def test_joint_posterior_and_comparison_equal_the_command_lines(exe, data, surrogate, scratch):
    """compare='hardened/intact' gives the ratio and the joint posterior that `rbcal calibrate
    --compare` writes to summary.json for the same seed; the ratio's draws are an array whose
    median is the reported one."""
    result = rbcal.calibrate(data, surrogate, method="mcmc", mcmc_max_steps=300, chains=2, walkers=8, threads=1,
                             min_shear_rate=0.0, seed=7, compare="hardened/intact")
    report = scratch / "python_cli_compare_report"
    subprocess.run([exe, "calibrate", data, "--surrogate", surrogate, "--method", "mcmc", "--mcmc-max-steps", "300",
                    "--chains", "2", "--walkers", "8", "--threads", "1", "--min-shear-rate", "0", "--seed", "7",
                    "--compare", "hardened/intact", "-o", str(report), "--no-plots"], check=True, capture_output=True)
    summary = json.loads((report / "summary.json").read_text())
    assert result.comparison["numerator"] == "hardened" and result.comparison["denominator"] == "intact"
    assert result.comparison["ratio_median"] == pytest.approx(summary["comparison"]["ratio_median"], rel=1e-12)
    assert result.comparison["interval"] == pytest.approx(summary["comparison"]["interval"], rel=1e-12)
    joint = result.joint
    assert [s["sample"] for s in joint["samples"]] == [s["sample"] for s in summary["joint"]["samples"]]
    for mine, theirs in zip(joint["samples"], summary["joint"]["samples"]):
        assert mine["shear_modulus_median_uN_per_m"] == pytest.approx(theirs["shear_modulus_median_uN_per_m"], rel=1e-12)
    draws = result.comparison_draws()
    assert draws.ndim == 1 and draws.size == result.comparison["pairs"]
    assert np.median(draws) == pytest.approx(result.comparison["ratio_median"], rel=1e-9)


def test_no_comparison_without_compare(python_result):
    assert python_result.comparison is None and python_result.joint is None
    with pytest.raises(ValueError, match="compare"):
        python_result.comparison_draws()
