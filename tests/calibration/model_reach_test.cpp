// The mismatch diagnosis (calibration/model_reach.hpp) on a constructed case: with the
// analytic model ln eta_re = phi (2 - 0.3 ln Ca + 0.1 ln lambda) over Ca 0.003 to 20 at
// lambda 5, eta_re at phi 0.4 spans exp(0.4 (2.161 - 0.3 ln 20)) = 1.655 to
// exp(0.4 (2.161 - 0.3 ln 0.003)) = 4.757. Points inside that span (within two standard
// deviations) are reachable; the others are named with their gap, and points at a phi
// outside the model's range with that reason. The calibration job fits the reachable
// points and lists the others as left out.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "analytic_viscosity_model.hpp"
#include "calibration/calibration_job.hpp"
#include "calibration/model_reach.hpp"
#include "synthetic_sample.hpp"

using namespace rbcal::calibration;
using rbcal::calibration::test_models::AnalyticViscosityModel;

namespace {

RelativeViscosityPoint point(double phi, double eta_re, int line) {
  RelativeViscosityPoint p;
  p.phi = phi;
  p.shear_rate = 150.0;
  p.eta_re = eta_re;
  p.eta_re_sd = 0.02 * eta_re;
  p.line = line;
  return p;
}

}  // namespace

TEST(ModelReach, NamesThePointsTheModelCannotReachAndByHowMuch) {
  const AnalyticViscosityModel model;  // relative model sd 1 %
  ModelSetup setup;                    // lambda 5 fixed
  const double lowest = std::exp(0.4 * (2.0 + 0.1 * std::log(5.0) - 0.3 * std::log(20.0)));
  const double highest = std::exp(0.4 * (2.0 + 0.1 * std::log(5.0) - 0.3 * std::log(0.003)));
  const std::vector<RelativeViscosityPoint> points = {point(0.4, 3.0, 10), point(0.4, 1.2, 11), point(0.4, 1.0, 12),
                                                      point(0.4, 6.0, 13), point(0.7, 9.0, 14),
                                                      point(0.4, 0.99 * lowest, 15)};
  const ReachDiagnosis d = diagnose_reach(points, model, setup);
  ASSERT_EQ(d.points.size(), 6u);
  EXPECT_TRUE(d.points[0].reachable());
  EXPECT_EQ(d.points[1].reach, Reach::below_model);
  EXPECT_NEAR(d.points[1].relative_gap, 1.2 / lowest - 1.0, 2e-3);  // the Ca scan ends at the range's ends
  EXPECT_NEAR(d.points[1].model_min, lowest, 1e-9 * lowest);
  EXPECT_EQ(d.points[2].reach, Reach::below_model);
  EXPECT_EQ(d.points[3].reach, Reach::above_model);
  EXPECT_NEAR(d.points[3].relative_gap, 6.0 / highest - 1.0, 2e-3);
  EXPECT_EQ(d.points[4].reach, Reach::phi_outside_model);
  EXPECT_TRUE(d.points[5].reachable()) << "1 % below the lowest value is within two standard deviations";
  EXPECT_EQ(d.reachable_count(), 2);
  EXPECT_NE(d.points[1].reason().find("below the model's lowest value 1.66 at phi 0.4"), std::string::npos)
      << d.points[1].reason();

  // One group per (phi, verdict), phi ascending, with the range of gaps.
  ASSERT_EQ(d.unreachable_groups.size(), 3u);
  const ReachGroup& below = d.unreachable_groups[0];
  EXPECT_EQ(below.reach, Reach::below_model);
  EXPECT_EQ(below.points, 2);
  EXPECT_DOUBLE_EQ(below.measured_min, 1.0);
  EXPECT_DOUBLE_EQ(below.measured_max, 1.2);
  EXPECT_NEAR(below.gap_min, 1.2 / lowest - 1.0, 2e-3);  // the smaller miss
  EXPECT_NEAR(below.gap_max, 1.0 / lowest - 1.0, 2e-3);
  EXPECT_EQ(d.unreachable_groups[1].reach, Reach::above_model);
  EXPECT_EQ(d.unreachable_groups[2].reach, Reach::phi_outside_model);
  const std::string line = below.line(model.range(), setup);
  EXPECT_NE(line.find("phi 0.4: 2 points below the model at any G_s"), std::string::npos) << line;
  EXPECT_NE(line.find("off by 28 % to 40 %"), std::string::npos) << line;
  EXPECT_NE(d.unreachable_groups[2].line(model.range(), setup).find("outside the model's phi range 0.02 to 0.6"),
            std::string::npos);
}

// With lambda fitted, the scan covers the model's lambda range too: a point beyond reach
// at lambda 5 can be reachable at another lambda.
TEST(ModelReach, ScansTheLambdaRangeWhenLambdaIsFitted) {
  const AnalyticViscosityModel model;
  ModelSetup setup;
  const double highest_at_5 = std::exp(0.4 * (2.0 + 0.1 * std::log(5.0) - 0.3 * std::log(0.003)));
  const std::vector<RelativeViscosityPoint> points = {point(0.4, 1.1 * highest_at_5, 1)};
  EXPECT_EQ(diagnose_reach(points, model, setup).points[0].reach, Reach::above_model);
  setup.fit_lambda = true;  // lambda up to 20: ln eta_re gains 0.4 * 0.1 * ln 4 = 5.5 %
  EXPECT_TRUE(diagnose_reach(points, model, setup).points[0].reachable());
}

// The job fits what the model can reach and lists the rest: a synthetic sample at
// G_s 0.5 uN/m plus three unreachable points still gives G_s, and the three appear as
// left out with their reasons, one warning per phi.
TEST(ModelReach, TheJobFitsTheReachablePointsAndListsTheOthers) {
  const AnalyticViscosityModel model;
  std::mt19937_64 rng(7);
  test_models::SyntheticDesign design;
  design.shear_rates = {10.0, 22.0, 46.0, 100.0, 220.0};
  SampleData sample = test_models::synthetic_sample(model, design, rng);
  sample.points.push_back(point(0.4, 1.0, 901));
  sample.points.push_back(point(0.4, 9.0, 902));
  sample.points.push_back(point(0.65, 9.0, 903));
  CalibrationInput input;
  input.source = "constructed";
  input.samples = {sample};
  CalibrationJobOptions o;
  o.method = "direct";
  o.min_shear_rate = 0.0;
  o.keep_out_of_hematocrit_order = true;  // the point below the model is also below phi 0.3's curve
  std::ostringstream log;
  const CalibrationReport report = calibrate_samples(input, model, o, log);
  const SampleReport& r = report.samples.at(0);
  ASSERT_TRUE(r.direct.has_value()) << log.str();
  EXPECT_NEAR(r.direct->shear_modulus / 0.5e-6, 1.0, 0.1);
  ASSERT_EQ(r.left_out.size(), 3u);
  EXPECT_EQ(r.left_out[0].point.line, 901);
  EXPECT_NE(r.left_out[0].reason.find("below the model's lowest value"), std::string::npos) << r.left_out[0].reason;
  EXPECT_NE(r.left_out[1].reason.find("above the model's highest value"), std::string::npos);
  EXPECT_NE(r.left_out[2].reason.find("phi 0.65 outside the model's phi range"), std::string::npos);
  EXPECT_EQ(r.sample.points.size(), sample.points.size() - 3);
  EXPECT_NE(log.str().find("cannot be reached: phi 0.4: 1 point below the model"), std::string::npos) << log.str();
  EXPECT_NE(log.str().find("cannot be reached: phi 0.65: 1 point outside"), std::string::npos);
}
