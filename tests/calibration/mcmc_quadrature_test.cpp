// The MCMC posterior against brute-force quadrature of the same LogPosterior: marginal quantiles
// agree within Monte Carlo error, estimated from the chains' own ESS.
// Monte Carlo standard error of a quantile q_p: sqrt(p (1 - p) / ESS) / f(q_p), f the marginal density.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "analytic_viscosity_model.hpp"
#include "calibration/mcmc_calibration.hpp"
#include "synthetic_sample.hpp"

using namespace rbcal::calibration;
using rbcal::calibration::test_models::AnalyticViscosityModel;

namespace {

// Quantiles and density at the quantile of a density tabulated on a uniform grid (trapezoid rule).
struct Marginal {
  std::vector<double> x, density;  // density normalised to integrate to 1
  double quantile(double p) const {
    double cumulative = 0.0;
    for (std::size_t i = 0; i + 1 < x.size(); ++i) {
      const double piece = 0.5 * (density[i] + density[i + 1]) * (x[i + 1] - x[i]);
      if (cumulative + piece >= p) return x[i] + (p - cumulative) / piece * (x[i + 1] - x[i]);
      cumulative += piece;
    }
    return x.back();
  }
  double density_at(double v) const {
    for (std::size_t i = 0; i + 1 < x.size(); ++i)
      if (v <= x[i + 1]) return density[i] + (density[i + 1] - density[i]) * (v - x[i]) / (x[i + 1] - x[i]);
    return density.back();
  }
};

Marginal normalised(std::vector<double> x, std::vector<double> log_density) {
  const double top = *std::max_element(log_density.begin(), log_density.end());
  Marginal m{std::move(x), {}};
  double area = 0.0;
  for (double l : log_density) m.density.push_back(std::exp(l - top));
  for (std::size_t i = 0; i + 1 < m.x.size(); ++i) area += 0.5 * (m.density[i] + m.density[i + 1]) * (m.x[i + 1] - m.x[i]);
  for (double& d : m.density) d /= area;
  return m;
}

void expect_quantiles_match(const Marginal& exact, const ParameterSummary& summary, const std::vector<double>& draws) {
  for (double p : {0.025, 0.5, 0.975}) {
    SCOPED_TRACE(p);
    const double ess = (p == 0.5 ? summary.bulk_ess : summary.tail_ess);
    const double q_exact = exact.quantile(p);
    const double mcse = std::sqrt(p * (1.0 - p) / ess) / exact.density_at(q_exact);
    EXPECT_NEAR(quantile(draws, p), q_exact, 4.0 * mcse) << "MCSE " << mcse << " ESS " << ess;
  }
}

SampleData small_sample(const AnalyticViscosityModel& model, double discrepancy, std::uint64_t seed) {
  test_models::SyntheticDesign design;
  design.phis = {0.15, 0.3};
  design.shear_rates = {2.0, 5.0, 12.0, 30.0, 70.0, 160.0};
  design.relative_measurement_sd = 0.03;
  std::mt19937_64 rng(seed);
  SampleData sample = test_models::synthetic_sample(model, design, rng);
  std::normal_distribution<double> normal;
  for (auto& p : sample.points) p.eta_re *= 1.0 + discrepancy * normal(rng);
  return sample;
}

}  // namespace

namespace rbcal::calibration {
// Names the parameter in the test list (gtest would print its bytes).
void PrintTo(SamplerKind kind, std::ostream* out) { *out << to_string(kind); }
}  // namespace rbcal::calibration

// Both samplers: the independence sampler (the default) and the stretch-move ensemble.
class McmcQuadrature : public testing::TestWithParam<SamplerKind> {};

INSTANTIATE_TEST_SUITE_P(Samplers, McmcQuadrature, testing::Values(SamplerKind::Independence, SamplerKind::Ensemble),
                         [](const testing::TestParamInfo<SamplerKind>& i) { return to_string(i.param); });

TEST_P(McmcQuadrature, OneDimensionalPosteriorOfLnShearModulus) {
  AnalyticViscosityModel model;
  const SampleData sample = small_sample(model, 0.0, 101);
  McmcCalibrationOptions options;
  options.sampler.sampler = GetParam();
  options.sampler.seed = 7;
  const McmcCalibration result = calibrate_mcmc(sample, model, options);
  ASSERT_TRUE(result.mcmc.converged) << result.mcmc.stop_reason;
  EXPECT_EQ(result.mcmc.sampler.substr(0, to_string(GetParam()).size()), to_string(GetParam())) << result.mcmc.sampler;

  const LogPosterior posterior(model, sample.plasma.eta0, result.points, result.posterior);
  const double center = result.start_fit.estimate(0), width = 10.0 * result.start_fit.ln_shear_modulus_sd;
  std::vector<double> x, log_density;
  for (int i = 0; i <= 4000; ++i) {
    x.push_back(center - width + 2.0 * width * i / 4000.0);
    log_density.push_back(posterior(Eigen::VectorXd::Constant(1, x.back())));
  }
  expect_quantiles_match(normalised(x, log_density), result.mcmc.parameters[0], result.mcmc.parameter_draws(0));
}

TEST_P(McmcQuadrature, TwoDimensionalPosteriorWithModelDiscrepancy) {
  AnalyticViscosityModel model;
  const SampleData sample = small_sample(model, 0.05, 202);
  McmcCalibrationOptions options;
  options.sampler.sampler = GetParam();
  options.posterior.fit_discrepancy = true;
  options.sampler.seed = 8;
  const McmcCalibration result = calibrate_mcmc(sample, model, options);
  ASSERT_TRUE(result.mcmc.converged) << result.mcmc.stop_reason;
  EXPECT_EQ(result.mcmc.sampler.substr(0, to_string(GetParam()).size()), to_string(GetParam())) << result.mcmc.sampler;
  ASSERT_EQ(result.mcmc.parameter_names.size(), 2u);

  // Quadrature on a grid covering the draws generously; marginals by summing over the other axis.
  const LogPosterior posterior(model, sample.plasma.eta0, result.points, result.posterior);
  const auto range_of = [&](int p) {
    const auto d = result.mcmc.parameter_draws(p);
    const double lo = quantile(d, 0.0), hi = quantile(d, 1.0), pad = 0.5 * (hi - lo);
    return std::make_pair(lo - pad, hi + pad);
  };
  const auto [g_lo, g_hi] = range_of(0);
  const auto [s_lo, s_hi] = range_of(1);
  constexpr int kNodes = 301;
  std::vector<double> gx(kNodes), sx(kNodes), grid(kNodes * kNodes);
  for (int i = 0; i < kNodes; ++i) {
    gx[i] = g_lo + (g_hi - g_lo) * i / (kNodes - 1);
    sx[i] = s_lo + (s_hi - s_lo) * i / (kNodes - 1);
  }
  double top = -1e300;
  for (int i = 0; i < kNodes; ++i)
    for (int j = 0; j < kNodes; ++j) {
      grid[i * kNodes + j] = posterior(Eigen::Vector2d(gx[i], sx[j]));
      top = std::max(top, grid[i * kNodes + j]);
    }
  std::vector<double> log_g(kNodes), log_s(kNodes);
  for (int i = 0; i < kNodes; ++i) {
    double sum_g = 0.0, sum_s = 0.0;
    for (int j = 0; j < kNodes; ++j) {
      sum_g += std::exp(grid[i * kNodes + j] - top);
      sum_s += std::exp(grid[j * kNodes + i] - top);
    }
    log_g[i] = std::log(sum_g);
    log_s[i] = std::log(sum_s);
  }
  {
    SCOPED_TRACE("ln G_s");
    expect_quantiles_match(normalised(gx, log_g), result.mcmc.parameters[0], result.mcmc.parameter_draws(0));
  }
  {
    SCOPED_TRACE("ln sigma_d");
    expect_quantiles_match(normalised(sx, log_s), result.mcmc.parameters[1], result.mcmc.parameter_draws(1));
  }
}
