#pragma once
// The two halves of every stop-and-resume test: a run stopped part-way, as a killed job
// would be (at its last checkpoint), and the options that continue it.
#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>

#include "solver/simulation/case_runner.hpp"

namespace rbcal::solver::test_cases {

// Runs c into dir for max_steps steps, expects it stopped there, and returns the options
// that resume it (resume on, no step limit).
inline RunOptions interrupted_run(const SimulationCase& c, const std::filesystem::path& dir, std::int64_t max_steps) {
  RunOptions part;
  part.output_dir = dir.string();
  part.max_steps = max_steps;
  EXPECT_EQ(run_case(c, part)["status"], "interrupted");
  part.max_steps = 0;
  part.resume = true;
  return part;
}

// The same case run to its end without a stop, into dir.
inline nlohmann::json straight_run(const SimulationCase& c, const std::filesystem::path& dir) {
  RunOptions straight;
  straight.output_dir = dir.string();
  return run_case(c, straight);
}

}  // namespace rbcal::solver::test_cases
