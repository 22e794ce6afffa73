// The joint posterior over several samples (calibration/joint_posterior.hpp): its likelihood
// is the samples' with the model's errors correlated across them, and what the samples share
// (the offset c) cancels from a ratio of their G_s.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "analytic_offset_family.hpp"
#include "analytic_viscosity_model.hpp"
#include "calibration/direct_fit.hpp"
#include "calibration/joint_likelihood.hpp"
#include "calibration/joint_posterior.hpp"
#include "calibration/mcmc_calibration.hpp"
#include "calibration/sample_comparison.hpp"
#include "synthetic_sample.hpp"

using namespace rbcal::calibration;

namespace {

JointSample joint_sample_of(const SampleData& s, const std::string& name) {
  return {name, s.points, s.plasma.eta0, s.plasma.standard_error};
}

SampleData drawn(const rbcal::surrogate::ViscosityModel& model, double shear_modulus, std::mt19937_64& rng) {
  test_models::SyntheticDesign design;
  design.shear_modulus = shear_modulus;
  design.shear_rates = {10.0, 22.0, 46.0, 100.0, 220.0};
  return test_models::synthetic_sample(model, design, rng);
}

}  // namespace

// Two samples' joint likelihood is the sum of theirs when the model's errors are independent
// (the analytic model), and not when they share a term: with a box correction every point's
// error carries the same beta, so the covariance between the two samples' points is the box's
// rank-one term g_i g_j sd_beta^2, as within one sample.
TEST(JointPosterior, LikelihoodCouplesTheSamplesThroughTheModelsSharedErrors) {
  const test_models::AnalyticViscosityModel model;
  std::mt19937_64 rng(3);
  const SampleData a = drawn(model, 0.5e-6, rng), b = drawn(model, 1.0e-6, rng);
  const ViscosityObservation at{&model, a.plasma.eta0, kDefaultCellRadius, {}};
  const double joint = joint_log_likelihood(joint_residuals(
      model, {}, kDefaultCellRadius,
      {{&a.points, 0.6e-6, 5.0, a.plasma.eta0, false}, {&b.points, 0.9e-6, 5.0, b.plasma.eta0, false}}));
  const double separate = joint_log_likelihood(joint_residuals(at, a.points, 0.6e-6, 5.0, false)) +
                          joint_log_likelihood(joint_residuals(at, b.points, 0.9e-6, 5.0, false));
  EXPECT_NEAR(joint, separate, 1e-9 * std::abs(separate));

  const auto boxed = test_models::analytic_offset_family(1.0, 0.75, 0.15, rbcal::surrogate::BoxCorrectionPrior{0.1, 0.05});
  const JointResiduals both = joint_residuals(
      boxed, {{"offset_c", 0.8}}, kDefaultCellRadius,
      {{&a.points, 0.6e-6, 5.0, a.plasma.eta0, false}, {&b.points, 0.9e-6, 5.0, b.plasma.eta0, false}});
  const Eigen::MatrixXd sigma = both.covariance.dense();
  const std::size_t i = 3, j = a.points.size() + 7;  // a point of each sample
  ASSERT_GT(sigma.rows(), static_cast<Eigen::Index>(j));
  const auto g = [&](const RelativeViscosityPoint& p, double shear_modulus) {
    const double plain = boxed.predict_at_offset(p.phi, capillary_number(a.plasma.eta0, p.shear_rate, kDefaultCellRadius, shear_modulus), 5.0, 0.8).eta_re;
    return std::pow(plain, 1.1) * std::log(plain);
  };
  EXPECT_NEAR(sigma(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)),
              0.05 * 0.05 * g(a.points[i], 0.6e-6) * g(b.points[j - a.points.size()], 0.9e-6), 1e-12);
}

// A family whose offset c and G_s are confounded (c0 = 2 + (c - 0.75): a shift of c moves ln
// eta_re exactly as a shift of ln G_s by 3.3 times it), so that each sample's G_s is known only
// as well as c's prior allows, while their ratio is known from the data. Truth: G_s 0.5 and
// 1.0 uN/m, ratio 0.5, at c = 0.75.
TEST(JointPosterior, RatioIntervalCoversTheTruthAndIsNarrowerThanOneSampleAtATime) {
  const auto family = test_models::analytic_offset_family(1.0);
  McmcOptions sampler;
  sampler.threads = 1;
  DirectFitOptions fit_options;
  JointPosteriorOptions options;
  int covered = 0, narrower = 0;
  double width_joint = 0.0, width_separate = 0.0;
  const int seeds = 30;
  for (int seed = 0; seed < seeds; ++seed) {
    std::mt19937_64 rng(100 + seed);
    const SampleData a = drawn(family, 0.5e-6, rng), b = drawn(family, 1.0e-6, rng);
    const std::vector<DirectFitResult> fits = {fit_direct(a, family, fit_options), fit_direct(b, family, fit_options)};
    sampler.seed = 500 + seed;
    const JointCalibration joint =
        calibrate_joint({joint_sample_of(a, "a"), joint_sample_of(b, "b")}, fits, family, options, sampler);
    const ShearModulusRatio r = joint.ratio(0, 1);
    if (r.interval.lower <= 0.5 && 0.5 <= r.interval.upper) ++covered;
    // One sample at a time: each with its own offset, the ratio of independent draws.
    McmcCalibrationOptions one;
    one.sampler = sampler;
    const McmcCalibration ma = calibrate_mcmc(a, family, one), mb = calibrate_mcmc(b, family, one);
    const ShearModulusRatio s = compare_shear_moduli(ma.shear_modulus_draws(), mb.shear_modulus_draws());
    const double wj = std::log(r.interval.upper / r.interval.lower), ws = std::log(s.interval.upper / s.interval.lower);
    width_joint += wj / seeds;
    width_separate += ws / seeds;
    if (wj < ws) ++narrower;
  }
  std::printf("joint ratio interval covers 0.5 in %d of %d seeds; mean width in ln: joint %.3f, one at a time %.3f "
              "(%.1f times narrower)\n",
              covered, seeds, width_joint, width_separate, width_separate / width_joint);
  EXPECT_GE(covered, 27);  // at least 90 %
  EXPECT_EQ(narrower, seeds);
  // c's prior sd 0.15 alone puts sqrt(2) x 0.15 / 0.3 = 0.71 in the one-at-a-time ln ratio's sd
  // (a 95 % width near 2.8); the joint ratio sees only the measurement errors.
  EXPECT_LT(width_joint, 0.5 * width_separate);
}

// Hierarchical: mu near the samples' common G_s, tau small when they agree.
TEST(JointPosterior, HierarchicalLayerReportsThePopulation) {
  const test_models::AnalyticViscosityModel model;
  std::mt19937_64 rng(9);
  std::vector<JointSample> samples;
  std::vector<DirectFitResult> fits;
  for (int i = 0; i < 4; ++i) {
    const SampleData s = drawn(model, 0.8e-6, rng);
    samples.push_back(joint_sample_of(s, "s" + std::to_string(i)));
    fits.push_back(fit_direct(s, model, {}));
  }
  JointPosteriorOptions options;
  options.hierarchical = true;
  McmcOptions sampler;
  sampler.threads = 1;
  const JointCalibration joint = calibrate_joint(samples, fits, model, options, sampler);
  ASSERT_TRUE(joint.mcmc.converged) << joint.mcmc.stop_reason;
  EXPECT_TRUE(joint.hierarchical);
  EXPECT_EQ(joint.parameter_names.back(), "ln_tau");
  EXPECT_EQ(joint.parameter_names.front(), "z_G_s[s0]");
  EXPECT_LT(joint.mu_interval.lower, 0.8e-6);
  EXPECT_GT(joint.mu_interval.upper, 0.8e-6);
  EXPECT_LT(joint.tau_median, 0.2);  // four samples of one G_s
}

TEST(JointPosterior, NamesItsParametersAndRefusesOneSample) {
  const test_models::AnalyticViscosityModel model;
  std::mt19937_64 rng(1);
  const SampleData a = drawn(model, 0.5e-6, rng);
  JointPosteriorOptions options;
  options.posterior.setup.fit_lambda = true;
  options.shared_lambda = true;
  const JointLogPosterior p(model, {joint_sample_of(a, "a"), joint_sample_of(a, "b")}, options);
  EXPECT_EQ(p.parameter_names(), (std::vector<std::string>{"ln_G_s[a]", "ln_G_s[b]", "ln_lambda"}));
  EXPECT_EQ(p.lambda_index(0), p.lambda_index(1));
  options.shared_lambda = false;
  const JointLogPosterior q(model, {joint_sample_of(a, "a"), joint_sample_of(a, "b")}, options);
  EXPECT_EQ(q.parameter_names(), (std::vector<std::string>{"ln_G_s[a]", "ln_G_s[b]", "ln_lambda[a]", "ln_lambda[b]"}));
  EXPECT_THROW(JointLogPosterior(model, {joint_sample_of(a, "a")}, options), std::invalid_argument);
}
