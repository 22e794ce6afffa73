#pragma once
// Convergence and efficiency diagnostics of Markov chains, each chain a series of draws of one
// scalar. All functions split each chain into halves first ("split" chains, BDA3 section 11.4),
// so that a drift within a chain shows up as between-chain variance.
#include <vector>

namespace rbcal::calibration {

using ChainSet = std::vector<std::vector<double>>;  // chains of equal length (>= 4 draws)

// Classic split R-hat: sqrt(var_plus / W), var_plus = (n-1)/n W + B/n (Gelman et al. 2013, BDA3 eq. 11.3-11.4).
double split_rhat(const ChainSet& chains);

// Rank-normalised split R-hat: the larger of the bulk (rank-normalised draws) and tail (folded
// draws |x - median|, rank-normalised) values (Vehtari et al. 2021, Bayesian Analysis 16(2), eq. 14ff).
double rank_normalized_split_rhat(const ChainSet& chains);

// Effective sample size M N / tau of split chains, with the multi-chain autocorrelation estimate
// rho_t = 1 - (W - mean autocovariance_t) / var_plus (BDA3 eq. 11.7; Vehtari et al. 2021 eq. 10)
// truncated by Geyer's initial monotone sequence (Geyer 1992).
double effective_sample_size(const ChainSet& chains);

// Bulk-ESS: effective_sample_size of the rank-normalised draws (Vehtari et al. 2021).
double bulk_effective_sample_size(const ChainSet& chains);

// Tail-ESS: the smaller ESS of the indicators I(x <= q_0.05) and I(x <= q_0.95) (Vehtari et al. 2021).
double tail_effective_sample_size(const ChainSet& chains);

// Integrated autocorrelation time tau = 1 + 2 sum_{t>=1} rho_t = total draws / ESS (in draws of one chain).
double integrated_autocorrelation_time(const ChainSet& chains);

// The draws replaced by normal scores of their pooled fractional ranks, Phi^-1((r - 3/8) / (S + 1/4))
// (Blom 1958; Vehtari et al. 2021 eq. 14); ties get their average rank.
ChainSet rank_normalize(const ChainSet& chains);

// Each chain cut into two halves (the middle draw of an odd chain dropped).
ChainSet split_chains(const ChainSet& chains);

}  // namespace rbcal::calibration
