// Single-precision population storage (FluidConfig::single_precision): populations kept in
// 32 bits as f_q - w_q, arithmetic in 64 bits. The stored deviations from the fluid at rest
// are of the order of the flow's velocity U (and of its density changes), and each store
// rounds them to float's unit round-off 6e-8: each step adds errors of order 1e-7 U to the
// velocity field (double storage: 1e-15 U), which a steady state carries at up to a few
// 1e-6 U (measured below: 2.8e-6 at tau 0.6, 2e-6 in Poiseuille flow). The tolerances are
// 1e-5 U for profiles (the steady-state check stops at 1e-7 per interval), 1e-4 for the
// wall stress and Poiseuille's small flow.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "solver/fluid/couette_flow.hpp"
#include "solver/simulation/simulation_case.hpp"

using namespace rbcal::solver;

namespace {

FluidConfig couette_config(double tau, bool single) {
  FluidConfig cfg;
  cfg.nx = 2;
  cfg.ny = 16;
  cfg.nz = 3;
  cfg.viscosity = (tau - 0.5) / 3.0;
  cfg.wall_velocity_bottom = -0.02;
  cfg.wall_velocity_top = 0.03;
  cfg.single_precision = single;
  return cfg;
}

}  // namespace

class SinglePrecisionCouette : public ::testing::TestWithParam<double> {};

// The exact linear profile and wall stress of plane Couette flow (couette_test.cpp), to
// float's resolution.
TEST_P(SinglePrecisionCouette, ReachesLinearProfileAndWallStress) {
  const FluidConfig cfg = couette_config(GetParam(), true);
  FluidLattice fluid(cfg);
  CouetteRun run;
  run.tolerance = 1e-7;  // steps below float's resolution of the profile never settle further
  const CouetteResult r = run_to_steady_couette(fluid, run);
  ASSERT_TRUE(r.converged);
  const double jump = cfg.wall_velocity_top - cfg.wall_velocity_bottom;
  double max_error = 0.0;
  for (int y = 0; y < cfg.ny; ++y) {
    const double exact = cfg.wall_velocity_bottom + jump * (y + 0.5) / cfg.ny;
    max_error = std::max(max_error, std::abs(r.profile[y] - exact));
  }
  std::cout << "tau " << GetParam() << ": largest profile error / velocity jump " << max_error / jump << "\n";
  EXPECT_LT(max_error / jump, 1e-5);
  const double stress = cfg.viscosity * jump / cfg.ny;
  const WallTraction t = fluid.wall_traction();
  EXPECT_NEAR(t.bottom[2] / stress, 1.0, 1e-4);
  EXPECT_NEAR(t.top[2] / stress, -1.0, 1e-4);
}

INSTANTIATE_TEST_SUITE_P(RelaxationTimes, SinglePrecisionCouette, ::testing::Values(0.6, 1.0, 1.7));

// Force-driven Poiseuille flow: TRT with Lambda = 3/16 is exact at half-way walls
// (poiseuille_test.cpp); stored in float, the parabola holds to float's resolution of the
// velocity.
TEST(SinglePrecision, PoiseuilleParabola) {
  FluidConfig cfg;
  cfg.nx = 1;
  cfg.ny = 12;
  cfg.nz = 2;
  cfg.viscosity = (0.8 - 0.5) / 3.0;
  cfg.single_precision = true;
  FluidLattice fluid(cfg);
  const double g = 1e-6;
  for (std::size_t n = 0; n < fluid.node_count(); ++n) fluid.force(2)[n] = g;
  for (int s = 0; s < 20000; ++s) fluid.step();
  const std::vector<double> u = streamwise_profile(fluid);
  const double centre = g / (2.0 * cfg.viscosity) * (cfg.ny / 2.0) * (cfg.ny / 2.0);
  double max_error = 0.0;
  for (int y = 0; y < cfg.ny; ++y) {
    const double exact = g / (2.0 * cfg.viscosity) * (y + 0.5) * (cfg.ny - 0.5 - y);
    max_error = std::max(max_error, std::abs(u[y] - exact));
  }
  std::cout << "largest error / centre-line velocity " << max_error / centre << "\n";
  EXPECT_LT(max_error / centre, 1e-4);
}

// Mass: each store rounds, so it is conserved to float's resolution per step, not exactly;
// over 5000 steps of sheared flow the drift stays far below what would matter.
TEST(SinglePrecision, MassDriftsOnlyByRoundOff) {
  FluidLattice fluid(couette_config(1.0, true));
  const double m0 = fluid.total_mass();
  for (int s = 0; s < 5000; ++s) fluid.step();
  std::cout << "relative mass change " << fluid.total_mass() / m0 - 1.0 << "\n";
  EXPECT_NEAR(fluid.total_mass() / m0, 1.0, 1e-6);
}

// Float and double storage run the same flow: the profiles agree to float's resolution.
TEST(SinglePrecision, AgreesWithDoubleStorage) {
  FluidLattice single(couette_config(0.8, true)), twice(couette_config(0.8, false));
  for (int s = 0; s < 3000; ++s) {
    single.step();
    twice.step();
  }
  const std::vector<double> a = streamwise_profile(single), b = streamwise_profile(twice);
  double d = 0.0;
  for (std::size_t y = 0; y < a.size(); ++y) d = std::max(d, std::abs(a[y] - b[y]));
  std::cout << "largest profile difference " << d << " (velocity jump 0.05)\n";
  EXPECT_LT(d, 1e-5 * 0.05);
  EXPECT_GT(d, 0.0) << "the two storages ran identically: float storage not in use";
}

// numerics.precision in a case file: "float" selects the storage and is written back; any
// other word is refused naming the field.
TEST(SinglePrecision, CaseFieldIsReadWrittenAndChecked) {
  nlohmann::json j = case_to_json(SimulationCase{});
  j["cells"]["placements"] = nlohmann::json::array({{{"center", {0.0, 0.0, 0.0}}}});
  EXPECT_FALSE(case_from_json(j, "case.json").single_precision);
  EXPECT_FALSE(case_to_json(case_from_json(j, "case.json"))["numerics"].contains("precision"));
  j["numerics"]["precision"] = "float";
  const SimulationCase c = case_from_json(j, "case.json");
  EXPECT_TRUE(c.single_precision);
  EXPECT_EQ(case_to_json(c)["numerics"]["precision"], "float");
  j["numerics"]["precision"] = "half";
  try {
    case_from_json(j, "case.json");
    FAIL() << "numerics.precision \"half\" was accepted";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("numerics.precision"), std::string::npos) << e.what();
  }
}
