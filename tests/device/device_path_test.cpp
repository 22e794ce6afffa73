// The device path (solver/device/) against the CPU solver. Built as usual it runs on the
// host's threads (what CI tests); in a build with -DRBCAL_CUDA=ON the same assertions run
// on the GPU. The two paths add the same terms in different orders (atomics), so they agree
// to round-off, not bit for bit; the tolerances below are round-off grown over the steps run.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <vector>

#include "../scratch_path.hpp"
#include "../simulation/small_sheared_case.hpp"
#include "solver/fluid/d3q19.hpp"
#include "solver/simulation/shear_flow_simulation.hpp"

namespace rbcal::solver {
namespace {

double max_difference(const std::vector<std::vector<Vec3>>& a, const std::vector<std::vector<Vec3>>& b) {
  EXPECT_EQ(a.size(), b.size());
  double d = 0.0;
  for (std::size_t c = 0; c < std::min(a.size(), b.size()); ++c)
    for (std::size_t m = 0; m < a[c].size(); ++m) d = std::max(d, (a[c][m] - b[c][m]).cwiseAbs().maxCoeff());
  return d;
}

// Share of the populations that differ by more than round-off of double arithmetic.
double share_of_populations_differing(const FluidLattice& a, const FluidLattice& b) {
  const std::vector<double> pa = a.populations(), pb = b.populations();
  std::size_t differing = 0;
  for (std::size_t i = 0; i < pa.size(); ++i) differing += std::abs(pa[i] - pb[i]) > 1e-14;
  return static_cast<double>(differing) / static_cast<double>(pa.size());
}

double max_population_difference(const FluidLattice& a, const FluidLattice& b) {
  const std::vector<double> pa = a.populations(), pb = b.populations();
  double d = 0.0;
  for (std::size_t i = 0; i < pa.size(); ++i) d = std::max(d, std::abs(pa[i] - pb[i]));
  return d;
}

struct Comparison {
  double positions, velocities, populations, eta_stresslet, eta_wall;
};

Comparison run_both(const SimulationCase& c, int steps) {
  ShearFlowSimulation cpu(c), device(c, Backend::Device);
  for (int s = 0; s < steps; ++s) {
    cpu.step();
    device.step();
  }
  EXPECT_EQ(cpu.steps_done(), device.steps_done());
  const Observables a = cpu.observe(), b = device.observe();
  return {max_difference(cpu.positions(), device.positions()), max_difference(cpu.velocities(), device.velocities()),
          max_population_difference(cpu.fluid(), device.fluid()), std::abs(a.eta_re_stresslet - b.eta_re_stresslet),
          std::abs(a.eta_re_wall - b.eta_re_wall)};
}

// Plane Couette flow is an exact steady solution of the lattice Boltzmann scheme with
// half-way bounce-back walls: after the start-up transient every node carries the linear
// profile u_z = U (2 (y + 1/2) / ny - 1) to round-off. The fluid update alone, on the
// device, and the same number of steps on the CPU give the same populations.
TEST(DevicePath, CouetteFlowIsExactAndMatchesTheCpu) {
  SimulationCase c = test_cases::small_sheared_case(MembraneLaw::NeoHookean);
  c.flow.viscosity_ratio = 1.0;  // a uniform viscosity: the cell plays no part in fluid-only steps
  ShearFlowSimulation device(c, Backend::Device);
  const int steps = 1500;
  device.device_fluid_steps(steps);
  const FluidLattice& f = device.fluid();
  const double u_wall = device.units().wall_speed;
  const int ny = f.ny();
  double worst = 0.0;
  for (int x = 0; x < f.nx(); ++x)
    for (int y = 0; y < ny; ++y)
      for (int z = 0; z < f.nz(); ++z) {
        const NodeMoments m = f.moments(f.index(x, y, z));
        const double exact = u_wall * (2.0 * (y + 0.5) / ny - 1.0);
        worst = std::max({worst, std::abs(m.uz - exact), std::abs(m.ux), std::abs(m.uy)});
      }
  EXPECT_LT(worst / u_wall, 1e-11) << "largest deviation from the linear profile, relative to the wall speed";

  // The CPU's lattice from the same start, the same steps.
  ShearFlowSimulation start(c);
  FluidLattice cpu(start.fluid().config());
  cpu.restore(start.fluid().populations(), 0);
  for (int s = 0; s < steps; ++s) cpu.step();
  EXPECT_LT(max_population_difference(cpu, f), 1e-13);
}

// A capsule with a viscosity contrast (the inside fraction rebuilt on the device), bending
// and the volume penalty, two fluid steps per membrane step: every part of the coupled step.
TEST(DevicePath, CapsuleWithContrastMatchesTheCpu) {
  SimulationCase c = test_cases::small_sheared_case(MembraneLaw::Skalak);
  c.volume_stiffness = 10.0;
  c.indicator_tolerance = 0.0;  // rebuilt at every membrane step
  const Comparison d = run_both(c, 200);
  EXPECT_LT(d.positions, 1e-10);
  EXPECT_LT(d.velocities, 1e-12);
  EXPECT_LT(d.populations, 1e-12);
  EXPECT_LT(d.eta_stresslet, 1e-9);
  EXPECT_LT(d.eta_wall, 1e-10);
}

// The RK4 node update and the last step's velocity (not the interval mean).
TEST(DevicePath, Rk4AndLastStepVelocityMatchTheCpu) {
  SimulationCase c = test_cases::small_sheared_case(MembraneLaw::NeoHookean);
  c.integrator = Integrator::RK4;
  c.node_velocity = NodeVelocity::LastStep;
  c.coupling_interval = 3;
  const Comparison d = run_both(c, 90);
  EXPECT_LT(d.positions, 1e-10);
  EXPECT_LT(d.populations, 1e-12);
}

// 99 red cells at phi 0.41, lambda 5 (the CPU bench case): cells that touch each other's
// stencils, the periodic seams and the walls.
TEST(DevicePath, DenseSuspensionMatchesTheCpu) {
  // RBCAL_CASES_DIR in the environment: a test binary carried to another machine.
  const char* moved = std::getenv("RBCAL_CASES_DIR");
  SimulationCase c = read_case(std::string(moved ? moved : RBCAL_CASES_DIR) + "/bench_dense_n8.json");
  const Comparison d = run_both(c, 40);
  EXPECT_LT(d.positions, 1e-9);
  EXPECT_LT(d.populations, 1e-11);
  EXPECT_LT(d.eta_stresslet, 1e-8);
  EXPECT_LT(d.eta_wall, 1e-9);
}

// A checkpoint written from the device and read back into the device path continues the
// run: the state comes back from the device whole.
TEST(DevicePath, CheckpointContinuesTheRun) {
  const SimulationCase c = test_cases::small_sheared_case(MembraneLaw::Skalak);
  ShearFlowSimulation straight(c, Backend::Device), first(c, Backend::Device), second(c, Backend::Device);
  const std::string path = testing_support::scratch_path("device_checkpoint.bin").string();
  for (int s = 0; s < 61; ++s) straight.step();  // stops inside a coupling interval
  for (int s = 0; s < 31; ++s) first.step();
  first.save_checkpoint(path);
  second.restore_checkpoint(path);
  EXPECT_EQ(second.steps_done(), 31);
  for (int s = 0; s < 30; ++s) second.step();
  EXPECT_LT(max_difference(straight.positions(), second.positions()), 1e-10);
  EXPECT_LT(max_population_difference(straight.fluid(), second.fluid()), 1e-12);
  std::filesystem::remove(path);
}

// Float population storage (numerics.precision "float") on the device path: the same shifted
// storage as the CPU lattice, the same arithmetic, so the two agree to float's resolution of
// the populations (6e-8 of their deviations from rest), not to double round-off.
TEST(DevicePath, FloatStorageMatchesTheCpu) {
  SimulationCase c = test_cases::small_sheared_case(MembraneLaw::Skalak);
  c.single_precision = true;
  const Comparison d = run_both(c, 200);
  std::cout << "float storage, device against CPU: positions " << d.positions << ", populations " << d.populations
            << ", eta_re " << d.eta_stresslet << "\n";
  EXPECT_LT(d.positions, 1e-7);
  EXPECT_LT(d.populations, 1e-8);
  EXPECT_LT(d.eta_stresslet, 1e-6);
  // And the device really stores floats: after the same steps most of its populations equal
  // the CPU float storage's exactly (where no atomic's round-off flipped a float's last bit),
  // while against double storage nearly all differ.
  SimulationCase twice = c;
  twice.single_precision = false;
  ShearFlowSimulation device(c, Backend::Device), cpu_float(c), cpu_double(twice);
  for (int s = 0; s < 200; ++s) {
    device.step();
    cpu_float.step();
    cpu_double.step();
  }
  const double same = share_of_populations_differing(device.fluid(), cpu_float.fluid());
  const double other = share_of_populations_differing(device.fluid(), cpu_double.fluid());
  std::cout << "share of populations differing: from CPU float " << same << ", from CPU double " << other << "\n";
  EXPECT_LT(same, 0.9 * other) << "the device does not store as the CPU's float storage does";
}

}  // namespace
}  // namespace rbcal::solver
