// The fluid update's software prefetch is a host tuning: every compiled distance gives the
// same populations bit for bit, in double and in float storage, and a distance the update
// is not compiled for is refused with the ones it is. Timing the distances on a lattice
// (to keep the fastest) leaves its state as it was.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "solver/fluid/fluid_lattice.hpp"

using namespace rbcal::solver;

namespace {

// Populations after 20 steps of a disordered state (viscosity contrast, forces, sliding
// walls) on a lattice whose rows span several prefetch distances.
FluidLattice disordered_lattice(int prefetch_distance, bool single_precision) {
  FluidConfig cfg;
  cfg.nx = 5;
  cfg.ny = 6;
  cfg.nz = 300;
  cfg.wall_velocity_bottom = -0.02;
  cfg.wall_velocity_top = 0.02;
  cfg.single_precision = single_precision;
  cfg.prefetch_distance = prefetch_distance;
  FluidLattice fluid(cfg);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> vel(-0.02, 0.02), nu(0.03, 0.3), force(-1e-4, 1e-4);
  for (std::size_t n = 0; n < fluid.node_count(); ++n) {
    fluid.viscosity()[n] = nu(rng);
    for (int d = 0; d < 3; ++d) fluid.force(d)[n] = force(rng);
    fluid.set_equilibrium(n, 1.0, vel(rng), vel(rng), vel(rng));
  }
  return fluid;
}

std::vector<double> after_steps(int prefetch_distance, bool single_precision, bool choose_midway = false) {
  FluidLattice fluid = disordered_lattice(prefetch_distance, single_precision);
  for (int s = 0; s < 20; ++s) {
    if (choose_midway && s == 10) fluid.choose_fastest_prefetch_distance(2);
    fluid.step();
  }
  return fluid.populations();
}

}  // namespace

TEST(PrefetchDistance, EveryCompiledDistanceGivesTheSamePopulations) {
  for (const bool single : {false, true}) {
    const std::vector<double> reference = after_steps(FluidConfig{}.prefetch_distance, single);
    for (const int distance : kPrefetchDistances) {
      SCOPED_TRACE("distance " + std::to_string(distance) + (single ? ", float storage" : ", double storage"));
      EXPECT_EQ(after_steps(distance, single), reference);
    }
  }
}

TEST(PrefetchDistance, RefusesADistanceTheUpdateIsNotCompiledFor) {
  FluidConfig cfg;
  cfg.prefetch_distance = 48;
  try {
    FluidLattice fluid(cfg);
    FAIL() << "accepted a prefetch distance of 48";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("prefetch distance 48 is not one of 0, 8, 16, 32, 64, 96, 128, 256"),
              std::string::npos)
        << e.what();
  }
}

TEST(PrefetchDistance, ChoosingTheFastestLeavesTheStateAsItWas) {
  for (const bool single : {false, true}) {
    SCOPED_TRACE(single ? "float storage" : "double storage");
    FluidLattice fluid = disordered_lattice(64, single);
    for (int s = 0; s < 3; ++s) fluid.step();
    const std::vector<double> before = fluid.populations();
    const std::int64_t steps = fluid.steps_done();
    const int chosen = fluid.choose_fastest_prefetch_distance(2);
    EXPECT_NE(std::find(kPrefetchDistances.begin(), kPrefetchDistances.end(), chosen), kPrefetchDistances.end())
        << chosen;
    EXPECT_EQ(fluid.config().prefetch_distance, chosen);
    EXPECT_EQ(fluid.populations(), before);
    EXPECT_EQ(fluid.steps_done(), steps);
    // And a run that chose midway goes on as one that never did.
    EXPECT_EQ(after_steps(64, single, true), after_steps(64, single));
  }
}

TEST(PrefetchDistance, SettingOneTheUpdateIsNotCompiledForIsRefused) {
  FluidLattice fluid(FluidConfig{});
  EXPECT_THROW(fluid.set_prefetch_distance(7), std::invalid_argument);
  fluid.set_prefetch_distance(32);
  EXPECT_EQ(fluid.config().prefetch_distance, 32);
}
