// Force-driven Poiseuille flow between resting walls. The exact solution with walls at
// y = -1/2 and y = ny - 1/2 is u_z(y) = g/(2 nu) (y + 1/2)(ny - 1/2 - y). TRT with the
// magic parameter Lambda = 3/16 reproduces this parabola exactly (to round-off) for any
// relaxation time (Ginzburg, Verhaeghe & d'Humieres, Commun. Comput. Phys. 3 (2008) 427,
// section 4); with another Lambda the walls slip by an amount that depends on tau.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "solver/fluid/couette_flow.hpp"

using namespace rbcal::solver;

namespace {

// Largest deviation from the parabola relative to the centre-line velocity.
double poiseuille_error(double tau, double magic) {
  FluidConfig cfg;
  cfg.nx = 1;
  cfg.ny = 12;
  cfg.nz = 2;
  cfg.viscosity = (tau - 0.5) / 3.0;
  cfg.magic = magic;
  FluidLattice fluid(cfg);
  const double g = 1e-6;
  for (std::size_t n = 0; n < fluid.node_count(); ++n) fluid.force(2)[n] = g;

  std::vector<double> previous = streamwise_profile(fluid);
  for (int block = 0; block < 2000; ++block) {
    for (int s = 0; s < 100; ++s) fluid.step();
    std::vector<double> current = streamwise_profile(fluid);
    double change = 0.0;
    for (int y = 0; y < cfg.ny; ++y) change = std::max(change, std::abs(current[y] - previous[y]));
    previous = current;
    if (change < 1e-22) break;
  }
  const double centre = g / (2.0 * cfg.viscosity) * (cfg.ny / 2.0) * (cfg.ny / 2.0);
  double max_error = 0.0;
  for (int y = 0; y < cfg.ny; ++y) {
    const double exact = g / (2.0 * cfg.viscosity) * (y + 0.5) * (cfg.ny - 0.5 - y);
    max_error = std::max(max_error, std::abs(previous[y] - exact));
  }
  return max_error / centre;
}

}  // namespace

class Poiseuille : public ::testing::TestWithParam<double> {};

TEST_P(Poiseuille, MagicTrtIsExactAtHalfwayWalls) {
  EXPECT_LT(poiseuille_error(GetParam(), 3.0 / 16.0), 1e-10);
}

INSTANTIATE_TEST_SUITE_P(RelaxationTimes, Poiseuille, ::testing::Values(0.55, 0.8, 1.0, 2.0, 4.0));

TEST(PoiseuilleControl, OtherMagicParameterMovesTheWalls) {
  // With Lambda = 1/4 the effective walls move off mid-link: an error far above
  // round-off, which shows that the test above can fail.
  const double error = poiseuille_error(1.0, 0.25);
  std::cout << "Lambda = 1/4: relative error " << error << "\n";
  EXPECT_GT(error, 1e-4);
}
