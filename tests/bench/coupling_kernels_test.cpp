// The coupling-kernel bench times both kernels over every node, on one thread, and leaves the
// caller's thread count as it was.
#include "bench/coupling_kernels.hpp"

#include <gtest/gtest.h>
#include <omp.h>

#include <random>
#include <stdexcept>

namespace rbcal::bench {
namespace {

using solver::Vec3;

TEST(CouplingKernels, TimesEveryNodeOnOneThreadAndRestoresTheThreads) {
  solver::FluidConfig lattice;
  lattice.nx = 16;
  lattice.ny = 12;
  lattice.nz = 16;
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> px(-4.0, 20.0), py(1.0, 10.0), pz(-4.0, 20.0), f(-1.0, 1.0);
  std::vector<std::vector<Vec3>> x(2), force(2);
  for (int c = 0; c < 2; ++c)
    for (int i = 0; i < 150 + 50 * c; ++i) {
      x[c].emplace_back(px(rng), py(rng), pz(rng));
      force[c].emplace_back(f(rng), f(rng), f(rng));
    }
  const int threads = omp_get_max_threads();
  solver::FluidLattice fluid(lattice);
  const CouplingKernelTimings t = time_coupling_kernels(solver::KernelKind::Peskin4, x, force, fluid, 5);
  EXPECT_EQ(omp_get_max_threads(), threads);
  EXPECT_EQ(t.nodes, 350u);
  EXPECT_EQ(t.passes, 5);
  EXPECT_GT(t.spreading_fastest, 0.0);
  EXPECT_GT(t.interpolation_fastest, 0.0);
  EXPECT_LE(t.spreading_fastest, t.spreading_median);
  EXPECT_LE(t.interpolation_fastest, t.interpolation_median);
}

TEST(CouplingKernels, RefusesNoPassesAndNoNodes) {
  solver::FluidConfig lattice;
  lattice.nx = lattice.ny = lattice.nz = 8;
  solver::FluidLattice fluid(lattice);
  const std::vector<std::vector<Vec3>> one = {{Vec3(3.5, 3.5, 3.5)}};
  EXPECT_THROW(time_coupling_kernels(solver::KernelKind::Peskin4, one, one, fluid, 0), std::invalid_argument);
  const std::vector<std::vector<Vec3>> none = {{}};
  EXPECT_THROW(time_coupling_kernels(solver::KernelKind::Peskin4, none, none, fluid, 3), std::invalid_argument);
}

}  // namespace
}  // namespace rbcal::bench
