// Reading rheometer CSV files: a good file with two samples, the plasma plateau and the
// propagated errors of eta_re, and a table of malformed files that must each be rejected with
// a message naming the file, the line and the field.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "calibration/calibration_input.hpp"
#include "calibration/rheometer_data.hpp"
#include "../scratch_path.hpp"
#include "shipped_sample_all_hematocrits.hpp"

using namespace rbcal::calibration;
namespace fs = std::filesystem;

namespace {

const char* kHeader = "sample,kind,phi,shear_rate_per_s,viscosity_mPa_s,sd_mPa_s,n\n";

fs::path write_temp(const std::string& name, const std::string& text) {
  const fs::path dir = rbcal::testing_support::scratch_path("csv");
  fs::create_directories(dir);
  const fs::path path = dir / name;
  std::ofstream(path) << text;
  return path;
}

}  // namespace

TEST(RheometerData, ReadsSamplesPlasmaPlateauAndPropagatedErrors) {
  const std::string text = std::string("# provenance: synthetic test file\n") + kHeader +
                           "intact,plasma,0,1,2.0,0.5,3\n"  // below the plateau: ignored for eta0
                           "intact,plasma,0,20,1.5,0.03,4\n"
                           "intact,plasma,0,100,1.6,0.03,4\n"
                           "intact,suspension,0.4,100,6.2,0.2,4\n"
                           "\n"
                           "hard,plasma,0,50,1.55,0.02,1\n"
                           "hard,suspension,0.2,50,4.0,0.1,1\n";
  const fs::path path = write_temp("good.csv", text);
  const RheometerData data = read_rheometer_csv(path);
  ASSERT_EQ(data.rows.size(), 6u);
  EXPECT_EQ(data.provenance.at(0), "provenance: synthetic test file");
  EXPECT_NEAR(data.rows[3].viscosity, 6.2e-3, 1e-15);  // mPa s -> Pa s
  EXPECT_EQ(data.rows[3].line, 6);

  const CalibrationInput input = make_calibration_input(data);
  ASSERT_EQ(input.samples.size(), 2u);
  const SampleData& intact = input.sample("intact");
  EXPECT_EQ(intact.plasma.plateau_rows, 2);
  EXPECT_NEAR(intact.plasma.eta0, 1.55e-3, 1e-15);
  // Scatter: s = 0.0707 mPa s over 2 rows -> 0.05; propagated: sqrt(2 * 0.03^2 / 4) / 2 = 0.0106.
  EXPECT_NEAR(intact.plasma.scatter_standard_error, 0.05e-3, 1e-12);
  EXPECT_NEAR(intact.plasma.propagated_standard_error, std::sqrt(2 * 0.03 * 0.03 / 4) / 2 * 1e-3, 1e-12);
  EXPECT_NEAR(intact.plasma.standard_error, 0.05e-3, 1e-12);
  ASSERT_EQ(intact.points.size(), 1u);
  const auto& p = intact.points[0];
  EXPECT_NEAR(p.eta_re, 6.2 / 1.55, 1e-12);
  EXPECT_NEAR(p.eta_re_sd, p.eta_re * std::hypot(0.2 / 2 / 6.2, 0.05 / 1.55), 1e-12);

  // A plateau threshold above every plasma row is an error naming the sample.
  EXPECT_THROW(make_calibration_input(data, {200.0}), RheometerDataError);
  EXPECT_THROW(input.sample("patient"), std::out_of_range);
}

struct BadCsv {
  std::string name;
  std::string text;
  int line;
  std::string field;
  std::string words;  // part of the explanation
};

TEST(RheometerData, EveryMalformedFileNamesFileLineAndField) {
  const std::string good_plasma = "s,plasma,0,20,1.5,0.03,4\n";
  const std::vector<BadCsv> table = {
      {"no_header.csv", "s,plasma,0,20,1.5,0.03,4\n", 1, "sample", "missing from the header"},
      {"missing_column.csv", "sample,kind,phi,shear_rate_per_s,viscosity_mPa_s,n\n" + good_plasma, 1, "sd_mPa_s",
       "missing from the header"},
      {"extra_column.csv", "sample,kind,phi,shear_rate_per_s,viscosity_mPa_s,sd_mPa_s,n,temp\n", 1, "temp",
       "unknown column"},
      {"short_row.csv", kHeader + good_plasma + "s,suspension,0.4,20,5.0,0.1\n", 3, "(row)",
       "expected 7 fields, found 6"},
      {"long_row.csv", kHeader + good_plasma + "s,suspension,0.4,20,5.0,0.1,3,9\n", 3, "(row)",
       "expected 7 fields, found 8"},
      {"non_numeric.csv", kHeader + good_plasma + "s,suspension,0.4,20,abc,0.1,3\n", 3, "viscosity_mPa_s",
       "not a finite number"},
      {"empty_number.csv", kHeader + good_plasma + "s,suspension,,20,5.0,0.1,3\n", 3, "phi", "empty"},
      {"zero_viscosity.csv", kHeader + good_plasma + "s,suspension,0.4,20,0,0.1,3\n", 3, "viscosity_mPa_s",
       "must be positive"},
      {"negative_rate.csv", kHeader + good_plasma + "s,suspension,0.4,-1,5.0,0.1,3\n", 3, "shear_rate_per_s",
       "must be positive"},
      {"negative_sd.csv", kHeader + good_plasma + "s,suspension,0.4,20,5.0,-0.1,3\n", 3, "sd_mPa_s",
       "must not be negative"},
      {"zero_repeats.csv", kHeader + good_plasma + "s,suspension,0.4,20,5.0,0.1,0\n", 3, "n", "integer >= 1"},
      {"fractional_repeats.csv", kHeader + good_plasma + "s,suspension,0.4,20,5.0,0.1,2.5\n", 3, "n",
       "integer >= 1"},
      {"phi_one.csv", kHeader + good_plasma + "s,suspension,1.0,20,5.0,0.1,3\n", 3, "phi", "(0, 1)"},
      {"phi_zero_suspension.csv", kHeader + good_plasma + "s,suspension,0,20,5.0,0.1,3\n", 3, "phi", "(0, 1)"},
      {"plasma_with_phi.csv", kHeader + std::string("s,plasma,0.1,20,1.5,0.03,4\n"), 2, "phi", "phi = 0"},
      {"duplicate.csv", kHeader + good_plasma + "s,suspension,0.4,20,5.0,0.1,3\n# note\ns,suspension,0.4,20,5.1,0.1,3\n",
       5, "shear_rate_per_s", "duplicate of line 3"},
      {"no_plasma.csv", kHeader + good_plasma + "t,suspension,0.4,20,5.0,0.1,3\nt,suspension,0.2,20,3.0,0.1,3\n", 3,
       "sample", "'t' has no plasma rows"},
      {"unknown_kind.csv", kHeader + good_plasma + "s,blood,0.4,20,5.0,0.1,3\n", 3, "kind", "unknown kind 'blood'"},
      {"empty_sample.csv", kHeader + good_plasma + ",suspension,0.4,20,5.0,0.1,3\n", 3, "sample", "empty sample"},
      {"no_rows.csv", std::string("# only a comment\n") + kHeader, 2, "(row)", "no data rows"},
      {"assumed_without_sd.csv", kHeader + std::string("s,plasma_assumed,0,0,1.4,0,1\n"), 2, "sd_mPa_s",
       "needs its standard deviation"},
      {"assumed_with_rate.csv", kHeader + std::string("s,plasma_assumed,0,20,1.4,0.2,1\n"), 2, "shear_rate_per_s",
       "write 0"},
      {"assumed_and_measured.csv", kHeader + good_plasma + "s,plasma_assumed,0,0,1.4,0.2,1\n", 3, "kind",
       "already has measured plasma rows"},
      {"assumed_twice.csv", kHeader + std::string("s,plasma_assumed,0,0,1.4,0.2,1\ns,plasma_assumed,0,0,1.5,0.2,1\n"),
       3, "kind", "already has a plasma_assumed row"},
  };
  for (const auto& bad : table) {
    SCOPED_TRACE(bad.name);
    const fs::path path = write_temp(bad.name, bad.text);
    try {
      read_rheometer_csv(path);
      ADD_FAILURE() << "no error for " << bad.name;
    } catch (const RheometerDataError& e) {
      const std::string expected_prefix = path.string() + ":" + std::to_string(bad.line) + ": field " + bad.field + ": ";
      EXPECT_EQ(std::string(e.what()).rfind(expected_prefix, 0), 0u) << e.what();
      EXPECT_NE(std::string(e.what()).find(bad.words), std::string::npos) << e.what();
      EXPECT_EQ(e.line(), bad.line);
      EXPECT_EQ(e.field(), bad.field);
    }
  }
}

TEST(RheometerData, MissingFileIsNamed) {
  try {
    read_rheometer_csv("/nonexistent/rheometer.csv");
    FAIL();
  } catch (const RheometerDataError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/rheometer.csv"), std::string::npos);
  }
}

TEST(RheometerData, AnAssumedPlasmaViscosityStandsInForPlasmaRows) {
  // A sample without plasma measurements (the shipped Kim et al. 2017 digitisation) with an
  // assumed eta0 = 1.45 +- 0.20 mPa s: eta_re uses it, and its error enters every point.
  const fs::path path = write_temp("assumed.csv", std::string(kHeader) +
                                                      "k,plasma_assumed,0,0,1.45,0.20,1\n"
                                                      "k,suspension,0.45,100,4.35,0.0,1\n");
  const CalibrationInput input = read_calibration_input(path);
  const SampleData& k = input.sample("k");
  EXPECT_TRUE(k.plasma.assumed);
  EXPECT_NEAR(k.plasma.eta0, 1.45e-3, 1e-15);
  EXPECT_NEAR(k.plasma.standard_error, 0.20e-3, 1e-15);
  ASSERT_EQ(k.points.size(), 1u);
  EXPECT_NEAR(k.points[0].eta_re, 3.0, 1e-12);
  EXPECT_NEAR(k.points[0].eta_re_sd, 3.0 * 0.20 / 1.45, 1e-12);  // the assumption's error alone
}

TEST(RheometerData, TheShippedSampleReads) {
  const CalibrationInput input = read_calibration_input(RBCAL_SAMPLES_DIR "/kim2017_whole_blood.csv");
  ASSERT_EQ(input.samples.size(), 1u);
  EXPECT_TRUE(input.samples[0].plasma.assumed);
  EXPECT_EQ(input.samples[0].points.size(), 40u);  // 20 shear rates x hematocrit 0.35, 0.45 (0.55 excluded)
  for (const auto& p : input.samples[0].points) EXPECT_LT(p.phi, 0.5);
  const CalibrationInput all = read_calibration_input(test_models::shipped_sample_with_all_hematocrits());
  EXPECT_EQ(all.samples.at(0).points.size(), 60u);  // restored: hematocrit 0.55 too
}

TEST(RheometerData, AByteOrderMarkIsNotPartOfTheHeader) {
  // Excel's "CSV UTF-8" writes EF BB BF first; the first column was then "\xEF\xBB\xBFsample".
  const fs::path path = write_temp("bom.csv", std::string("\xEF\xBB\xBF") + kHeader +
                                                   "s,plasma,0,100,1.2,0.01,3\ns,suspension,0.4,100,4.0,0.1,3\n");
  const RheometerData data = read_rheometer_csv(path);
  ASSERT_EQ(data.sample_names().size(), 1u);
  EXPECT_EQ(data.sample_names()[0], "s");
}

TEST(RheometerData, AFolderIsNamedAsAFolder) {
  const fs::path dir = rbcal::testing_support::scratch_path("folder.csv");
  fs::create_directories(dir);
  try {
    read_rheometer_csv(dir);
    FAIL() << "a folder was read as a CSV file";
  } catch (const RheometerDataError& e) {
    EXPECT_NE(std::string(e.what()).find("is a folder"), std::string::npos) << e.what();
  }
}
