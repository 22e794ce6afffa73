"""rbcal's split R-hat and bulk ESS against an independent implementation of the published
rank-normalised estimators (Vehtari, Gelman, Simpson, Carpenter, Buerkner, Bayesian Analysis
16(2) 2021, 667-718: eqs. for rank normalisation, split R-hat, the multi-chain
autocorrelation and Geyer's initial monotone sequence), written here from the paper with
NumPy, not a call into rbcal. Tolerance: 1e-9 relative for R-hat and 1e-6 for ESS (the same
formulas, different summation order)."""
import statistics

import numpy as np
import pytest

import rbcal


def split(chains):
    n = chains.shape[1] // 2
    return np.concatenate([chains[:, :n], chains[:, -n:]], axis=0)


def rank_normalise(x):
    flat = x.ravel()
    order = flat.argsort(kind="mergesort")
    ranks = np.empty(flat.size)
    ranks[order] = np.arange(1, flat.size + 1)
    # average ranks of ties
    values, inverse = np.unique(flat, return_inverse=True)
    sums = np.bincount(inverse, weights=ranks)
    counts = np.bincount(inverse)
    ranks = (sums / counts)[inverse]
    inv = statistics.NormalDist().inv_cdf
    z = np.array([inv((r - 0.375) / (flat.size + 0.25)) for r in ranks])
    return z.reshape(x.shape)


def classic_rhat(chains):
    m, n = chains.shape
    means = chains.mean(axis=1)
    b = n * means.var(ddof=1)
    w = chains.var(axis=1, ddof=1).mean()
    var_plus = (n - 1) / n * w + b / n
    return np.sqrt(var_plus / w)


def rank_normalised_rhat(chains):
    s = split(chains)
    bulk = classic_rhat(rank_normalise(s))
    folded = np.abs(s - np.median(s))
    tail = classic_rhat(rank_normalise(folded))
    return max(bulk, tail)


def ess(chains):
    m, n = chains.shape
    centred = chains - chains.mean(axis=1, keepdims=True)
    acov = np.array([[np.dot(c[: n - t], c[t:]) / n for t in range(n)] for c in centred])
    means = chains.mean(axis=1)
    w = chains.var(axis=1, ddof=1).mean()
    var_plus = (n - 1) / n * w + n * means.var(ddof=1) / n
    rho = 1.0 - (w - acov.mean(axis=0)) / var_plus
    rho[0] = 1.0
    # Geyer's initial positive sequence of pair sums, made monotone.
    pairs = []
    for k in range(0, n - 1, 2):
        p = rho[k] + rho[k + 1]
        if p <= 0:
            break
        pairs.append(min(p, pairs[-1]) if pairs else p)
    tau = -1.0 + 2.0 * sum(pairs)
    return m * n / tau


def bulk_ess(chains):
    return ess(rank_normalise(split(chains)))


@pytest.mark.parametrize("case", ["independent", "autocorrelated", "shifted"])
def test_rhat_and_bulk_ess_agree_with_the_published_estimators(case):
    rng = np.random.default_rng(2021)
    chains = rng.normal(size=(4, 400))
    if case == "autocorrelated":  # AR(1), phi 0.8
        for k in range(4):
            for t in range(1, 400):
                chains[k, t] = 0.8 * chains[k, t - 1] + chains[k, t]
    if case == "shifted":  # one chain elsewhere: R-hat well above 1
        chains[0] += 1.5
    d = rbcal.chain_diagnostics(chains)
    assert d["rhat"] == pytest.approx(rank_normalised_rhat(chains), rel=1e-9)
    assert d["bulk_ess"] == pytest.approx(bulk_ess(chains), rel=1e-6)
    if case == "shifted":
        assert d["rhat"] > 1.1
    else:
        assert d["rhat"] < 1.02
