// Plane Couette flow: with half-way bounce-back and the moving-wall term, the steady
// lattice solution is the exact linear profile u_z = U_b + (U_t - U_b)(y + 1/2)/ny for
// any relaxation time (walls mid-link at y = -1/2 and y = ny - 1/2), and the momentum
// exchanged with each wall is the viscous stress rho nu du/dy.
#include <gtest/gtest.h>

#include <cmath>

#include "solver/fluid/couette_flow.hpp"

using namespace rbcal::solver;

class Couette : public ::testing::TestWithParam<double> {};

TEST_P(Couette, ReachesLinearProfileAndWallStress) {
  const double tau = GetParam();
  FluidConfig cfg;
  cfg.nx = 2;
  cfg.ny = 16;
  cfg.nz = 3;
  cfg.viscosity = (tau - 0.5) / 3.0;
  cfg.wall_velocity_bottom = -0.02;
  cfg.wall_velocity_top = 0.03;
  FluidLattice fluid(cfg);
  CouetteRun run;
  run.tolerance = 1e-13;
  const CouetteResult r = run_to_steady_couette(fluid, run);
  ASSERT_TRUE(r.converged);

  const double jump = cfg.wall_velocity_top - cfg.wall_velocity_bottom;
  double max_error = 0.0;
  for (int y = 0; y < cfg.ny; ++y) {
    const double exact = cfg.wall_velocity_bottom + jump * (y + 0.5) / cfg.ny;
    max_error = std::max(max_error, std::abs(r.profile[y] - exact));
  }
  EXPECT_LT(max_error / jump, 1e-8);
  EXPECT_NEAR(r.measured_shear_rate / r.imposed_shear_rate, 1.0, 1e-8);

  const double stress = cfg.viscosity * jump / cfg.ny;  // rho = 1
  const WallTraction t = fluid.wall_traction();
  EXPECT_NEAR(t.bottom[2] / stress, 1.0, 1e-8);
  EXPECT_NEAR(t.top[2] / stress, -1.0, 1e-8);
  EXPECT_NEAR(t.bottom[0], 0.0, 1e-12);
  EXPECT_NEAR(t.top[0], 0.0, 1e-12);
}

INSTANTIATE_TEST_SUITE_P(RelaxationTimes, Couette, ::testing::Values(0.6, 1.0, 1.7));
