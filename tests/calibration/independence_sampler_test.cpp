// The independence sampler and its multivariate t proposal against known distributions:
// moments of the t (covariance dof / (dof - 2) x scale), quantiles of a correlated Gaussian
// and of a skewed (Gamma) target within Monte Carlo error, and the fallback to the ensemble
// when the fitted proposal cannot match the posterior (two separated modes).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include <boost/math/distributions/gamma.hpp>

#include "calibration/detail/independence_sampler.hpp"
#include "calibration/mcmc_sampling.hpp"

using namespace rbcal::calibration;

TEST(MultivariateT, DrawsHaveTheLocationAndCovarianceOfTheT) {
  const Eigen::Vector2d mean(1.0, -2.0);
  Eigen::Matrix2d scale;
  scale << 2.0, 0.6, 0.6, 0.5;
  const double dof = 6.0;  // finite fourth moments, so the sample covariance settles
  const MultivariateT t(mean, scale, dof);
  std::mt19937_64 rng(11);
  constexpr int kDraws = 200000;
  Eigen::Vector2d sum = Eigen::Vector2d::Zero();
  Eigen::Matrix2d squares = Eigen::Matrix2d::Zero();
  for (int i = 0; i < kDraws; ++i) {
    const Eigen::VectorXd x = t.draw(rng);
    sum += x;
    squares += (x - mean) * (x - mean).transpose();
  }
  const Eigen::Matrix2d covariance = dof / (dof - 2.0) * scale;
  const Eigen::Vector2d sample_mean = sum / kDraws;
  const Eigen::Matrix2d sample_covariance = squares / kDraws;
  for (int i = 0; i < 2; ++i) {
    // Standard error of a mean: sqrt(var / n); of a (co)variance: a few percent at this n.
    EXPECT_NEAR(sample_mean(i), mean(i), 5.0 * std::sqrt(covariance(i, i) / kDraws));
    for (int j = 0; j < 2; ++j) EXPECT_NEAR(sample_covariance(i, j), covariance(i, j), 0.03 * covariance(i, i));
  }
}

TEST(MultivariateT, LogDensityIsTheTKernel) {
  // In one dimension with scale s^2 the kernel is -(dof + 1) / 2 ln(1 + (x - m)^2 / (dof s^2)).
  const MultivariateT t(Eigen::VectorXd::Constant(1, 0.5), Eigen::MatrixXd::Constant(1, 1, 4.0), 3.0);
  const auto at = [&](double x) { return t.log_density(Eigen::VectorXd::Constant(1, x)); };
  EXPECT_NEAR(at(0.5), 0.0, 1e-15);
  EXPECT_NEAR(at(2.5), -2.0 * std::log1p(4.0 / 12.0), 1e-14);
  EXPECT_NEAR(at(-3.5), -2.0 * std::log1p(16.0 / 12.0), 1e-14);
  // With its normaliser the density integrates to 1 (trapezoid over +-2000 scales; the tails
  // beyond hold about 1e-10 for 3 dof) and has covariance dof / (dof - 2) x scale.
  double integral = 0.0;
  const double h = 0.01;
  for (double x = -4000.0; x <= 4000.0; x += h) integral += h * std::exp(at(x) + t.log_normaliser());
  EXPECT_NEAR(integral, 1.0, 1e-6);
  EXPECT_NEAR(t.covariance()(0, 0), 3.0 * 4.0, 1e-12);
}

namespace {

McmcOptions independence_options(std::uint64_t seed) {
  McmcOptions o;
  o.sampler = SamplerKind::Independence;
  o.seed = seed;
  o.threads = 1;
  return o;
}

// |q_sample - q_exact| within 4 Monte Carlo standard errors sqrt(p (1 - p) / ESS) / f(q).
template <class Density, class Quantile>
void expect_quantiles(const McmcResult& r, int parameter, Density density, Quantile exact) {
  const std::vector<double> draws = r.parameter_draws(parameter);
  for (double p : {0.025, 0.5, 0.975}) {
    SCOPED_TRACE(p);
    const double ess = p == 0.5 ? r.parameters[parameter].bulk_ess : r.parameters[parameter].tail_ess;
    const double q = exact(p);
    const double mcse = std::sqrt(p * (1.0 - p) / ess) / density(q);
    EXPECT_NEAR(quantile(draws, p), q, 4.0 * mcse) << "ESS " << ess;
  }
}

// N(1, 0.5^2): its density and quantiles.
double normal_density(double x) {
  return std::exp(-0.5 * std::pow((x - 1.0) / 0.5, 2)) / (0.5 * std::sqrt(2.0 * std::numbers::pi));
}
double normal_quantile(double p) { return 1.0 + 0.5 * std::sqrt(2.0) * boost::math::erf_inv(2.0 * p - 1.0); }

// N(mu, Sigma) with correlation 0.9, whose marginal of x0 is N(1, 0.5^2).
struct CorrelatedGaussian {
  Eigen::Matrix2d sigma = (Eigen::Matrix2d() << 0.25, 0.9 * 0.5 * 2.0, 0.9 * 0.5 * 2.0, 4.0).finished();
  Eigen::Vector2d mu{1.0, -3.0};
  LogDensity log_density() const {
    const Eigen::Matrix2d precision = sigma.inverse();
    const Eigen::Vector2d m = mu;
    return [precision, m](const Eigen::VectorXd& x) {
      const Eigen::Vector2d d = x - m;
      return -0.5 * d.dot(precision * d);
    };
  }
};

}  // namespace

TEST(IndependenceSampler, CorrelatedGaussianQuantilesAndFewStepsPerEffectiveDraw) {
  const CorrelatedGaussian target;
  const McmcResult r = sample_posterior(target.log_density(), {"x0", "x1"}, {target.mu, Eigen::Vector2d(0.5, 2.0), {}},
                                        independence_options(3));
  ASSERT_TRUE(r.converged) << r.stop_reason;
  EXPECT_EQ(r.pilot_steps, 100);
  EXPECT_NE(r.sampler.find("independence"), std::string::npos) << r.sampler;
  // A fitted t proposal accepts most draws in two dimensions; the stretch move accepts about
  // half and needs hundreds of steps (its first check alone is at 500).
  EXPECT_GT(r.acceptance_fraction, 0.5);
  EXPECT_LE(r.steps, 200);
  expect_quantiles(r, 0, normal_density, normal_quantile);
}

// With the posterior's Laplace covariance the independence stage starts at once: no pilot,
// the same quantiles, and fewer evaluations than with the pilot.
TEST(IndependenceSampler, StartsWithoutAPilotFromALaplaceCovariance) {
  const CorrelatedGaussian target;
  const LogDensity log_density = target.log_density();
  const McmcStart with_covariance{target.mu, Eigen::Vector2d(0.5, 2.0), target.sigma};
  const McmcResult r = sample_posterior(log_density, {"x0", "x1"}, with_covariance, independence_options(3));
  ASSERT_TRUE(r.converged) << r.stop_reason;
  EXPECT_EQ(r.pilot_steps, 0);
  EXPECT_NE(r.sampler.find("Laplace covariance"), std::string::npos) << r.sampler;
  EXPECT_GT(r.acceptance_fraction, 0.5);
  const McmcResult piloted = sample_posterior(log_density, {"x0", "x1"}, {target.mu, Eigen::Vector2d(0.5, 2.0), {}},
                                              independence_options(3));
  EXPECT_LT(2 * r.evaluations, piloted.evaluations);
  // Every proposal of the stage is recorded with its importance weight.
  EXPECT_EQ(static_cast<long long>(r.proposal_log_weights.size()), 4LL * 8 * r.steps);
  expect_quantiles(r, 0, normal_density, normal_quantile);
}

// A Laplace covariance far narrower than the posterior (sd 10 times too small) must not be
// trusted: chains confined to it look converged. The draws' spread gives it away, and the
// sampler falls back to the pilot, with the right quantiles.
TEST(IndependenceSampler, ATooNarrowStartCovarianceFallsBackToThePilot) {
  const LogDensity log_density = [](const Eigen::VectorXd& x) { return -0.5 * std::pow((x(0) - 1.0) / 0.5, 2); };
  const McmcStart narrow{Eigen::VectorXd::Constant(1, 1.0), Eigen::VectorXd::Constant(1, 0.05),
                         Eigen::MatrixXd::Constant(1, 1, 0.05 * 0.05)};
  const McmcResult r = sample_posterior(log_density, {"x"}, narrow, independence_options(7));
  ASSERT_TRUE(r.converged) << r.stop_reason;
  EXPECT_EQ(r.pilot_steps, 100) << r.sampler;
  EXPECT_NE(r.sampler.find("too narrow"), std::string::npos) << r.sampler;
  expect_quantiles(r, 0, normal_density, normal_quantile);
}

TEST(IndependenceSampler, SkewedTargetQuantiles) {
  // Gamma(shape 3, scale 1): skewed, light left tail bounded at 0.
  const boost::math::gamma_distribution<double> gamma(3.0, 1.0);
  const LogDensity log_density = [](const Eigen::VectorXd& x) {
    return x(0) > 0.0 ? 2.0 * std::log(x(0)) - x(0) : -std::numeric_limits<double>::infinity();
  };
  const McmcResult r = sample_posterior(log_density, {"x"}, {Eigen::VectorXd::Constant(1, 3.0),
                                                             Eigen::VectorXd::Constant(1, 0.5), {}},
                                        independence_options(5));
  ASSERT_TRUE(r.converged) << r.stop_reason;
  EXPECT_EQ(r.pilot_steps, 100) << r.sampler;
  expect_quantiles(r, 0, [&](double x) { return boost::math::pdf(gamma, x); },
                   [&](double p) { return boost::math::quantile(gamma, p); });
}

TEST(IndependenceSampler, FallsBackToTheEnsembleWhenTheProposalFitsPoorly) {
  // Two narrow modes 20 sd apart: one t over both accepts only a few percent of its draws.
  const LogDensity log_density = [](const Eigen::VectorXd& x) {
    const double a = -0.5 * std::pow((x(0) + 1.0) / 0.1, 2), b = -0.5 * std::pow((x(0) - 1.0) / 0.1, 2);
    return std::max(a, b) + std::log1p(std::exp(std::min(a, b) - std::max(a, b)));
  };
  McmcOptions o = independence_options(9);
  o.max_steps = 1000;
  const McmcResult r = sample_posterior(log_density, {"x"}, {Eigen::VectorXd::Zero(1), Eigen::VectorXd::Constant(1, 1.0), {}}, o);
  EXPECT_EQ(r.pilot_steps, 0);
  EXPECT_NE(r.sampler.find("ensembles went on"), std::string::npos) << r.sampler;
  EXPECT_EQ(r.steps, 1000);  // the ensemble's own schedule, the pilot's steps included
}

TEST(IndependenceSampler, SameSeedSameDraws) {
  const LogDensity log_density = [](const Eigen::VectorXd& x) { return -0.5 * x.squaredNorm(); };
  const McmcStart start{Eigen::VectorXd::Zero(1), Eigen::VectorXd::Ones(1), {}};
  const McmcResult a = sample_posterior(log_density, {"x"}, start, independence_options(4));
  McmcOptions two_threads = independence_options(4);
  two_threads.threads = 2;
  const McmcResult b = sample_posterior(log_density, {"x"}, start, two_threads);
  EXPECT_EQ(a.parameter_draws(0), b.parameter_draws(0));
}
