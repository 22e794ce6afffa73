// Split R-hat, ESS and the integrated autocorrelation time on chains whose answers are known:
// AR(1) chains x_t = rho x_{t-1} + sqrt(1 - rho^2) e_t have tau = (1 + rho) / (1 - rho).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "calibration/chain_diagnostics.hpp"

using namespace rbcal::calibration;

namespace {

ChainSet ar1_chains(int chains, int length, double rho, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> normal;
  ChainSet out(chains);
  for (auto& c : out) {
    double x = normal(rng);  // stationary start
    for (int t = 0; t < length; ++t) {
      x = rho * x + std::sqrt(1.0 - rho * rho) * normal(rng);
      c.push_back(x);
    }
  }
  return out;
}

}  // namespace

TEST(ChainDiagnostics, SplitRhatByHand) {
  // Split halves {1,2} {3,4} {2,3} {4,5}: W = 0.5, B/n = 5/3, n = 2:
  // var_plus = 0.25 + 5/3, R-hat = sqrt(var_plus / W).
  const ChainSet chains = {{1, 2, 3, 4}, {2, 3, 4, 5}};
  EXPECT_NEAR(split_rhat(chains), std::sqrt((0.25 + 5.0 / 3.0) / 0.5), 1e-12);
}

TEST(ChainDiagnostics, AutocorrelationTimeOfAr1) {
  for (double rho : {0.0, 0.5, 0.9}) {
    SCOPED_TRACE(rho);
    const ChainSet chains = ar1_chains(4, 50000, rho, 17);
    const double expected_tau = (1.0 + rho) / (1.0 - rho);
    // Relative standard error of tau-hat is about sqrt(2 (2 W + 1) / N) with window W ~ 5 tau (Sokal).
    const double tolerance = 4.0 * std::sqrt(2.0 * (10.0 * expected_tau + 1.0) / 200000.0);
    EXPECT_NEAR(integrated_autocorrelation_time(chains) / expected_tau, 1.0, tolerance);
    EXPECT_NEAR(effective_sample_size(chains) / (200000.0 / expected_tau), 1.0, tolerance);
    EXPECT_NEAR(bulk_effective_sample_size(chains) / (200000.0 / expected_tau), 1.0, tolerance);
    EXPECT_GT(tail_effective_sample_size(chains), 0.3 * 200000.0 / expected_tau);
    EXPECT_LT(split_rhat(chains), 1.01);
    EXPECT_LT(rank_normalized_split_rhat(chains), 1.01);
  }
}

TEST(ChainDiagnostics, RhatFlagsChainsThatDisagree) {
  ChainSet shifted = ar1_chains(4, 2000, 0.5, 23);
  for (double& x : shifted[3]) x += 1.0;  // one chain in another place
  EXPECT_GT(split_rhat(shifted), 1.05);
  EXPECT_GT(rank_normalized_split_rhat(shifted), 1.05);

  ChainSet drifting = ar1_chains(4, 2000, 0.5, 29);
  for (auto& c : drifting)
    for (std::size_t t = 0; t < c.size(); ++t) c[t] += 2.0 * t / c.size();  // not stationary: split halves differ
  EXPECT_GT(split_rhat(drifting), 1.05);

  // Same location, different scale: only the folded (tail) part of the rank-normalised R-hat sees it.
  ChainSet scaled = ar1_chains(4, 2000, 0.0, 31);
  for (double& x : scaled[0]) x *= 4.0;
  for (double& x : scaled[1]) x *= 4.0;
  EXPECT_LT(split_rhat(scaled), 1.01);
  EXPECT_GT(rank_normalized_split_rhat(scaled), 1.05);
}

TEST(ChainDiagnostics, RankNormalisationGivesNormalScores) {
  const ChainSet chains = {{10.0, 30.0, 20.0, 40.0}, {50.0, 60.0, 70.0, 80.0}};
  const ChainSet z = rank_normalize(chains);
  EXPECT_LT(z[0][0], z[0][2]);  // order kept
  EXPECT_LT(z[0][2], z[0][1]);
  EXPECT_NEAR(z[0][0], -z[1][3], 1e-12);  // symmetric scores
  EXPECT_THROW(split_rhat({{1.0, 2.0}}), std::invalid_argument);
}

TEST(ChainDiagnostics, NonFiniteDrawsAreRefusedNotLoopedOn) {
  // A NaN compares unequal to itself, so the tie grouping of the ranks never advanced past it
  // and the diagnostics hung (and sorting NaN keys is undefined behaviour).
  ChainSet chains = ar1_chains(4, 100, 0.5, 11);
  chains[2][37] = std::nan("");
  try {
    rank_normalized_split_rhat(chains);
    FAIL() << "a NaN draw was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("draw 37 of chain 2"), std::string::npos) << e.what();
  }
  EXPECT_THROW(rank_normalize(chains), std::invalid_argument);
  EXPECT_THROW(bulk_effective_sample_size(chains), std::invalid_argument);
  chains[2][37] = INFINITY;
  EXPECT_THROW(split_rhat(chains), std::invalid_argument);
}
