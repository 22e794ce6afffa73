// The calibration policy behind `rbcal calibrate` (calibration/calibration_job.hpp): options
// are checked once with messages that name the option, only the chosen methods run, points
// above phi_max are left out with a warning, and a method that cannot run becomes a warning
// instead of ending the job. Data: the SYNTHETIC curves of data/synthetic_rheometer.csv,
// written from ln eta_re = phi (2.5 - 0.4 ln Ca) (see its header), on that same law.
#include <gtest/gtest.h>

#include <sstream>

#include "analytic_viscosity_model.hpp"
#include "calibration/calibration_job.hpp"

using namespace rbcal::calibration;
using rbcal::calibration::test_models::AnalyticViscosityModel;

namespace {

AnalyticViscosityModel synthetic_law() { return test_models::synthetic_rheometer_law(); }

CalibrationJobOptions options(const std::string& method) {
  CalibrationJobOptions o;
  o.data_file = RBCAL_CALIBRATION_DATA "/synthetic_rheometer.csv";
  o.method = method;
  o.sampler.threads = 1;
  o.min_shear_rate = 0.0;  // synthetic curves: no aggregation to leave out
  return o;
}

}  // namespace

TEST(CalibrationJob, ChecksItsOptionsOnceNamingTheOption) {
  EXPECT_EQ(options("all").invalid_reason(), "");
  EXPECT_NE(options("fit").invalid_reason().find("--method fit"), std::string::npos);
  CalibrationJobOptions o = options("all");
  o.compare = "intact";
  EXPECT_NE(o.invalid_reason().find("--compare intact: expected NUMERATOR/DENOMINATOR"), std::string::npos);
  o = options("direct");
  o.compare = "intact/hardened";
  EXPECT_NE(o.invalid_reason().find("--compare needs the mcmc method"), std::string::npos);
  o = options("direct");
  o.joint = true;
  EXPECT_NE(o.invalid_reason().find("--joint needs the mcmc method"), std::string::npos);
  o = options("all");
  o.hierarchical = true;
  EXPECT_NE(o.invalid_reason().find("need --joint"), std::string::npos);
  o = options("all");
  o.setup.cell_radius = -1.0;
  EXPECT_NE(o.invalid_reason().find("cell radius"), std::string::npos);
  o = options("all");
  o.phi_max = 0.0;
  EXPECT_NE(o.invalid_reason().find("--phi-max"), std::string::npos);
  std::ostringstream log;
  o = options("all");
  o.surrogate_file = "/nonexistent/surrogate.json";
  try {
    run_calibration_job(o, log);
    FAIL() << "ran without a surrogate";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("surrogate file /nonexistent/surrogate.json not found"), std::string::npos);
  }
}

TEST(CalibrationJob, RunsTheChosenMethodOnTheChosenPoints) {
  const CalibrationInput input = read_calibration_input(RBCAL_CALIBRATION_DATA "/synthetic_rheometer.csv");
  CalibrationJobOptions o = options("direct");
  o.samples = {"intact"};
  o.phi_max = 0.25;
  std::ostringstream log;
  const CalibrationReport report = calibrate_samples(input, synthetic_law(), o, log);
  ASSERT_EQ(report.samples.size(), 1u);
  const SampleReport& r = report.samples[0];
  EXPECT_FALSE(r.alpha);
  EXPECT_FALSE(r.mcmc);
  ASSERT_TRUE(r.direct);
  for (const auto& p : r.sample.points) EXPECT_LE(p.phi, 0.25);
  bool warned = false;
  for (const auto& w : r.warnings) warned = warned || w.find("with phi > 0.25 left out") != std::string::npos;
  EXPECT_TRUE(warned);
  // The file's header: intact G_s 0.5 uN/m. The interval must hold it.
  EXPECT_LT(r.direct->shear_modulus_interval.lower, 0.5e-6);
  EXPECT_GT(r.direct->shear_modulus_interval.upper, 0.5e-6);
  EXPECT_NE(log.str().find("sample intact:"), std::string::npos) << log.str();
  EXPECT_NE(log.str().find("G_s direct"), std::string::npos) << log.str();
  EXPECT_EQ(report.provenance.options["phi_max"], 0.25);

  o.samples = {"nobody"};
  EXPECT_THROW(calibrate_samples(input, synthetic_law(), o, log), std::invalid_argument);
}

TEST(CalibrationJob, LeavesOutLowShearRatesByDefault) {
  // Whole blood aggregates below complete disaggregation (38 1/s at 45 %, Snabre et al.
  // 1987): by default points below 40 1/s are left out and counted in a warning.
  const CalibrationInput input = read_calibration_input(RBCAL_CALIBRATION_DATA "/synthetic_rheometer.csv");
  CalibrationJobOptions o = options("direct");
  o.min_shear_rate = CalibrationJobOptions{}.min_shear_rate;
  EXPECT_EQ(o.min_shear_rate, 40.0);
  o.samples = {"intact"};
  std::ostringstream log;
  const CalibrationReport report = calibrate_samples(input, synthetic_law(), o, log);
  const SampleReport& r = report.samples.at(0);
  std::size_t low = 0;
  for (const auto& p : input.sample("intact").points) low += p.shear_rate < 40.0 ? 1 : 0;
  ASSERT_GT(low, 0u);
  EXPECT_EQ(r.sample.points.size(), input.sample("intact").points.size() - low);
  for (const auto& p : r.sample.points) EXPECT_GE(p.shear_rate, 40.0);
  EXPECT_NE(r.warnings.at(0).find(std::to_string(low) + " points below 40 1/s left out"), std::string::npos)
      << r.warnings.at(0);
}

// Data that the model cannot reach end no job: the sample is reported with the reasons.
TEST(CalibrationJob, DataTheModelCannotReachBecomeWarningsNotErrors) {
  const CalibrationInput input = read_calibration_input(RBCAL_CALIBRATION_DATA "/synthetic_rheometer.csv");
  CalibrationJobOptions o = options("direct");
  o.samples = {"hardened"};
  AnalyticViscosityModel narrow = synthetic_law();
  narrow.box.ca_min = 1e-12;
  narrow.box.ca_max = 1e-9;  // no measured point inside the model's Ca range
  std::ostringstream log;
  const CalibrationReport report = calibrate_samples(input, narrow, o, log);
  ASSERT_EQ(report.samples.size(), 1u);
  EXPECT_FALSE(report.samples[0].direct);
  ASSERT_FALSE(report.samples[0].warnings.empty());
  EXPECT_NE(report.samples[0].warnings[0].find("cannot be reached: phi 0.1:"), std::string::npos)
      << report.samples[0].warnings[0];
  EXPECT_NE(report.samples[0].warnings.back().find("nothing to calibrate"), std::string::npos);
  EXPECT_EQ(report.samples[0].left_out.size(), input.sample("hardened").points.size());
}

// The MCMC's posterior is truncated to the model's range: when an end of its interval lies at the
// range's Ca edge, a warning says that the library, not the data, set it (read as a limit).
TEST(CalibrationJob, NamesAnIntervalEndThatTheModelsRangeCut) {
  const CalibrationInput input = read_calibration_input(RBCAL_CALIBRATION_DATA "/synthetic_rheometer.csv");
  CalibrationJobOptions o = options("mcmc");
  o.samples = {"intact"};
  const auto cut_warning = [](const SampleReport& r) {
    for (const auto& w : r.warnings)
      if (w.find("MCMC: the lower end of the G_s interval") != std::string::npos &&
          w.find("read it as a lower limit") != std::string::npos)
        return true;
    return false;
  };
  std::ostringstream log;
  const CalibrationReport wide = calibrate_samples(input, synthetic_law(), o, log);
  ASSERT_TRUE(wide.samples.at(0).mcmc);
  EXPECT_FALSE(cut_warning(wide.samples[0]));
  // At the true G_s (0.5 uN/m) the highest shear rate (50 1/s) sits at Ca 0.62: a range ending at Ca 0.66
  // cuts the interval's lower end (the larger Ca).
  AnalyticViscosityModel narrow = synthetic_law();
  narrow.box.ca_max = 0.66;
  const CalibrationReport cut = calibrate_samples(input, narrow, o, log);
  ASSERT_TRUE(cut.samples.at(0).mcmc);
  EXPECT_TRUE(cut_warning(cut.samples[0]));
  EXPECT_GT(cut.samples[0].mcmc->shear_modulus_interval.lower, wide.samples[0].mcmc->shear_modulus_interval.lower);
}

// A direct fit that leaves out points one G_s could keep inside the model's Ca range (here the
// highest shear rates, past a range that ends at Ca 0.3 where the truth puts them at 0.62) is
// refitted holding them, and a warning gives both; with --hold-points the fit holds them itself.
TEST(CalibrationJob, SaysWhenTheDirectFitLeftOutPointsItCouldHaveKept) {
  const CalibrationInput input = read_calibration_input(RBCAL_CALIBRATION_DATA "/synthetic_rheometer.csv");
  CalibrationJobOptions o = options("direct");
  o.samples = {"intact"};
  AnalyticViscosityModel narrow = synthetic_law();
  narrow.box.ca_max = 0.3;
  const auto shed_warning = [](const SampleReport& r) {
    for (const auto& w : r.warnings)
      if (w.find("points one G_s keeps inside the model's Ca range; holding them all (--hold-points) gives G_s") !=
          std::string::npos)
        return true;
    return false;
  };
  std::ostringstream log;
  const CalibrationReport free_set = calibrate_samples(input, narrow, o, log);
  ASSERT_TRUE(free_set.samples.at(0).direct);
  const DirectFitResult& shed = *free_set.samples[0].direct;
  EXPECT_LT(static_cast<int>(shed.used_points().size()), shed.coverable_points);
  EXPECT_TRUE(shed_warning(free_set.samples[0]));

  o.hold_coverable_points = true;
  const CalibrationReport held = calibrate_samples(input, narrow, o, log);
  ASSERT_TRUE(held.samples.at(0).direct);
  EXPECT_EQ(static_cast<int>(held.samples[0].direct->used_points().size()), held.samples[0].direct->coverable_points);
  EXPECT_FALSE(shed_warning(held.samples[0]));
}

// Without the MCMC's by-products the posterior's summary is the same (the by-products draw
// from their own seeds), and bands, predictive check, saved draws and evidence are absent.
TEST(CalibrationJob, MCMCByproductsCanBeLeftOutWithoutChangingTheInterval) {
  const CalibrationInput input = read_calibration_input(RBCAL_CALIBRATION_DATA "/synthetic_rheometer.csv");
  CalibrationJobOptions o = options("mcmc");
  o.samples = {"intact"};
  std::ostringstream log;
  const CalibrationReport full = calibrate_samples(input, synthetic_law(), o, log);
  o.mcmc_byproducts = false;
  const CalibrationReport lean = calibrate_samples(input, synthetic_law(), o, log);
  const SampleReport &f = full.samples.at(0), &l = lean.samples.at(0);
  ASSERT_TRUE(f.mcmc && l.mcmc);
  EXPECT_EQ(l.mcmc->shear_modulus_median, f.mcmc->shear_modulus_median);
  EXPECT_EQ(l.mcmc->shear_modulus_interval.lower, f.mcmc->shear_modulus_interval.lower);
  EXPECT_EQ(l.mcmc->shear_modulus_interval.upper, f.mcmc->shear_modulus_interval.upper);
  EXPECT_FALSE(f.bands.empty());
  EXPECT_TRUE(f.predictive_check && f.evidence && f.saved_draws);
  EXPECT_TRUE(l.bands.empty());
  EXPECT_FALSE(l.predictive_check || l.evidence || l.saved_draws);
}

// --joint: one posterior over both samples, whose ratio --compare reports (the synthetic truth:
// hardened 1.0 over intact 0.5 uN/m), and the brief report that says so.
TEST(CalibrationJob, JointPosteriorGivesTheComparison) {
  const CalibrationInput input = read_calibration_input(RBCAL_CALIBRATION_DATA "/synthetic_rheometer.csv");
  CalibrationJobOptions o = options("mcmc");
  o.joint = true;
  o.compare = "hardened/intact";
  std::ostringstream log;
  const CalibrationReport report = calibrate_samples(input, synthetic_law(), o, log);
  ASSERT_TRUE(report.joint) << log.str();
  EXPECT_EQ(report.joint->calibration.samples.size(), 2u);
  EXPECT_TRUE(report.joint->calibration.mcmc.converged) << report.joint->calibration.mcmc.stop_reason;
  ASSERT_TRUE(report.comparison);
  EXPECT_EQ(report.comparison->source, "joint posterior, model nuisances shared");
  EXPECT_LT(report.comparison->ratio.interval.lower, 2.0);
  EXPECT_GT(report.comparison->ratio.interval.upper, 2.0);
  EXPECT_NE(log.str().find("joint posterior over 2 samples"), std::string::npos) << log.str();
  EXPECT_NE(log.str().find("G_s ratio hardened / intact"), std::string::npos);
}
