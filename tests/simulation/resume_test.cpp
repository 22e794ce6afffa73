// A run stopped part-way (as a killed job would be, at its last checkpoint) and resumed
// gives exactly the result of an uninterrupted run: same averages, same time series.
#include <gtest/gtest.h>

#include <filesystem>

#include "solver/simulation/case_runner.hpp"
#include "tests/simulation/interrupted_run.hpp"
#include "tests/simulation/same_run.hpp"
#include "tests/simulation/small_sheared_case.hpp"

using namespace rbcal::solver;

namespace {

SimulationCase small_case() { return test_cases::small_sheared_case(MembraneLaw::NeoHookean); }

}  // namespace

// Runs c straight and again stopped after max_steps and resumed; both must agree bit for bit.
void expect_resume_equals_straight(const SimulationCase& c, const std::string& name, std::int64_t max_steps) {
  namespace fs = std::filesystem;
  // Outside the source tree, whatever directory the test is started from.
  const fs::path root = fs::temp_directory_path() / ("rbcal_resume_test_" + name);
  fs::remove_all(root);
  const nlohmann::json a = test_cases::straight_run(c, root / "straight");
  const RunOptions resume = test_cases::interrupted_run(c, root / "interrupted", max_steps);
  const nlohmann::json b = run_case(c, resume);
  test_cases::expect_same_run(a, root / "straight", b, root / "interrupted");
  fs::remove_all(root);
}

TEST(Resume, InterruptedAndResumedRunEqualsStraightRun) {
  expect_resume_equals_straight(small_case(), "capsule", 37);  // between checkpoints and records
}

// The shipped dense example (phi 0.31, 171 cells, data/cases/dense_suspension.json), cut to
// about 38 steps: a restart in the middle continues it bit for bit.
TEST(Resume, ShippedDenseExampleRestartsBitIdentically) {
  SimulationCase c = read_case(RBCAL_CASES_DIR "/dense_suspension.json");
  ASSERT_GE(c.target_phi, 0.3);
  c.strain_end = 0.02;  // 1875 steps per strain unit
  c.window = {0.005, 0.02};
  c.record_interval = 0.002;
  c.checkpoint_interval = 0.01;
  c.vtk_interval = 0.0;
  expect_resume_equals_straight(c, "dense", 27);
}

// A run at coupling interval 2 stopped part-way continues at interval 1 only when asked
// (RunOptions::coupling_interval, `rbcal simulate --resume --coupling-interval 1`), and its
// result says from which strain; the case block keeps the case's own interval.
TEST(Resume, ContinuesUnderAnotherCouplingIntervalOnlyWhenAsked) {
  namespace fs = std::filesystem;
  const fs::path root = fs::temp_directory_path() / "rbcal_resume_test_interval";
  fs::remove_all(root);
  SimulationCase c = small_case();
  c.coupling_interval = 2;
  const nlohmann::json a = test_cases::straight_run(c, root / "straight");
  EXPECT_FALSE(a["result"].contains("coupling_interval_changes"));

  RunOptions part = test_cases::interrupted_run(c, root / "switched", 37);
  SimulationCase other = c;
  other.coupling_interval = 1;
  EXPECT_THROW(run_case(other, part), std::runtime_error);  // not without asking

  part.coupling_interval = 1;
  // A run that fails after the switch resumes from the same checkpoint again (as
  // `rbcal library generate` does): the switch is one change, not one per attempt.
  const fs::path saved = root / "switched" / "checkpoint.bin", copy = root / "checkpoint_at_switch.bin";
  fs::copy_file(saved, copy);
  part.max_steps = 5;
  ASSERT_EQ(run_case(c, part)["status"], "interrupted");
  fs::copy_file(copy, saved, fs::copy_options::overwrite_existing);
  part.max_steps = 0;
  const nlohmann::json b = run_case(c, part);
  ASSERT_TRUE(b["result"].contains("coupling_interval_changes")) << b.dump();
  EXPECT_EQ(b["result"]["coupling_interval_changes"].size(), 1u) << b["result"].dump();
  const nlohmann::json& change = b["result"]["coupling_interval_changes"][0];
  EXPECT_EQ(change["from"], 2);
  EXPECT_EQ(change["to"], 1);
  EXPECT_GT(change["at_strain"].get<double>(), 0.0);
  EXPECT_LT(change["at_strain"].get<double>(), c.strain_end);
  EXPECT_EQ(b["numerics"]["coupling_interval"], 2);
  // The membrane step is a numerical choice: eta_re - 1 moves by far less than 1 %.
  const double sp_a = a["result"]["eta_re"].get<double>() - 1.0, sp_b = b["result"]["eta_re"].get<double>() - 1.0;
  EXPECT_NE(sp_a, sp_b);
  EXPECT_NEAR(sp_b, sp_a, 0.01 * sp_a);
  fs::remove_all(root);
}

// A finished run continued to a later strain (run.strain_end and the window raised in the
// case, then --resume) equals a run made to that strain at once: its last checkpoint, at its
// end, is where the continuation starts.
TEST(Resume, FinishedRunExtendsToALaterStrain) {
  namespace fs = std::filesystem;
  const fs::path root = fs::temp_directory_path() / "rbcal_resume_test_extend";
  fs::remove_all(root);
  SimulationCase longer = small_case();
  longer.strain_end = 0.3;
  longer.window = {0.1, 0.3};
  const nlohmann::json a = test_cases::straight_run(longer, root / "straight");

  RunOptions first;
  first.output_dir = (root / "extended").string();
  ASSERT_TRUE(run_case(small_case(), first).contains("result"));
  first.resume = true;
  const nlohmann::json b = run_case(longer, first);
  test_cases::expect_same_run(a, root / "straight", b, root / "extended");
  fs::remove_all(root);
}
