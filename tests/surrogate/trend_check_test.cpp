// The trend check of a viscosity model (surrogate/trend_check.hpp): a model with the right
// trends passes, and one whose eta_re falls with phi in one corner or rises with Ca fails
// naming that corner; the Pries et al. 1992 correlation gives 3.2 at H 0.45 (its eta_45)
// and 1 at H 0 by construction.
#include <gtest/gtest.h>

#include <cmath>

#include "surrogate/trend_check.hpp"

using namespace rbcal::surrogate;

namespace {

// ln eta_re = phi (a - 0.3 ln Ca); with `dent`, eta_re falls with phi above phi 0.45 at Ca < 0.02.
class TrendModel : public PointwiseViscosityModel {
 public:
  double a = 2.5;
  bool dent = false;
  bool flat_dense = false;  // above phi 0.48, eta_re rises with Ca by 0.1 % per step (sd 1 %)
  ViscosityPrediction predict_point(double phi, double ca, double lambda, const NuisanceValues&) const override {
    ViscosityPrediction p;
    if (flat_dense && phi > 0.48) {
      p.eta_re = std::exp(phi * a) * (1.0 + 1e-3 * std::log(ca / 0.01) / std::log(3.2 / 0.01) * 10.0);
      p.sd = 0.01 * p.eta_re;
      return p;
    }
    double alpha = a - 0.3 * std::log(ca) + 0.05 * std::log(lambda);
    if (dent && ca < 0.02 && phi > 0.45) alpha *= 0.45 / phi;  // phi alpha held at its phi 0.45 value ...
    p.eta_re = std::exp(phi * alpha) * (dent && ca < 0.02 && phi > 0.45 ? 1.0 - (phi - 0.45) : 1.0);  // ... times a falling factor
    return p;
  }
  ParameterRange range() const override { return {0.05, 0.55, 0.01, 3.2, 0.1, 10.0}; }
};

}  // namespace

TEST(TrendCheck, PriesCorrelationAtItsAnchors) {
  EXPECT_NEAR(pries_1992_relative_viscosity(0.45), 3.2, 1e-12);
  EXPECT_NEAR(pries_1992_relative_viscosity(0.0), 1.0, 1e-12);
  // docs/validation.md: 2.90 at phi_actual 0.412 of the N_a 4 library's phi 0.41 cases
  EXPECT_NEAR(pries_1992_relative_viscosity(0.412), 2.90, 0.005);
}

TEST(TrendCheck, AModelWithTheRightTrendsPasses) {
  TrendModel m;
  m.a = std::log(pries_1992_relative_viscosity(0.41)) / 0.41 + 0.3 * std::log(0.8) - 0.05 * std::log(5.0);
  const TrendCheck t = check_trends(m);
  EXPECT_TRUE(t.not_rising_with_phi.empty());
  EXPECT_TRUE(t.not_falling_with_ca.empty());
  EXPECT_NEAR(t.high_shear_eta_re / t.high_shear_pries, 1.0, 1e-9);
  EXPECT_TRUE(t.passed()) << t.report();
  EXPECT_EQ(t.phi.size(), 11u);
  EXPECT_EQ(t.viscosity_ratio.size(), 6u);
}

TEST(TrendCheck, NamesWhereEtaReFallsWithPhi) {
  TrendModel m;
  m.dent = true;
  const TrendCheck t = check_trends(m);
  ASSERT_FALSE(t.not_rising_with_phi.empty());
  for (const TrendViolation& v : t.not_rising_with_phi) {
    EXPECT_GE(v.phi, 0.45 - 1e-9);
    EXPECT_LT(v.capillary_number, 0.02);
    EXPECT_LE(v.eta_re_next, v.eta_re_here);
  }
  EXPECT_FALSE(t.passed());
  EXPECT_NE(t.report().find("rises with phi:        FAIL"), std::string::npos) << t.report();
}

TEST(TrendCheck, FailsAtHighShearFarFromBlood) {
  TrendModel m;
  m.a = 5.0;  // eta_re about 7 at phi 0.41, Ca 0.8: the N_a 4 library's level
  const TrendCheck t = check_trends(m);
  EXPECT_FALSE(t.high_shear_ok());
  EXPECT_NE(t.report().find("high shear (phi 0.41, Ca 0.8, lambda 5): FAIL"), std::string::npos) << t.report();
}

// The Ca trend's violations are counted per phi and sized in the model's sd, so a report
// tells a flat dense corner (steps far below the sd) from a resolved rise.
TEST(TrendCheck, CountsCaViolationsPerPhiInUnitsOfTheSd) {
  TrendModel m;
  m.flat_dense = true;
  const TrendCheck t = check_trends(m);
  // Probe phi 0.5 and 0.55 lie above 0.48: every one of their 10 Ca steps x 6 lambda rises.
  ASSERT_EQ(t.not_falling_with_ca.size(), 120u);
  for (const TrendViolation& v : t.not_falling_with_ca) {
    EXPECT_GT(v.phi, 0.48);
    // Each step rises by 1 % of eta_re over the 10 steps / 10 = 0.1 %, i.e. 0.1 sd.
    EXPECT_NEAR(v.size_in_sd(), 0.1, 0.01);
  }
  EXPECT_NE(t.report().find("not falling, per phi (of 60 steps): 0.5: 60; 0.55: 60; the largest rise is 0.1"),
            std::string::npos)
      << t.report();
}
