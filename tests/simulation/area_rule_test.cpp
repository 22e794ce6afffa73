// cells.skalak_c_per_Ca: the membrane runs with C = max(skalak_c, skalak_c_per_Ca * Ca);
// the field is read, written back and checked; a checkpoint resumes under any rule that
// gives the same C, and only then.
#include <gtest/gtest.h>

#include <filesystem>

#include "formats/format_error.hpp"
#include "solver/simulation/case_runner.hpp"
#include "solver/simulation/simulation_case.hpp"
#include "tests/simulation/interrupted_run.hpp"
#include "tests/simulation/small_sheared_case.hpp"

using namespace rbcal::solver;

namespace {

SimulationCase small_case(double skalak_c, double per_ca) {
  SimulationCase c = test_cases::small_sheared_case(MembraneLaw::Skalak);
  c.skalak_c = skalak_c;
  c.skalak_c_per_ca = per_ca;  // Ca 0.1
  return c;
}

}  // namespace

TEST(AreaRule, EffectiveCIsTheLargerOfTheFloorAndTheRule) {
  EXPECT_DOUBLE_EQ(small_case(10.0, 0.0).effective_skalak_c(), 10.0);
  EXPECT_DOUBLE_EQ(small_case(10.0, 125.0).effective_skalak_c(), 12.5);   // 125 * Ca 0.1
  EXPECT_DOUBLE_EQ(small_case(20.0, 125.0).effective_skalak_c(), 20.0);   // the floor wins
}

TEST(AreaRule, ReadWrittenBackAndChecked) {
  nlohmann::json j = case_to_json(small_case(10.0, 125.0));
  EXPECT_EQ(j["cells"]["skalak_c_per_Ca"], 125.0);
  EXPECT_FALSE(case_to_json(small_case(10.0, 0.0))["cells"].contains("skalak_c_per_Ca"));
  const SimulationCase back = case_from_json(j, "rule.json");
  EXPECT_DOUBLE_EQ(back.skalak_c_per_ca, 125.0);
  EXPECT_DOUBLE_EQ(back.effective_skalak_c(), 12.5);
  j["cells"]["skalak_c_per_Ca"] = -1.0;
  try {
    case_from_json(j, "rule.json");
    FAIL() << "a negative skalak_c_per_Ca was accepted";
  } catch (const rbcal::formats::FormatError& e) {
    EXPECT_NE(std::string(e.what()).find("rule.json"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("cells.skalak_c_per_Ca"), std::string::npos) << e.what();
  }
}

TEST(AreaRule, CheckpointResumesUnderARuleGivingTheSameC) {
  namespace fs = std::filesystem;
  const fs::path root = fs::temp_directory_path() / "rbcal_area_rule_test";
  fs::remove_all(root);
  const SimulationCase explicit_c = small_case(12.5, 0.0), rule = small_case(10.0, 125.0);
  const nlohmann::json a = test_cases::straight_run(explicit_c, root / "straight");
  const RunOptions part = test_cases::interrupted_run(explicit_c, root / "interrupted", 20);
  // Another C (the rule at another floor) is another state.
  EXPECT_THROW(run_case(small_case(10.0, 150.0), part), std::runtime_error);
  const nlohmann::json b = run_case(rule, part);
  EXPECT_EQ(a["result"]["eta_re"].get<double>(), b["result"]["eta_re"].get<double>());
  EXPECT_EQ(b["result"]["skalak_c"].get<double>(), 12.5);
  EXPECT_EQ(b["cells"]["skalak_c_per_Ca"], 125.0);
  fs::remove_all(root);
}
