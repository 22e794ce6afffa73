// Two-layer plane Couette flow: plasma-like fluid below, a ten times more viscous fluid
// above (the per-node viscosity that the cells' interiors will use). Shear stress is
// uniform across the gap, so each layer has a linear profile with slopes in the inverse
// ratio of the viscosities: with the interface mid-way between the last node of one
// layer and the first of the other, and walls mid-link,
//   u(y) = U_b + tau_xy (y + 1/2) / mu_1                    (lower layer, h_1 nodes)
//   u(y) = U_t - tau_xy (ny - 1/2 - y) / mu_2               (upper layer)
//   tau_xy = (U_t - U_b) / (h_1 / mu_1 + h_2 / mu_2).
#include <gtest/gtest.h>

#include <cmath>

#include "solver/fluid/couette_flow.hpp"

using namespace rbcal::solver;

TEST(TwoLayerCouette, MatchesPiecewiseLinearProfile) {
  FluidConfig cfg;
  cfg.nx = 1;
  cfg.ny = 20;
  cfg.nz = 1;
  cfg.wall_velocity_bottom = -0.01;
  cfg.wall_velocity_top = 0.01;
  FluidLattice fluid(cfg);
  const int h1 = 10;
  const double nu1 = 0.05, nu2 = 0.5;
  for (int y = 0; y < cfg.ny; ++y) fluid.viscosity()[fluid.index(0, y, 0)] = y < h1 ? nu1 : nu2;

  CouetteRun run;
  run.tolerance = 1e-13;
  const CouetteResult r = run_to_steady_couette(fluid, run);
  ASSERT_TRUE(r.converged);

  const double jump = cfg.wall_velocity_top - cfg.wall_velocity_bottom;
  const double h2 = cfg.ny - h1;
  const double stress = jump / (h1 / nu1 + h2 / nu2);
  double max_error = 0.0;
  for (int y = 0; y < cfg.ny; ++y) {
    const double exact = y < h1 ? cfg.wall_velocity_bottom + stress * (y + 0.5) / nu1
                                : cfg.wall_velocity_top - stress * (cfg.ny - 0.5 - y) / nu2;
    max_error = std::max(max_error, std::abs(r.profile[y] - exact));
  }
  EXPECT_LT(max_error / jump, 1e-8);
  const WallTraction t = fluid.wall_traction();
  EXPECT_NEAR(t.bottom[2] / stress, 1.0, 1e-8);
  EXPECT_NEAR(t.top[2] / stress, -1.0, 1e-8);
}
