// Conservation: collision and streaming with sliding walls conserve mass exactly (the
// moving-wall terms cancel pairwise for a tangential wall velocity), and in a periodic
// box the Guo force adds exactly sum(F) of momentum per step.
#include <gtest/gtest.h>

#include <cmath>
#include <omp.h>

#include <random>
#include <vector>

#include "solver/fluid/d3q19.hpp"
#include "solver/fluid/fluid_lattice.hpp"

using namespace rbcal::solver;

namespace {

// A disordered state: random velocities, viscosities (contrast 10) and forces.
void randomise(FluidLattice& fluid, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> vel(-0.02, 0.02), nu(0.02, 0.2), force(-1e-4, 1e-4),
      rho(0.98, 1.02);
  for (std::size_t n = 0; n < fluid.node_count(); ++n) {
    fluid.viscosity()[n] = nu(rng);
    for (int d = 0; d < 3; ++d) fluid.force(d)[n] = force(rng);
    fluid.set_equilibrium(n, rho(rng), vel(rng), vel(rng), vel(rng));
  }
}

std::array<double, 3> total_momentum(const FluidLattice& fluid) {
  std::array<double, 3> p{0, 0, 0};
  for (int q = 0; q < d3q19::Q; ++q)
    for (std::size_t n = 0; n < fluid.node_count(); ++n)
      for (int d = 0; d < 3; ++d) p[d] += d3q19::c[q][d] * fluid.population(q, n);
  return p;
}

}  // namespace

TEST(Conservation, MassWithSlidingWallsAndForcing) {
  FluidConfig cfg;
  cfg.nx = 6;
  cfg.ny = 7;
  cfg.nz = 9;
  cfg.wall_velocity_bottom = -0.03;
  cfg.wall_velocity_top = 0.05;
  FluidLattice fluid(cfg);
  randomise(fluid, 42);
  const double m0 = fluid.total_mass();
  for (int s = 0; s < 500; ++s) fluid.step();
  EXPECT_NEAR(fluid.total_mass() / m0, 1.0, 1e-13);
}

TEST(Conservation, MomentumGainEqualsTotalForceInPeriodicBox) {
  FluidConfig cfg;
  cfg.nx = 5;
  cfg.ny = 6;
  cfg.nz = 7;
  cfg.y_boundary = WallNormalBoundary::Periodic;
  FluidLattice fluid(cfg);
  randomise(fluid, 7);
  std::array<double, 3> force_sum{0, 0, 0};
  for (int d = 0; d < 3; ++d)
    for (std::size_t n = 0; n < fluid.node_count(); ++n) force_sum[d] += fluid.force(d)[n];
  const std::array<double, 3> p0 = total_momentum(fluid);
  const int steps = 300;
  for (int s = 0; s < steps; ++s) fluid.step();
  const std::array<double, 3> p1 = total_momentum(fluid);
  for (int d = 0; d < 3; ++d) EXPECT_NEAR(p1[d] - p0[d], steps * force_sum[d], 1e-12) << "component " << d;
}

TEST(Conservation, MomentsReturnWhatWasSet) {
  FluidConfig cfg;
  cfg.nx = cfg.ny = cfg.nz = 2;
  FluidLattice fluid(cfg);
  const std::size_t n = fluid.index(1, 0, 1);
  fluid.force(0)[n] = 1e-3;
  fluid.force(2)[n] = -2e-3;
  fluid.set_equilibrium(n, 1.01, 0.01, -0.02, 0.03);
  const NodeMoments m = fluid.moments(n);
  EXPECT_NEAR(m.rho, 1.01, 1e-15);
  EXPECT_NEAR(m.ux, 0.01, 1e-15);
  EXPECT_NEAR(m.uy, -0.02, 1e-15);
  EXPECT_NEAR(m.uz, 0.03, 1e-15);
}

TEST(Determinism, ResultDoesNotDependOnThreadCount) {
  // Large enough (> 4096 nodes) for the update to run on the OpenMP team.
  auto run = [](int threads) {
    omp_set_num_threads(threads);
    FluidConfig cfg;
    cfg.nx = 16;
    cfg.ny = 18;
    cfg.nz = 20;
    cfg.wall_velocity_bottom = -0.02;
    cfg.wall_velocity_top = 0.02;
    FluidLattice fluid(cfg);
    randomise(fluid, 3);
    for (int s = 0; s < 20; ++s) fluid.step();
    std::vector<double> f;
    for (int q = 0; q < d3q19::Q; ++q)
      for (std::size_t n = 0; n < fluid.node_count(); ++n) f.push_back(fluid.population(q, n));
    return f;
  };
  const int threads = omp_get_max_threads();
  const std::vector<double> one = run(1);
  const std::vector<double> two = run(2);
  omp_set_num_threads(threads);
  ASSERT_EQ(one.size(), two.size());
  for (std::size_t i = 0; i < one.size(); ++i) ASSERT_EQ(one[i], two[i]) << "entry " << i;
}
