// The consistency diagnostic: a nuisance in the outer tenth of its range is named with its
// distance from the bound; methods whose 95 % intervals do not overlap are named with z.
#include <gtest/gtest.h>

#include "calibration/calibration_report.hpp"
#include "calibration/consistency_check.hpp"

using namespace rbcal::calibration;

namespace {

SampleReport report_with(double offset, double direct_gs, double alpha_gs, double alpha_se) {
  SampleReport r;
  DirectFitResult d;
  d.covariance_ok = true;
  d.shear_modulus = direct_gs;
  d.shear_modulus_interval = {direct_gs / 1.5, direct_gs * 1.5, 0.95};
  NuisanceEstimate n;
  n.prior = {"offset_c", "immersed-boundary offset", 0.75, 0.15, 0.45, 1.05};
  n.value = offset;
  n.interval = {offset - 0.1, std::min(offset + 0.1, 1.05), 0.95};
  d.nuisances.push_back(n);
  r.direct = d;
  AlphaMethodResult a;
  a.shear_modulus.mean = alpha_gs;
  a.shear_modulus.standard_error = alpha_se;
  a.shear_modulus.count = 9;
  r.alpha = a;
  return r;
}

rbcal::surrogate::ParameterRange range() {
  rbcal::surrogate::ParameterRange g;
  g.lambda_min = 0.1;
  g.lambda_max = 10.0;
  return g;
}

}  // namespace

TEST(ConsistencyCheck, ConsistentWhenInsideAndOverlapping) {
  const ConsistencyCheck c = check_consistency(report_with(0.75, 1.0e-6, 1.1e-6, 0.1e-6), range());
  EXPECT_TRUE(c.consistent());
  EXPECT_TRUE(c.lines().empty());
  ASSERT_EQ(c.comparisons.size(), 1u);
  EXPECT_TRUE(c.comparisons[0].overlap);
  EXPECT_EQ(c.to_json()["consistent"], true);
}

TEST(ConsistencyCheck, NamesANuisanceAtEitherBound) {
  // 1.004 on 0.45 .. 1.05 is 7.6 % of the range from the upper bound; 0.5 is 8.3 % from the lower.
  ConsistencyCheck c = check_consistency(report_with(1.004, 1.0e-6, 1.1e-6, 0.1e-6), range());
  ASSERT_EQ(c.at_bounds.size(), 1u);
  EXPECT_TRUE(c.at_bounds[0].upper);
  EXPECT_NEAR(c.at_bounds[0].distance_share(), 0.046 / 0.6, 1e-12);
  EXPECT_FALSE(c.consistent());
  ASSERT_EQ(c.lines().size(), 1u);
  EXPECT_NE(c.lines()[0].find("offset_c (direct)"), std::string::npos) << c.lines()[0];
  EXPECT_NE(c.lines()[0].find("upper end"), std::string::npos) << c.lines()[0];
  c = check_consistency(report_with(0.5, 1.0e-6, 1.1e-6, 0.1e-6), range());
  ASSERT_EQ(c.at_bounds.size(), 1u);
  EXPECT_FALSE(c.at_bounds[0].upper);
  // 0.52 is 11.7 % from the lower bound: not at it.
  EXPECT_TRUE(check_consistency(report_with(0.52, 1.0e-6, 1.1e-6, 0.1e-6), range()).at_bounds.empty());
}

TEST(ConsistencyCheck, NamesMethodsWhoseIntervalsDoNotOverlap) {
  // direct 0.8 [0.533, 1.2] uN/m against alpha 5.9 +- 1.96 x 0.5: far apart.
  const ConsistencyCheck c = check_consistency(report_with(0.75, 0.8e-6, 5.9e-6, 0.5e-6), range());
  ASSERT_EQ(c.comparisons.size(), 1u);
  EXPECT_FALSE(c.comparisons[0].overlap);
  EXPECT_GT(c.comparisons[0].z, 3.0);
  EXPECT_FALSE(c.consistent());
  ASSERT_EQ(c.lines().size(), 1u);
  EXPECT_NE(c.lines()[0].find("methods disagree"), std::string::npos);
  EXPECT_NE(c.lines()[0].find("alpha"), std::string::npos);
}

TEST(ConsistencyCheck, FittedLambdaIsCheckedOnItsLogRange) {
  SampleReport r = report_with(0.75, 1.0e-6, 1.1e-6, 0.1e-6);
  r.direct->parameter_names = {"ln_G_s", "ln_lambda"};
  r.direct->lambda = 8.0;  // ln 8 is 95 % of the way from ln 0.1 to ln 10
  r.direct->lambda_interval = {5.0, 10.0, 0.95};
  const ConsistencyCheck c = check_consistency(r, range());
  ASSERT_EQ(c.at_bounds.size(), 1u);
  EXPECT_EQ(c.at_bounds[0].parameter, "lambda");
  EXPECT_TRUE(c.at_bounds[0].upper);
}
