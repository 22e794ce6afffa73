// The seed study's alpha method: the exp(alpha phi) fit itself, and recovery of a known G_s from
// synthetic data of an analytic model whose alpha falls with Ca.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "analytic_viscosity_model.hpp"
#include "calibration/alpha_method.hpp"
#include "synthetic_sample.hpp"

using namespace rbcal::calibration;
using rbcal::calibration::test_models::AnalyticViscosityModel;

TEST(ExponentialAlphaFit, ExactDataGiveAlphaAndUnitRSquared) {
  const std::vector<double> phi = {0.1, 0.2, 0.4, 0.6, 0.8};
  std::vector<double> eta;
  for (double p : phi) eta.push_back(std::exp(2.7 * p));
  for (auto space : {AlphaFitSpace::linear, AlphaFitSpace::log_through_origin}) {
    const auto fit = fit_exponential_alpha(phi, eta, space);
    EXPECT_NEAR(fit.alpha, 2.7, 1e-10);
    EXPECT_NEAR(fit.r_squared, 1.0, 1e-12);
    EXPECT_EQ(fit.points, 5);
  }
}

TEST(ExponentialAlphaFit, LinearSpaceFitMinimisesTheSeedStudysCost) {
  // Least squares on [eta_re - exp(alpha phi)]: the cost is stationary at the estimate and the
  // estimate differs from the log-space one on scattered data.
  const std::vector<double> phi = {0.1, 0.2, 0.4, 0.6, 0.8};
  const std::vector<double> eta = {1.35, 1.6, 3.2, 4.6, 9.5};
  const auto fit = fit_exponential_alpha(phi, eta, AlphaFitSpace::linear);
  auto cost = [&](double a) {
    double c = 0.0;
    for (std::size_t i = 0; i < phi.size(); ++i) c += std::pow(eta[i] - std::exp(a * phi[i]), 2);
    return c;
  };
  EXPECT_LT(cost(fit.alpha), cost(fit.alpha + 1e-4));
  EXPECT_LT(cost(fit.alpha), cost(fit.alpha - 1e-4));
  const auto log_fit = fit_exponential_alpha(phi, eta, AlphaFitSpace::log_through_origin);
  EXPECT_GT(std::abs(fit.alpha - log_fit.alpha), 1e-3);
  EXPECT_GT(fit.r_squared, 0.9);
  EXPECT_LT(fit.r_squared, 1.0);
}

TEST(AlphaMethod, LevelCrossingsInterpolateLinearly) {
  const auto x = level_crossings({0.0, 1.0, 2.0, 3.0}, {3.0, 1.0, 2.0, 0.0}, 1.5);
  ASSERT_EQ(x.size(), 3u);
  EXPECT_NEAR(x[0], 0.75, 1e-15);
  EXPECT_NEAR(x[1], 1.5, 1e-15);
  EXPECT_NEAR(x[2], 2.25, 1e-15);
  EXPECT_TRUE(level_crossings({0.0, 1.0}, {1.0, 2.0}, 5.0).empty());
}

TEST(AlphaMethod, RecoversKnownShearModulus) {
  AnalyticViscosityModel model;  // alpha = 2 - 0.3 ln Ca + 0.1 ln lambda: exact exp(alpha phi) form
  model.c3 = 0.0;
  test_models::SyntheticDesign design;
  design.shear_modulus = 0.55e-6;
  design.relative_measurement_sd = 0.003;
  design.add_model_noise = false;
  design.phis = {0.1, 0.2, 0.4, 0.6};  // like the seed study's hematocrits
  std::mt19937_64 rng(42);
  const SampleData sample = test_models::synthetic_sample(model, design, rng);

  const AlphaMethodResult result = estimate_by_alpha_matching(sample, model);
  ASSERT_EQ(result.measured.size(), design.shear_rates.size());
  for (const auto& m : result.measured) EXPECT_GT(m.fit.r_squared, 0.99);
  // alpha falls with shear rate (shear thinning), as in the seed study's Fig. 5(b).
  EXPECT_GT(result.measured.front().fit.alpha, result.measured.back().fit.alpha + 0.5);
  ASSERT_EQ(result.shear_modulus.count, static_cast<int>(design.shear_rates.size()));
  for (const auto& match : result.per_shear_rate) {
    ASSERT_TRUE(match.matched) << match.message;
    EXPECT_NEAR(match.shear_modulus / design.shear_modulus, 1.0, 0.1);
    EXPECT_NEAR(match.capillary_number,
                capillary_number(design.plasma_viscosity, match.shear_rate, kDefaultCellRadius, design.shear_modulus),
                0.1 * match.capillary_number);
  }
  EXPECT_NEAR(result.shear_modulus.mean / design.shear_modulus, 1.0, 0.03);
  // The seed study's direction (Ca -> shear rate) agrees; Ca whose shear rate lies beyond the
  // measured ones are reported as unmatched, not extrapolated.
  EXPECT_GT(result.shear_modulus_per_ca.count, 3);
  EXPECT_NEAR(result.shear_modulus_per_ca.mean / design.shear_modulus, 1.0, 0.05);
  for (const auto& match : result.per_capillary_number)
    if (!match.matched) {
      EXPECT_FALSE(match.message.empty());
    }
}

TEST(AlphaMethod, ShearRatesBeyondTheModelAreSkippedWithAMessage) {
  AnalyticViscosityModel model;
  model.box.ca_min = 0.05;  // the lowest shear rates map below the model's Ca range
  test_models::SyntheticDesign design;
  design.add_model_noise = false;
  design.relative_measurement_sd = 0.0;
  std::mt19937_64 rng(1);
  const SampleData sample = test_models::synthetic_sample(model, design, rng);
  const AlphaMethodResult result = estimate_by_alpha_matching(sample, model);
  int unmatched = 0;
  for (const auto& match : result.per_shear_rate)
    if (!match.matched) {
      ++unmatched;
      EXPECT_NE(match.message.find("outside the model's alpha"), std::string::npos);
      EXPECT_LT(match.shear_rate, 10.0);
    } else {
      EXPECT_NEAR(match.shear_modulus / design.shear_modulus, 1.0, 1e-3);
    }
  EXPECT_GT(unmatched, 0);
}

// Curves measured at their own shear rates (a digitised figure: no rate shared by two
// hematocrits) are read at the rates of one curve by log-log interpolation inside each curve's
// range; the known G_s comes back as from shared rates. The analytic model is exactly linear in
// ln Ca (so in ln shear rate), where the interpolation is exact.
TEST(AlphaMethod, CurvesAtTheirOwnShearRatesAreInterpolated) {
  AnalyticViscosityModel model;
  model.c3 = 0.0;
  test_models::SyntheticDesign design;
  design.shear_modulus = 0.55e-6;
  design.relative_measurement_sd = 0.0;
  design.add_model_noise = false;
  design.phis = {0.2, 0.3, 0.4};
  SampleData sample;
  std::mt19937_64 rng(5);
  for (std::size_t k = 0; k < design.phis.size(); ++k) {
    test_models::SyntheticDesign one = design;
    one.phis = {design.phis[k]};
    for (double& rate : one.shear_rates) rate *= std::pow(1.07, static_cast<double>(k));  // own rates per curve
    const SampleData part = test_models::synthetic_sample(model, one, rng);
    sample.plasma = part.plasma;
    sample.points.insert(sample.points.end(), part.points.begin(), part.points.end());
  }
  const AlphaMethodResult result = estimate_by_alpha_matching(sample, model);
  EXPECT_TRUE(result.curves_interpolated);
  ASSERT_GE(result.shear_modulus.count, 5);
  EXPECT_NEAR(result.shear_modulus.mean / design.shear_modulus, 1.0, 1e-6);
  // The reference curve's lowest rate (1 1/s) lies below the other curves' ranges: it has one
  // hematocrit, is not extrapolated, and is skipped; the other seven have all three.
  ASSERT_EQ(result.measured.size(), design.shear_rates.size() - 1);
  for (const auto& m : result.measured) EXPECT_EQ(m.fit.points, 3) << m.shear_rate;
  EXPECT_GT(result.measured.front().shear_rate, 1.5);

  AlphaMethodOptions grid;
  grid.model_at_sample_hematocrits = false;  // the same here: the model is exactly exp(alpha phi)
  EXPECT_NEAR(estimate_by_alpha_matching(sample, model, grid).shear_modulus.mean / design.shear_modulus, 1.0, 1e-6);
}
