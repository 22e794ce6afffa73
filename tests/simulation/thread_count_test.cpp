// A dense coupled run gives the same numbers on one thread and on two: the parallel parts
// (membrane forces per cell, the node ordering's copies and stencils, the spreading by
// x-slabs, the inside fraction by column chunks, the fluid update) sum in an order that does
// not depend on the team.
#include <gtest/gtest.h>
#include <omp.h>

#include <filesystem>

#include "solver/simulation/case_runner.hpp"
#include "solver/simulation/simulation_case.hpp"
#include "tests/simulation/interrupted_run.hpp"
#include "tests/simulation/same_run.hpp"

using namespace rbcal::solver;

TEST(Determinism, ADenseCoupledRunDoesNotDependOnTheThreadCount) {
  namespace fs = std::filesystem;
  // The bench case (phi 0.41, 99 cells, lambda 5: the inside fraction is rebuilt), about 40
  // steps with the case-file defaults (coupling interval 2).
  SimulationCase c = read_case(RBCAL_CASES_DIR "/bench_dense_n8.json");
  c.strain_end = 0.021;  // 1920 steps per strain unit
  c.window = {0.005, 0.021};
  c.record_interval = 0.002;
  c.checkpoint_interval = 0.0;
  c.vtk_interval = 0.0;
  const fs::path root = fs::temp_directory_path() / "rbcal_thread_count_test";
  fs::remove_all(root);
  const int threads = omp_get_max_threads();
  omp_set_num_threads(1);
  const nlohmann::json one = test_cases::straight_run(c, root / "one");
  omp_set_num_threads(2);
  const nlohmann::json two = test_cases::straight_run(c, root / "two");
  omp_set_num_threads(threads);
  EXPECT_GE(one["result"]["steps"].get<std::int64_t>(), 40);
  test_cases::expect_same_run(one, root / "one", two, root / "two");
  fs::remove_all(root);
}
