// The window's error estimates: the blocking standard error of a correlated series, and the
// drift of its late half against its early half, on series whose answers are known.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "solver/simulation/detail/block_average.hpp"
#include "solver/simulation/window_drift.hpp"

using namespace rbcal::solver;

namespace {

// An AR(1) series x_t = mean + rho (x_{t-1} - mean) + e_t, stationary from its first sample,
// with unit marginal variance. Its mean's standard error over n samples is, for large n,
// sqrt((1 + rho) / ((1 - rho) n)) (e.g. Priestley, Spectral Analysis and Time Series, 1981,
// section 5.3).
std::vector<double> ar1(std::size_t n, double mean, double rho, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> e(0.0, std::sqrt(1.0 - rho * rho));
  std::vector<double> x(n);
  double dev = std::normal_distribution<double>(0.0, 1.0)(rng);
  for (double& v : x) {
    v = mean + dev;
    dev = rho * dev + e(rng);
  }
  return x;
}

// The drift as the solver takes it: with the window's blocking error.
WindowDrift drift_of(const std::vector<double>& x) {
  const MeanWithError whole = block_average(x);
  return window_drift(x, whole.sem / whole.mean);
}

}  // namespace

TEST(BlockAverage, StandardErrorOfACorrelatedSeries) {
  // 4096 samples with rho 0.9: the naive error is sqrt(19) = 4.4 times too small; the
  // blocking error, averaged over 40 series, lies within 15 % of the exact one.
  const std::size_t n = 4096;
  const double rho = 0.9, exact = std::sqrt((1 + rho) / ((1 - rho) * n));
  double sum = 0.0;
  for (unsigned seed = 1; seed <= 40; ++seed) sum += block_average(ar1(n, 5.0, rho, seed)).sem;
  EXPECT_NEAR(sum / 40, exact, 0.15 * exact);
}

TEST(WindowDrift, StationarySeriesRarelyDrift) {
  // 500 samples (a library run's window at its record interval), rho 0.95 (a correlation
  // time of 39 samples), 200 series: a drift beyond 3 sd in at most 2 % of them (Gaussian:
  // 0.3 %; 0.5 % over 2000 such series, where the halves' own blocking errors gave 9 %),
  // and no mean drift.
  int flagged = 0;
  double mean_z = 0.0;
  for (unsigned seed = 1; seed <= 200; ++seed) {
    const WindowDrift d = drift_of(ar1(500, 3.0, 0.95, seed));
    ASSERT_TRUE(d.available);
    if (std::abs(d.z()) > kDriftZ) ++flagged;
    mean_z += d.z() / 200;
  }
  EXPECT_LE(flagged, 4);
  EXPECT_NEAR(mean_z, 0.0, 0.3);
}

TEST(WindowDrift, RelaxingSeriesIsReported) {
  // A level relaxing by 10 % over the window, under the same noise at a tenth of the scale:
  // the halves' means differ by about 5 %, many sd.
  std::vector<double> x = ar1(500, 0.0, 0.95, 7);
  for (std::size_t i = 0; i < x.size(); ++i) x[i] = 3.0 * (1.0 + 0.1 * i / x.size()) + 0.03 * x[i];
  const WindowDrift d = drift_of(x);
  ASSERT_TRUE(d.available);
  EXPECT_NEAR(d.drift, std::log(1.075 / 1.025), 0.01);
  EXPECT_TRUE(drifts(d));
  // The same noise without the trend is not reported.
  std::vector<double> flat = ar1(500, 0.0, 0.95, 7);
  for (double& v : flat) v = 3.0 + 0.03 * v;
  EXPECT_FALSE(drifts(drift_of(flat)));
}

TEST(WindowDrift, TooShortOrNotPositiveIsNotAvailable) {
  EXPECT_FALSE(window_drift(std::vector<double>(31, 2.0), 0.01).available);
  EXPECT_TRUE(window_drift(std::vector<double>(32, 2.0), 0.01).available);
  EXPECT_FALSE(window_drift(std::vector<double>(64, -1.0), 0.01).available);
}

TEST(WindowDrift, ReadFromAResultBlock) {
  // What rbcal simulate and library generate print: the fields of result.json, when there.
  EXPECT_FALSE(drift_of_result(nlohmann::json{{"eta_re", 2.0}}).available);
  const WindowDrift d = drift_of_result(nlohmann::json{{"eta_re_drift", 0.094}, {"eta_re_drift_sd", 0.0286}});
  ASSERT_TRUE(d.available);
  EXPECT_NEAR(d.z(), 3.29, 0.01);
  EXPECT_TRUE(drifts(d));
  // Past 3 sd but within 2 %: a very steady run's tiny drift is not reported.
  EXPECT_FALSE(drifts(drift_of_result(nlohmann::json{{"eta_re_drift", 0.015}, {"eta_re_drift_sd", 0.001}})));
}
