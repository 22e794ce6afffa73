// The log posterior term by term: the Gaussian likelihood with its three variance parts, the
// normalised priors, their supports, and the optional truncation to the model's range.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "analytic_offset_family.hpp"
#include "analytic_viscosity_model.hpp"
#include "calibration/posterior.hpp"

using namespace rbcal::calibration;
using rbcal::calibration::test_models::AnalyticViscosityModel;

namespace {

RelativeViscosityPoint point(double phi, double rate, double eta_re, double sd) {
  RelativeViscosityPoint p;
  p.phi = phi;
  p.shear_rate = rate;
  p.eta_re = eta_re;
  p.eta_re_sd = sd;
  return p;
}

}  // namespace

TEST(Posterior, LikelihoodAddsMeasurementModelAndDiscrepancyVariances) {
  AnalyticViscosityModel model;
  const double eta0 = 1.5e-3, g_s = 1e-6;
  const auto data = point(0.3, 20.0, 2.4, 0.05);
  PosteriorOptions options;
  options.fit_discrepancy = true;
  const LogPosterior posterior(model, eta0, {data}, options);
  ASSERT_EQ(posterior.dimension(), 2);
  EXPECT_EQ(posterior.parameter_names()[1], "ln_sigma_d");
  const double sigma_d = 0.07;
  const Eigen::Vector2d theta(std::log(g_s), std::log(sigma_d));

  const auto p = model.predict(0.3, capillary_number(eta0, 20.0, kDefaultCellRadius, g_s), 5.0);
  const double variance = 0.05 * 0.05 + p.sd * p.sd + std::pow(sigma_d * p.eta_re, 2);
  const double expected = -0.5 * (std::pow(2.4 - p.eta_re, 2) / variance + std::log(2 * std::numbers::pi * variance));
  EXPECT_NEAR(posterior.log_likelihood(theta), expected, 1e-12);
  EXPECT_NEAR(posterior(theta), posterior.log_prior(theta) + expected, 1e-12);
}

TEST(Posterior, PriorsAreNormalisedAndBounded) {
  AnalyticViscosityModel model;
  PosteriorOptions options;
  options.setup.fit_lambda = true;
  options.fit_discrepancy = true;
  const LogPosterior posterior(model, 1.5e-3, {point(0.2, 10.0, 1.8, 0.05)}, options);
  ASSERT_EQ(posterior.lambda_index(), 1);
  ASSERT_EQ(posterior.discrepancy_index(), 2);
  // Uniform in ln G_s over [1e-8, 1e-3], in ln lambda over the model's [0.1, 20], normal in ln sigma_d.
  const double ln_sigma = std::log(0.05);
  const Eigen::Vector3d inside(std::log(1e-6), std::log(5.0), ln_sigma);
  const double expected = -std::log(std::log(1e-3 / 1e-8)) - std::log(std::log(20.0 / 0.1)) -
                          0.5 * std::log(2.0 * std::numbers::pi);
  EXPECT_NEAR(posterior.log_prior(inside), expected, 1e-12);
  EXPECT_NEAR(posterior.log_prior(Eigen::Vector3d(inside(0), inside(1), ln_sigma + 1.0)), expected - 0.5, 1e-12);
  EXPECT_TRUE(std::isinf(posterior(Eigen::Vector3d(std::log(2e-3), std::log(5.0), ln_sigma))));
  EXPECT_TRUE(std::isinf(posterior(Eigen::Vector3d(std::log(1e-6), std::log(30.0), ln_sigma))));
  EXPECT_DOUBLE_EQ(posterior.lambda(inside), 5.0);
}

TEST(Posterior, IsTruncatedToTheModelsRangeByDefault) {
  AnalyticViscosityModel model;  // Ca in [0.003, 20]
  const double eta0 = 1.5e-3;
  const auto data = point(0.2, 100.0, 1.8, 0.05);
  // Ca = eta0 * 100 * 4e-6 / G_s: G_s = 1e-6 gives Ca 0.6 (inside), G_s = 1e-8 gives Ca 60 (outside).
  PosteriorOptions options;
  const LogPosterior truncated(model, eta0, {data}, options);
  options.reject_outside_model_range = false;
  const LogPosterior trusting(model, eta0, {data}, options);
  const Eigen::VectorXd inside = Eigen::VectorXd::Constant(1, std::log(1e-6));
  const Eigen::VectorXd outside = Eigen::VectorXd::Constant(1, std::log(1.2e-8));
  EXPECT_DOUBLE_EQ(truncated(inside), trusting(inside));
  EXPECT_TRUE(std::isfinite(trusting(outside)));
  EXPECT_TRUE(std::isinf(truncated(outside)));
}

TEST(Posterior, PlasmaViscosityAsNuisanceParameter) {
  AnalyticViscosityModel model;
  const double eta0_hat = 1.5e-3, se = 0.03e-3, g_s = 1e-6;
  auto data = point(0.3, 20.0, 2.4, 0.06);
  data.viscosity = 3.7e-3;
  data.viscosity_se = 0.05e-3;
  const LogPosterior without_se(model, eta0_hat, {data}, {});
  EXPECT_EQ(without_se.plasma_viscosity_index(), -1);  // no standard error: eta0 stays fixed
  const LogPosterior posterior(model, eta0_hat, {data}, {}, se);
  ASSERT_EQ(posterior.plasma_viscosity_index(), 1);
  EXPECT_EQ(posterior.parameter_names()[1], "ln_eta0");

  const double eta0 = 1.53e-3;
  const Eigen::Vector2d theta(std::log(g_s), std::log(eta0));
  EXPECT_DOUBLE_EQ(posterior.plasma_viscosity(theta), eta0);
  // Likelihood with eta_re = eta / eta0, sd = se(eta) / eta0, and Ca from that eta0.
  const auto p = model.predict(0.3, capillary_number(eta0, 20.0, kDefaultCellRadius, g_s), 5.0);
  const double variance = std::pow(0.05e-3 / eta0, 2) + p.sd * p.sd;
  const double expected = -0.5 * (std::pow(3.7e-3 / eta0 - p.eta_re, 2) / variance +
                                  std::log(2 * std::numbers::pi * variance));
  EXPECT_NEAR(posterior.log_likelihood(theta), expected, 1e-12);
  // Prior: ln eta0 ~ N(ln eta0_hat, se / eta0_hat), on top of the uniform prior of ln G_s.
  const double s = se / eta0_hat, z = std::log(eta0 / eta0_hat) / s;
  const double expected_prior =
      -std::log(std::log(1e-3 / 1e-8)) - 0.5 * z * z - std::log(s) - 0.5 * std::log(2 * std::numbers::pi);
  EXPECT_NEAR(posterior.log_prior(theta), expected_prior, 1e-12);
}

// A model with the immersed boundary's offset adds c last, with the truncated normal prior
// normalised over the family's offsets, and predicts each point at theta's c.
TEST(Posterior, OffsetOfAFamilyHasATruncatedNormalPrior) {
  const auto family = test_models::analytic_offset_family(1.0, 0.7, 0.2);
  const double eta0 = 1.5e-3, g_s = 1e-6;
  const auto data = point(0.3, 20.0, 2.4, 0.05);
  const LogPosterior posterior(family, eta0, {data});
  ASSERT_EQ(posterior.dimension(), 2);
  EXPECT_EQ(posterior.nuisance_index(), 1);
  EXPECT_EQ(posterior.parameter_names()[1], "offset_c");
  Eigen::Vector2d theta(std::log(g_s), 0.3);
  EXPECT_EQ(posterior.log_prior(theta), -std::numeric_limits<double>::infinity());  // below the first member
  theta(1) = 1.2;
  EXPECT_EQ(posterior.log_prior(theta), -std::numeric_limits<double>::infinity());  // beyond the last
  // exp(log prior) integrates to 1 over c (the G_s part is the uniform density on ln G_s).
  const double ln_range = std::log(1e-3 / 1e-8);
  double integral = 0.0;
  const int n = 20000;
  for (int k = 0; k <= n; ++k) {
    theta(1) = 0.45 + 0.6 * k / n;
    const double w = (k == 0 || k == n) ? 0.5 : 1.0;
    integral += w * std::exp(posterior.log_prior(theta)) * ln_range * 0.6 / n;
  }
  EXPECT_NEAR(integral, 1.0, 1e-6);
  // The likelihood uses the family at theta's c.
  theta(1) = 0.93;
  const auto p = family.predict_at_offset(0.3, capillary_number(eta0, 20.0, kDefaultCellRadius, g_s), 5.0, 0.93);
  const double v = 0.05 * 0.05 + p.sd * p.sd;
  EXPECT_NEAR(posterior.log_likelihood(theta),
              -0.5 * (std::pow(2.4 - p.eta_re, 2) / v + std::log(2.0 * std::numbers::pi * v)), 1e-12);
  PosteriorOptions at_mean;
  at_mean.model_nuisances_as_parameters = false;
  EXPECT_EQ(LogPosterior(family, eta0, {data}, at_mean).dimension(), 1);
}

// The box correction enters the likelihood as an error common to every point: with members whose
// errors are independent, Sigma = D + sd_beta^2 g g^T (g_i = d eta_i / d beta), whose inverse and
// determinant the Sherman-Morrison formula and the matrix determinant lemma give in closed form,
// independently of the Cholesky factorisation the posterior uses.
TEST(Posterior, BoxCorrectionIsARankOneErrorCommonToEveryPoint) {
  const double box_sd = 0.07, eta0 = 1.5e-3, g_s = 1e-6;
  const auto family = test_models::analytic_offset_family(1.0, 0.75, 0.15, rbcal::surrogate::BoxCorrectionPrior{0.1, box_sd});
  const auto plain = test_models::analytic_offset_family(1.0, 0.75, 0.15);
  const std::vector<RelativeViscosityPoint> data = {point(0.2, 5.0, 2.0, 0.05), point(0.3, 50.0, 2.5, 0.06),
                                                    point(0.4, 500.0, 3.1, 0.08)};
  const LogPosterior posterior(family, eta0, data, {});
  ASSERT_EQ(posterior.dimension(), 2);  // ln G_s and the offset: beta is not a parameter
  const double offset = 0.8;
  const Eigen::Vector2d theta(std::log(g_s), offset);
  const double s2 = box_sd * box_sd;
  double quadratic = 0.0, log_det = 0.0, g_d_r = 0.0, g_d_g = 0.0, independent_sum = 0.0;
  for (const auto& x : data) {
    const double ca = capillary_number(eta0, x.shear_rate, kDefaultCellRadius, g_s);
    const auto p = plain.predict(x.phi, ca, 5.0, {{"offset_c", offset}});
    const double eta = std::pow(p.eta_re, 1.1);          // at beta's mean
    const double sd = 1.1 * eta / p.eta_re * p.sd;       // the chain rule
    const double g = eta * std::log(p.eta_re);           // d eta / d beta
    const double d = x.eta_re_sd * x.eta_re_sd + sd * sd;
    const double r = x.eta_re - eta;
    quadratic += r * r / d;
    log_det += std::log(d);
    g_d_r += g * r / d;
    g_d_g += g * g / d;
    independent_sum += r * r / (d + s2 * g * g) + std::log(d + s2 * g * g);
  }
  const double expected = -0.5 * (quadratic - s2 * g_d_r * g_d_r / (1.0 + s2 * g_d_g) + log_det +
                                  std::log(1.0 + s2 * g_d_g) + 3.0 * std::log(2.0 * std::numbers::pi));
  EXPECT_NEAR(posterior.log_likelihood(theta), expected, 1e-10);
  // The same variances taken as independent per point give another likelihood.
  const double independent = -0.5 * (independent_sum + 3.0 * std::log(2.0 * std::numbers::pi));
  EXPECT_GT(std::abs(posterior.log_likelihood(theta) - independent), 1e-3);
}
