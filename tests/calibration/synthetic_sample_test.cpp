// Synthetic samples of known G_s (calibration/synthetic_sample.hpp): the readings follow
// shear rate = Ca G_s / (eta0 a) and viscosity = eta0 eta_re, the file round-trips through the
// reader, and bad input is named.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "calibration/calibration_input.hpp"
#include "calibration/synthetic_sample.hpp"

namespace rbcal::calibration {
namespace {

std::vector<SimulatedViscosity> two_points() {
  return {{"a", 0.30, 0.5, 5.0, 2.0, 0.02}, {"b", 0.40, 2.0, 5.0, 3.0, 0.0}};
}

TEST(SyntheticSample, ReadingsFollowTheCapillaryNumberWithoutNoise) {
  SyntheticSampleOptions o;
  o.shear_modulus = 4e-6;
  o.plasma_viscosity = 1.2e-3;
  o.cell_radius = 4e-6;
  o.relative_noise = 0.0;
  const RheometerData d = synthetic_rheometer_data(two_points(), o);
  ASSERT_EQ(d.rows.size(), 3u);
  EXPECT_EQ(d.rows[0].kind, MeasurementKind::plasma_assumed);
  EXPECT_DOUBLE_EQ(d.rows[0].viscosity, 1.2e-3);
  EXPECT_DOUBLE_EQ(d.rows[0].viscosity_sd, 0.02 * 1.2e-3);
  // Ca 0.5 at G_s 4 uN/m, eta0 1.2 mPa s, a 4 um: 0.5 * 4e-6 / (1.2e-3 * 4e-6) = 416.67 1/s.
  EXPECT_NEAR(d.rows[1].shear_rate, 0.5 * 4e-6 / (1.2e-3 * 4e-6), 1e-9);
  EXPECT_NEAR(d.rows[2].shear_rate, 2.0 * 4e-6 / (1.2e-3 * 4e-6), 1e-9);
  EXPECT_DOUBLE_EQ(d.rows[1].viscosity, 1.2e-3 * 2.0);
  // The reported sd carries the run's own standard error (1 % here) even without noise.
  EXPECT_NEAR(d.rows[1].viscosity_sd, 1.2e-3 * 0.02, 1e-15);
  EXPECT_DOUBLE_EQ(d.rows[2].viscosity_sd, 0.0);
}

TEST(SyntheticSample, NoiseHasTheStatedSpreadAndTheSeedFixesIt) {
  std::vector<SimulatedViscosity> points;
  for (int i = 0; i < 400; ++i) points.push_back({"p" + std::to_string(i), 0.3, 0.1 * (i + 1), 5.0, 2.0, 0.0});
  SyntheticSampleOptions o;
  o.relative_noise = 0.05;
  const RheometerData a = synthetic_rheometer_data(points, o), b = synthetic_rheometer_data(points, o);
  double sum = 0.0, sum2 = 0.0;
  for (std::size_t i = 1; i < a.rows.size(); ++i) {
    EXPECT_EQ(a.rows[i].viscosity, b.rows[i].viscosity);
    const double e = a.rows[i].viscosity / (o.plasma_viscosity * 2.0) - 1.0;
    sum += e;
    sum2 += e * e;
    EXPECT_NEAR(a.rows[i].viscosity_sd, 0.05 * o.plasma_viscosity * 2.0, 1e-15);
  }
  const double n = static_cast<double>(points.size()), mean = sum / n;
  // 400 draws: the mean within 4 standard errors (0.05 / 20 each), the sd within 15 %.
  EXPECT_NEAR(mean, 0.0, 4.0 * 0.05 / 20.0);
  EXPECT_NEAR(std::sqrt(sum2 / n - mean * mean), 0.05, 0.15 * 0.05);
  o.seed = 2;
  EXPECT_NE(synthetic_rheometer_data(points, o).rows[1].viscosity, a.rows[1].viscosity);
}

TEST(SyntheticSample, RoundTripsThroughTheCsvReader) {
  const RheometerData d = synthetic_rheometer_data(two_points(), {});
  std::stringstream csv;
  write_rheometer_csv(d, csv);
  const RheometerData back = parse_rheometer_csv(csv, "round trip");
  ASSERT_EQ(back.rows.size(), d.rows.size());
  for (std::size_t i = 0; i < d.rows.size(); ++i) {
    EXPECT_EQ(back.rows[i].kind, d.rows[i].kind);
    EXPECT_NEAR(back.rows[i].shear_rate, d.rows[i].shear_rate, 1e-9 * d.rows[i].shear_rate);
    EXPECT_NEAR(back.rows[i].viscosity, d.rows[i].viscosity, 1e-9 * d.rows[i].viscosity);
    EXPECT_NEAR(back.rows[i].viscosity_sd, d.rows[i].viscosity_sd, 1e-9 * d.rows[i].viscosity);
  }
  EXPECT_EQ(back.provenance, d.provenance);
  const CalibrationInput input = make_calibration_input(back);
  ASSERT_EQ(input.samples.size(), 1u);
  EXPECT_EQ(input.samples[0].points.size(), 2u);
}

TEST(SyntheticSample, NamesWhatIsWrong) {
  auto points = two_points();
  SyntheticSampleOptions o;
  o.shear_modulus = 0.0;
  EXPECT_THROW(synthetic_rheometer_data(points, o), std::invalid_argument);
  points[1].phi = 1.2;
  try {
    synthetic_rheometer_data(points, {});
    FAIL() << "phi 1.2 accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("b: phi"), std::string::npos) << e.what();
  }
  points[1] = points[0];
  points[1].id = "c";
  try {
    synthetic_rheometer_data(points, {});
    FAIL() << "a duplicate point accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("c: a second point"), std::string::npos) << e.what();
  }
  EXPECT_THROW(synthetic_rheometer_data({}, {}), std::invalid_argument);
}

}  // namespace
}  // namespace rbcal::calibration
