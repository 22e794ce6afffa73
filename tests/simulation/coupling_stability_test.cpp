// numerics.coupling_interval "auto": the largest interval up to 2 within the coupling's
// measured stability bound K_s,lu k (sum phi^2)^3 <= 0.154 (docs/performance.md, "The
// stability bound per kernel"). The dense bench case (Ca 0.1, C 100, N_a 8, Re 0.2) sits at
// 96 % of the bound at k = 2 and runs there; at Ca 0.05 it needs 1.
#include <gtest/gtest.h>

#include <string>

#include "formats/json_file.hpp"
#include "solver/simulation/detail/coupling_stability.hpp"
#include "solver/simulation/simulation_case.hpp"

using namespace rbcal::solver;

namespace {

nlohmann::json bench_case(double ca) {
  nlohmann::json j = rbcal::formats::read_json_file(std::string(RBCAL_CASES_DIR) + "/bench_dense_n8.json");
  j["params"]["Ca"] = ca;
  return j;
}

}  // namespace

TEST(CouplingStability, BenchCaseSitsAtTheMeasuredFraction) {
  const SimulationCase c = case_from_json(bench_case(0.1), "bench");
  EXPECT_NEAR(2.0 * coupling_stiffness(c) / kCouplingStabilityBound, 0.96, 0.01);
}

TEST(CouplingStability, AutoTakesTwoWhereTheBoundAllowsAndOneElsewhere) {
  const SimulationCase soft = case_from_json(bench_case(0.1), "bench");  // no value: auto
  EXPECT_EQ(soft.coupling_interval, 2);
  EXPECT_TRUE(soft.coupling_interval_chosen);
  nlohmann::json stiff = bench_case(0.05);
  stiff["numerics"]["coupling_interval"] = "auto";
  const SimulationCase c = case_from_json(stiff, "bench");
  EXPECT_EQ(c.coupling_interval, 1);
  EXPECT_LE(c.coupling_interval * coupling_stiffness(c), kCouplingStabilityBound);
}

TEST(CouplingStability, AGivenIntervalIsKeptAndWrittenAsANumber) {
  nlohmann::json j = bench_case(0.05);
  j["numerics"]["coupling_interval"] = 3;
  const SimulationCase c = case_from_json(j, "bench");
  EXPECT_EQ(c.coupling_interval, 3);
  EXPECT_FALSE(c.coupling_interval_chosen);
  EXPECT_EQ(case_to_json(case_from_json(bench_case(0.05), "bench"))["numerics"]["coupling_interval"], 1);
}

TEST(CouplingStability, OtherWordsAreRefusedNamingTheField) {
  nlohmann::json j = bench_case(0.1);
  j["numerics"]["coupling_interval"] = "fast";
  try {
    case_from_json(j, "bench.json");
    FAIL() << "accepted \"fast\"";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("numerics.coupling_interval"), std::string::npos) << e.what();
  }
}
