// The MCMC calibration end to end: stop criterion, reproducibility with a fixed seed (also across
// thread counts), coverage of the credible interval over replications (cheap fixed-length runs),
// posterior-predictive bands, and the comparison of two samples.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "analytic_offset_family.hpp"
#include "analytic_viscosity_model.hpp"
#include "calibration/mcmc_calibration.hpp"
#include "calibration/predictive_bands.hpp"
#include "calibration/sample_comparison.hpp"
#include "synthetic_sample.hpp"

using namespace rbcal::calibration;
using rbcal::calibration::test_models::AnalyticViscosityModel;

TEST(McmcCalibration, StopsWhenConvergedAndIsReproducible) {
  AnalyticViscosityModel model;
  test_models::SyntheticDesign design;
  std::mt19937_64 rng(77);
  const SampleData sample = test_models::synthetic_sample(model, design, rng);
  McmcCalibrationOptions options;
  options.posterior.fit_discrepancy = true;
  options.sampler.threads = 1;
  const McmcCalibration a = calibrate_mcmc(sample, model, options);
  ASSERT_TRUE(a.mcmc.converged) << a.mcmc.stop_reason;
  EXPECT_LT(a.mcmc.parameters[0].rhat, 1.01);
  EXPECT_GE(a.mcmc.parameters[0].bulk_ess, 1000.0);
  EXPECT_LT(a.mcmc.steps, options.sampler.max_steps);
  EXPECT_GT(a.mcmc.acceptance_fraction, 0.2);
  EXPECT_LT(a.mcmc.acceptance_fraction, 0.9);
  EXPECT_LT(a.shear_modulus_interval.lower, a.shear_modulus_median);
  EXPECT_GT(a.shear_modulus_interval.upper, a.shear_modulus_median);
  EXPECT_EQ(static_cast<int>(a.mcmc.chains.size()), options.sampler.chains);

  options.sampler.threads = 2;
  const McmcCalibration b = calibrate_mcmc(sample, model, options);
  EXPECT_EQ(a.mcmc.steps, b.mcmc.steps);
  EXPECT_EQ(a.mcmc.parameter_draws(0), b.mcmc.parameter_draws(0));

  options.sampler.seed += 1;
  const McmcCalibration c = calibrate_mcmc(sample, model, options);
  EXPECT_NE(a.mcmc.parameter_draws(0), c.mcmc.parameter_draws(0));
  // Different seeds agree within Monte Carlo error.
  const double mcse = a.mcmc.parameters[0].sd / std::sqrt(a.mcmc.parameters[0].bulk_ess);
  EXPECT_NEAR(a.mcmc.parameters[0].mean, c.mcmc.parameters[0].mean, 6.0 * mcse);

  // A start fit made beforehand with the same options (the direct method's) gives the same run.
  options.sampler.seed -= 1;
  DirectFitOptions start = options.start_fit;
  start.setup = options.posterior.setup;
  const DirectFitResult fitted = fit_direct(sample, model, start);
  options.fitted_start = &fitted;
  const McmcCalibration d = calibrate_mcmc(sample, model, options);
  EXPECT_EQ(a.mcmc.parameter_draws(0), d.mcmc.parameter_draws(0));
}

TEST(McmcCalibration, CredibleIntervalCoversTheTruth) {
  // Cheap fixed-length runs (no convergence check) over 100 synthetic replications, with eta0
  // measured with a 2.1 % error (a nuisance parameter of the posterior).
  AnalyticViscosityModel model;
  test_models::SyntheticDesign design;
  design.plasma_relative_standard_error = 0.021;
  McmcCalibrationOptions options;
  options.sampler.chains = 2;
  options.sampler.walkers = 8;
  options.sampler.min_steps = 400;
  options.sampler.max_steps = 400;
  options.sampler.threads = 1;
  constexpr int kReplications = 100;
  std::mt19937_64 rng(4242);
  int covered = 0;
  double sum_error = 0.0, sum_squared = 0.0;
  for (int r = 0; r < kReplications; ++r) {
    const SampleData sample = test_models::synthetic_sample(model, design, rng);
    options.sampler.seed = 1000 + r;
    const McmcCalibration result = calibrate_mcmc(sample, model, options);
    ASSERT_EQ(result.mcmc.parameter_names.back(), "ln_eta0");
    const double error = std::log(result.shear_modulus_median / design.shear_modulus);
    sum_error += error;
    sum_squared += error * error;
    if (result.shear_modulus_interval.lower <= design.shear_modulus &&
        design.shear_modulus <= result.shear_modulus_interval.upper)
      ++covered;
  }
  EXPECT_GE(covered, 90);
  EXPECT_LE(covered, 99);
  const double bias = sum_error / kReplications;
  const double spread = std::sqrt(sum_squared / kReplications - bias * bias);
  EXPECT_LT(std::abs(bias), 3.0 * spread / std::sqrt(static_cast<double>(kReplications)));
}

TEST(McmcCalibration, PredictiveBandsFollowTheTrueCurve) {
  AnalyticViscosityModel model;
  test_models::SyntheticDesign design;
  std::mt19937_64 rng(88);
  const SampleData sample = test_models::synthetic_sample(model, design, rng);
  McmcCalibrationOptions options;
  options.sampler.threads = 1;
  const McmcCalibration result = calibrate_mcmc(sample, model, options);
  PredictiveBandOptions band_options;
  band_options.shear_rate_points = 20;
  band_options.max_draws = 400;
  const auto bands = predictive_bands(model, result, band_options);
  ASSERT_EQ(bands.size(), design.phis.size());
  int inside = 0, total = 0;
  for (const auto& band : bands) {
    ASSERT_EQ(band.shear_rate.size(), 20u);
    EXPECT_NEAR(band.shear_rate.front(), design.shear_rates.front(), 1e-12);
    EXPECT_NEAR(band.shear_rate.back(), design.shear_rates.back(), 1e-9);
    for (std::size_t i = 0; i < band.shear_rate.size(); ++i) {
      EXPECT_LT(band.lower[i], band.median[i]);
      EXPECT_GT(band.upper[i], band.median[i]);
      const double ca = capillary_number(design.plasma_viscosity, band.shear_rate[i], kDefaultCellRadius,
                                         design.shear_modulus);
      const double truth = design.plasma_viscosity * model.predict(band.phi, ca, design.lambda).eta_re;
      inside += band.lower[i] <= truth && truth <= band.upper[i];
      ++total;
    }
    // Shear thinning: the band's median falls with shear rate.
    EXPECT_GT(band.median.front(), band.median.back());
  }
  EXPECT_GE(inside, total * 9 / 10);
  // Without the model's error the band is narrower (only the uncertainty of G_s).
  band_options.include_model_error = false;
  const auto narrow = predictive_bands(model, result, band_options);
  EXPECT_LT(narrow[0].upper[5] - narrow[0].lower[5], bands[0].upper[5] - bands[0].lower[5]);
}

TEST(McmcCalibration, RatioOfTwoSamplesShearModuli) {
  AnalyticViscosityModel model;
  test_models::SyntheticDesign intact_design, hard_design;
  intact_design.shear_modulus = 0.55e-6;
  hard_design.shear_modulus = 2.43e-6;  // the seed study's hardened / intact values
  hard_design.shear_rates = {5.0, 10.0, 22.0, 46.0, 100.0, 220.0, 460.0, 1000.0};
  std::mt19937_64 rng(99);
  const SampleData intact = test_models::synthetic_sample(model, intact_design, rng);
  const SampleData hard = test_models::synthetic_sample(model, hard_design, rng);
  McmcCalibrationOptions options;
  options.sampler.threads = 1;
  const McmcCalibration a = calibrate_mcmc(intact, model, options);
  const McmcCalibration b = calibrate_mcmc(hard, model, options);
  const ShearModulusRatio ratio = compare_shear_moduli(b.shear_modulus_draws(), a.shear_modulus_draws());
  const double true_ratio = hard_design.shear_modulus / intact_design.shear_modulus;
  EXPECT_LT(ratio.interval.lower, true_ratio);
  EXPECT_GT(ratio.interval.upper, true_ratio);
  EXPECT_GT(ratio.probability_greater_than_one, 0.999);
  // Independent posteriors: ln ratio has the variance of the sum.
  const double sd_a = a.mcmc.parameters[0].sd, sd_b = b.mcmc.parameters[0].sd;
  std::vector<double> log_ratio;
  for (double r : ratio.draws) log_ratio.push_back(std::log(r));
  double mean = 0.0, squares = 0.0;
  for (double x : log_ratio) mean += x;
  mean /= log_ratio.size();
  for (double x : log_ratio) squares += (x - mean) * (x - mean);
  EXPECT_NEAR(std::sqrt(squares / log_ratio.size()) / std::hypot(sd_a, sd_b), 1.0, 0.05);
}

// An offset the data cannot see (every member the same) keeps its prior: normal(0.75, 0.15)
// truncated to [0.45, 1.05], whose median is 0.75 and whose 95 % central interval is
// 0.75 -+ 1.678 x 0.15 (the 2.5 % point of a normal cut at +-2 sd: Phi^-1(Phi(-2) + 0.025 x 0.9545)).
// An offset the data can see (slope 1) widens the G_s interval against the offset held at its mean.
TEST(McmcCalibration, OffsetKeepsItsPriorWhenUnseenAndWidensTheIntervalWhenSeen) {
  test_models::SyntheticDesign design;
  std::mt19937_64 rng(31);
  const auto blind = test_models::analytic_offset_family(0.0);
  const SampleData sample = test_models::synthetic_sample(blind, design, rng);
  McmcCalibrationOptions options;
  options.sampler.threads = 1;
  const McmcCalibration unseen = calibrate_mcmc(sample, blind, options);
  ASSERT_TRUE(unseen.mcmc.converged) << unseen.mcmc.stop_reason;
  const int k = static_cast<int>(unseen.mcmc.parameters.size()) - 1;
  ASSERT_EQ(unseen.mcmc.parameters[k].name, "offset_c");
  ASSERT_EQ(unseen.nuisances.size(), 1u);
  const double ess = unseen.mcmc.parameters[k].bulk_ess;
  ASSERT_GT(ess, 300.0);
  const double mass = 0.9545, density_median = 0.3989 / (0.15 * mass), density_tail = 0.0975 / (0.15 * mass);
  const NuisanceEstimate& c = unseen.nuisances[0];
  EXPECT_NEAR(c.value, 0.75, 4.0 * std::sqrt(0.25 / ess) / density_median);
  EXPECT_NEAR(c.interval.lower, 0.75 - 1.678 * 0.15, 4.0 * std::sqrt(0.025 * 0.975 / ess) / density_tail);
  EXPECT_NEAR(c.interval.upper, 0.75 + 1.678 * 0.15, 4.0 * std::sqrt(0.025 * 0.975 / ess) / density_tail);

  const auto seen = test_models::analytic_offset_family(1.0);
  const SampleData seen_sample = test_models::synthetic_sample(seen, design, rng);
  const McmcCalibration free_offset = calibrate_mcmc(seen_sample, seen, options);
  options.posterior.model_nuisances_as_parameters = false;
  const McmcCalibration held = calibrate_mcmc(seen_sample, seen, options);
  ASSERT_TRUE(free_offset.mcmc.converged && held.mcmc.converged);
  EXPECT_TRUE(held.nuisances.empty());
  const auto width = [](const Interval& i) { return std::log(i.upper / i.lower); };
  EXPECT_GT(width(free_offset.shear_modulus_interval), 1.3 * width(held.shear_modulus_interval));
}

// The posterior predictive check: on data of the model itself about 5 % of the points fall
// outside their 95 % predictive interval and no disagreement is flagged; when every point of
// the densest hematocrit is raised by 30 % (a model that cannot follow the data), those points
// fall outside and the check says so.
#include "calibration/posterior_predictive_check.hpp"

TEST(PosteriorPredictiveCheck, QuietOnTheModelsOwnDataAndFlagsDataItCannotFollow) {
  AnalyticViscosityModel model;
  test_models::SyntheticDesign design;
  std::mt19937_64 rng(91);
  SampleData sample = test_models::synthetic_sample(model, design, rng);
  McmcCalibrationOptions options;
  options.sampler.threads = 1;
  const McmcCalibration fair = calibrate_mcmc(sample, model, options);
  const PredictiveCheck quiet = posterior_predictive_check(model, fair);
  ASSERT_EQ(quiet.points.size(), sample.points.size());
  EXPECT_LE(quiet.outside(), 5) << quiet.line();  // 1.6 expected of 32
  EXPECT_FALSE(quiet.disagrees()) << quiet.line();
  for (const auto& p : quiet.points) EXPECT_TRUE(p.pit >= 0.0 && p.pit <= 1.0);

  for (auto& p : sample.points)
    if (p.phi == 0.4) {
      p.eta_re *= 1.3;
      p.eta_re_sd *= 1.3;
    }
  const McmcCalibration bent = calibrate_mcmc(sample, model, options);
  const PredictiveCheck flagged = posterior_predictive_check(model, bent);
  EXPECT_GE(flagged.outside(), 6) << flagged.line();
  EXPECT_TRUE(flagged.disagrees()) << flagged.line();
  EXPECT_EQ(flagged.to_json()["points_outside"], flagged.outside());
}
