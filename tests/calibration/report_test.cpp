// The calibration report: files present, summary.json with the documented keys and units,
// CSV tables whose row counts match the data, plots non-empty when gnuplot is installed, and
// tables without plots when it is not.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <set>
#include <string>

#include <nlohmann/json.hpp>

#include "analytic_viscosity_model.hpp"
#include "calibration/alpha_method.hpp"
#include "calibration/calibration_report.hpp"
#include "calibration/direct_fit.hpp"
#include "calibration/mcmc_calibration.hpp"
#include "calibration/predictive_bands.hpp"
#include "calibration/detail/report_plots.hpp"
#include "calibration/detail/report_tables.hpp"
#include "calibration/sample_comparison.hpp"
#include "synthetic_sample.hpp"

using namespace rbcal::calibration;
using rbcal::calibration::test_models::AnalyticViscosityModel;
namespace fs = std::filesystem;

namespace {

constexpr int kBandRates = 12;

// A short, cheap calibration of two synthetic samples by all three methods (the numbers are
// not under test here, only how they are written).
CalibrationReport make_report(const AnalyticViscosityModel& model) {
  CalibrationReport report;
  report.provenance = {"synthetic.csv", "analytic model", "rbcal calibrate synthetic.csv", {{"method", "all"}}, 5};
  std::mt19937_64 rng(3);
  for (const auto& [name, gs] : {std::pair{"intact", 0.5e-6}, std::pair{"hardened, fixed", 1.5e-6}}) {
    test_models::SyntheticDesign design;
    design.shear_modulus = gs;
    design.plasma_relative_standard_error = 0.021;
    SampleReport s;
    s.sample = test_models::synthetic_sample(model, design, rng);
    s.sample.name = name;
    s.alpha = estimate_by_alpha_matching(s.sample, model);
    s.direct = fit_direct(s.sample, model);
    McmcCalibrationOptions mo;
    mo.sampler.chains = 2;
    mo.sampler.walkers = 8;
    mo.sampler.min_steps = 100;
    mo.sampler.max_steps = 200;
    mo.sampler.threads = 1;
    s.mcmc = calibrate_mcmc(s.sample, model, mo);
    PredictiveBandOptions bo;
    bo.shear_rate_points = kBandRates;
    bo.max_draws = 100;
    s.bands = predictive_bands(model, *s.mcmc, bo);
    s.warnings.push_back("a test warning");
    report.samples.push_back(std::move(s));
  }
  report.comparison = SampleComparisonReport{"hardened, fixed", "intact",
                                             compare_shear_moduli(report.samples[1].mcmc->shear_modulus_draws(),
                                                                  report.samples[0].mcmc->shear_modulus_draws()),
                                             std::string{}};
  return report;
}

// Data rows of a CSV file (lines after the header).
int data_rows(const fs::path& file) {
  std::ifstream in(file);
  EXPECT_TRUE(in) << file;
  std::string line;
  int rows = -1;
  while (std::getline(in, line))
    if (!line.empty()) ++rows;
  return rows;
}

std::string header_of(const fs::path& file) {
  std::ifstream in(file);
  std::string line;
  std::getline(in, line);
  return line;
}

class ReportTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    model_ = new AnalyticViscosityModel;
    report_ = new CalibrationReport(make_report(*model_));
  }
  static void TearDownTestSuite() {
    delete report_;
    delete model_;
  }
  fs::path fresh_folder(const std::string& name) {
    const fs::path folder = fs::temp_directory_path() / ("rbcal_report_test_" + name);
    fs::remove_all(folder);
    return folder;
  }
  static AnalyticViscosityModel* model_;
  static CalibrationReport* report_;
};
AnalyticViscosityModel* ReportTest::model_ = nullptr;
CalibrationReport* ReportTest::report_ = nullptr;

}  // namespace

TEST_F(ReportTest, WritesTablesWhoseRowsMatchTheData) {
  const fs::path folder = fresh_folder("tables");
  ReportOptions options;
  options.plots = false;
  options.max_chain_draws = 500;
  const ReportFiles files = write_calibration_report(*report_, folder, options);
  for (const char* name : {"summary.json", "fits.csv", "alpha.csv", "gs_per_ca.csv", "chains.csv", "bands.csv"})
    EXPECT_TRUE(fs::exists(folder / name)) << name;
  EXPECT_FALSE(files.plots_written);

  int points = 0, alphas = 0, matches = 0, band_rows = 0;
  for (const SampleReport& s : report_->samples) {
    points += static_cast<int>(s.sample.points.size());
    alphas += static_cast<int>(s.alpha->measured.size() + s.alpha->model.size());
    matches += static_cast<int>(s.alpha->per_shear_rate.size() + s.alpha->per_capillary_number.size());
    band_rows += static_cast<int>(s.bands.size()) * kBandRates;
  }
  EXPECT_EQ(data_rows(folder / "fits.csv"), points);
  EXPECT_EQ(data_rows(folder / "alpha.csv"), alphas);
  EXPECT_EQ(data_rows(folder / "gs_per_ca.csv"), matches);
  EXPECT_EQ(data_rows(folder / "bands.csv"), band_rows);
  const int chain_rows = data_rows(folder / "chains.csv");
  EXPECT_GT(chain_rows, 2 * 200);  // both samples, at least 200 draws each
  EXPECT_LE(chain_rows, 2 * 500);
  EXPECT_EQ(header_of(folder / "fits.csv").rfind("sample,line,phi,shear_rate_per_s,eta_mPa_s,eta_se_mPa_s,eta_re,eta_re_sd", 0), 0u);
  EXPECT_EQ(header_of(folder / "chains.csv").rfind("sample,chain,step,walker,G_s_uN_per_m", 0), 0u);

  // A sample name with a comma is quoted, so every row keeps its column count.
  std::ifstream fits(folder / "fits.csv");
  std::string line;
  std::getline(fits, line);
  bool quoted = false;
  while (std::getline(fits, line)) quoted = quoted || line.rfind("\"hardened, fixed\",", 0) == 0;
  EXPECT_TRUE(quoted);
}

TEST_F(ReportTest, SummaryHasTheDocumentedKeysInReportUnits) {
  const fs::path folder = fresh_folder("summary");
  ReportOptions options;
  options.plots = false;
  write_calibration_report(*report_, folder, options);
  std::ifstream in(folder / "summary.json");
  const nlohmann::json j = nlohmann::json::parse(in);  // throws if not JSON
  EXPECT_EQ(j.at("schema"), "rbcal.calibration_report/1");
  for (const char* key : {"rbcal_version", "git_revision", "data_file", "surrogate_file", "options", "seed"})
    EXPECT_TRUE(j.at("provenance").contains(key)) << key;
  EXPECT_EQ(j.at("provenance").at("seed"), 5);
  ASSERT_EQ(j.at("samples").size(), 2u);
  const nlohmann::json& s = j.at("samples")[0];
  const SampleReport& r = report_->samples[0];
  EXPECT_EQ(s.at("name"), "intact");
  EXPECT_NEAR(s.at("plasma").at("eta0_mPa_s").get<double>(), 1e3 * r.sample.plasma.eta0, 1e-12);
  EXPECT_GT(s.at("plasma").at("eta0_standard_error_mPa_s").get<double>(), 0.0);
  EXPECT_EQ(s.at("points").at("total"), r.sample.points.size());
  EXPECT_TRUE(s.at("points").contains("used"));
  EXPECT_TRUE(s.at("points").at("skipped").is_array());
  const nlohmann::json& m = s.at("methods");
  for (const char* method : {"alpha", "direct", "mcmc"}) {
    SCOPED_TRACE(method);
    ASSERT_TRUE(m.contains(method));
    EXPECT_GT(m.at(method).at("G_s_uN_per_m").get<double>(), 0.0);
    const auto& i = m.at(method).at("interval_uN_per_m");
    EXPECT_LT(i.at("lower").get<double>(), i.at("upper").get<double>());
  }
  EXPECT_NEAR(m.at("direct").at("G_s_uN_per_m").get<double>(), 1e6 * r.direct->shear_modulus, 1e-9);
  EXPECT_NEAR(m.at("mcmc").at("G_s_uN_per_m").get<double>(), 1e6 * r.mcmc->shear_modulus_median, 1e-9);
  const auto& d = m.at("mcmc").at("diagnostics");
  for (const char* key : {"rhat", "ess", "tau", "acceptance_fraction", "steps", "converged", "parameters"})
    EXPECT_TRUE(d.contains(key)) << key;
  EXPECT_EQ(d.at("steps"), r.mcmc->mcmc.steps);
  const auto& alpha = m.at("alpha");
  ASSERT_EQ(alpha.at("alpha_per_shear_rate").size(), r.alpha->measured.size());
  EXPECT_TRUE(alpha.at("alpha_per_shear_rate")[0].contains("r_squared"));
  EXPECT_EQ(alpha.at("G_s_per_ca").size(), r.alpha->per_capillary_number.size());
  EXPECT_EQ(s.at("warnings")[0], "a test warning");
  EXPECT_EQ(j.at("comparison").at("numerator"), "hardened, fixed");
  EXPECT_GT(j.at("comparison").at("ratio_median").get<double>(), 1.0);
  EXPECT_FALSE(j.at("plots").at("written").get<bool>());
  std::set<std::string> listed(j.at("files").begin(), j.at("files").end());
  EXPECT_TRUE(listed.count("fits.csv") && listed.count("summary.json"));
}

// The posterior-predictive check's plot: each point's PIT against shear rate, its title
// counting the points outside the band; drawn only for a sample that has the check.
TEST_F(ReportTest, PredictiveCheckPlotCountsThePointsOutside) {
  if (find_gnuplot("gnuplot").empty()) GTEST_SKIP() << "gnuplot not installed";
  CalibrationReport r = *report_;
  PredictiveCheck check;
  const double pits[] = {0.01, 0.5, 0.9};
  for (int k = 0; k < 3; ++k) {
    PredictiveCheckPoint p;
    p.point = r.samples[0].sample.points.at(static_cast<std::size_t>(k));
    p.pit = pits[k];
    p.outside = p.pit < 0.025 || p.pit > 0.975;
    check.points.push_back(p);
  }
  r.samples[0].predictive_check = check;
  const fs::path folder = fresh_folder("ppc");
  const ReportFiles files = write_calibration_report(r, folder);
  ASSERT_TRUE(files.plots_written) << files.plots_message;
  std::ifstream v(folder / "intact_ppc.svg");
  const std::string text((std::istreambuf_iterator<char>(v)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("1 of 3 points outside"), std::string::npos);
  EXPECT_NE(text.find("PIT"), std::string::npos);
  EXPECT_TRUE(fs::exists(folder / "intact_ppc.png"));
  EXPECT_FALSE(fs::exists(folder / "hardened__fixed_ppc.svg")) << "a plot for a sample without the check";
}

// report.html: one self-contained page with each sample's headline, its warnings, the plots
// inline and the provenance; names are escaped, nothing is fetched from elsewhere.
TEST_F(ReportTest, HtmlPageHoldsHeadlinesWarningsPlotsAndProvenance) {
  const fs::path folder = fresh_folder("html");
  const ReportFiles files = write_calibration_report(*report_, folder);
  std::ifstream in(folder / "report.html");
  ASSERT_TRUE(in) << "no report.html";
  const std::string page((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(page.rfind("<!DOCTYPE html>", 0), 0u);
  for (const std::string sample : {"intact", "hardened, fixed"})
    EXPECT_NE(page.find("<h2>" + sample + "</h2>"), std::string::npos) << sample;
  EXPECT_NE(page.find("warning: a test warning"), std::string::npos);
  EXPECT_NE(page.find("direct fit"), std::string::npos);
  EXPECT_NE(page.find("<h2>Provenance</h2>"), std::string::npos);
  EXPECT_EQ(page.find("src=\"http"), std::string::npos) << "the page fetches something";
  if (files.plots_written) {
    EXPECT_NE(page.find("<svg"), std::string::npos) << "plots written but not inlined";
  }
  const nlohmann::json summary = nlohmann::json::parse(std::ifstream(folder / "summary.json"));
  EXPECT_NE(std::find(summary["files"].begin(), summary["files"].end(), "report.html"), summary["files"].end());
}

TEST_F(ReportTest, PlotsArePngAndSvgWhenGnuplotIsPresent) {
  if (find_gnuplot("gnuplot").empty()) GTEST_SKIP() << "gnuplot not installed";
  const fs::path folder = fresh_folder("plots");
  const ReportFiles files = write_calibration_report(*report_, folder);
  ASSERT_TRUE(files.plots_written) << files.plots_message;
  for (const std::string stem : {"intact", "hardened__fixed"})
    for (const std::string plot : {"_fit", "_gs_posterior", "_alpha", "_gs_vs_ca"}) {
      SCOPED_TRACE(stem + plot);
      const fs::path png = folder / (stem + plot + ".png"), svg = folder / (stem + plot + ".svg");
      ASSERT_TRUE(fs::exists(png));
      ASSERT_TRUE(fs::exists(svg));
      EXPECT_GT(fs::file_size(png), 1000u);
      std::ifstream p(png, std::ios::binary);
      std::string magic(4, '\0');
      p.read(magic.data(), 4);
      EXPECT_EQ(magic, "\x89PNG");
      std::ifstream v(svg);
      const std::string text((std::istreambuf_iterator<char>(v)), std::istreambuf_iterator<char>());
      EXPECT_NE(text.find("<svg"), std::string::npos);
      EXPECT_NE(text.find(plot == "_alpha" ? "shear rate [1/s]" : plot == "_fit" ? "viscosity eta [mPa s]" : "G_s [uN/m]"),
                std::string::npos);
    }
  EXPECT_TRUE(fs::exists(folder / "plots.gp"));
}

TEST_F(ReportTest, MissingGnuplotSkipsPlotsButWritesTables) {
  const fs::path folder = fresh_folder("no_gnuplot");
  ReportOptions options;
  options.gnuplot = "rbcal-no-such-gnuplot";
  const ReportFiles files = write_calibration_report(*report_, folder, options);
  EXPECT_FALSE(files.plots_written);
  EXPECT_NE(files.plots_message.find("not found"), std::string::npos) << files.plots_message;
  EXPECT_TRUE(fs::exists(folder / "fits.csv"));
  EXPECT_TRUE(fs::exists(folder / "summary.json"));
  EXPECT_FALSE(fs::exists(folder / "intact_fit.png"));
}

TEST_F(ReportTest, AlphaOnlySampleHasDataWithoutPredictionsAndNoChains) {
  CalibrationReport report;
  SampleReport s = report_->samples[0];
  s.direct.reset();
  s.mcmc.reset();
  s.bands.clear();
  report.samples.push_back(s);
  const fs::path folder = fresh_folder("alpha_only");
  ReportOptions options;
  options.plots = false;
  write_calibration_report(report, folder, options);
  EXPECT_EQ(data_rows(folder / "fits.csv"), static_cast<int>(s.sample.points.size()));
  EXPECT_EQ(data_rows(folder / "chains.csv"), 0);
  EXPECT_EQ(data_rows(folder / "bands.csv"), 0);
  std::ifstream in(folder / "summary.json");
  const nlohmann::json j = nlohmann::json::parse(in);
  EXPECT_FALSE(j.at("samples")[0].at("methods").contains("mcmc"));
  EXPECT_FALSE(j.contains("comparison"));
}

TEST(ReportNames, CsvFieldsAndFileStems) {
  EXPECT_EQ(csv_field("intact"), "intact");
  EXPECT_EQ(csv_field("a,b"), "\"a,b\"");
  EXPECT_EQ(csv_field("say \"x\""), "\"say \"\"x\"\"\"");
  EXPECT_EQ(sample_file_stem("patient 3/a"), "patient_3_a");
  EXPECT_EQ(sample_file_stem(".hidden"), "_.hidden");
  EXPECT_EQ(sample_file_stem(""), "_");
}
