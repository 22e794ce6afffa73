// Checkpoint and restart: a run interrupted after N steps and restarted from its
// checkpoint ends bit-identical to an uninterrupted run; damaged or foreign checkpoints
// are refused with a message naming the file.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "solver/simulation/shear_flow_simulation.hpp"

using namespace rbcal::solver;

namespace {

SimulationCase tiny_case() {
  SimulationCase c;
  c.shape = CellShape::Biconcave;
  c.triangles = 320;
  c.flow.capillary_number = 0.2;
  c.flow.viscosity_ratio = 5.0;  // exercises the inside fraction and viscosity field
  c.resolution.nodes_per_radius = 4;
  c.resolution.box_in_radii = {4.0, 4.0, 5.0};
  c.cells.push_back({{0.0, 0.0, 0.0}, {1.0, 0.0, 0.0, 30.0}});
  return c;
}

}  // namespace

TEST(Checkpoint, RestartContinuesBitIdentically) {
  const std::string path = "checkpoint_test.bin";
  ShearFlowSimulation straight(tiny_case());
  for (int s = 0; s < 40; ++s) straight.step();

  {
    ShearFlowSimulation first_half(tiny_case());
    for (int s = 0; s < 20; ++s) first_half.step();
    first_half.save_checkpoint(path);
  }
  ShearFlowSimulation resumed(tiny_case());
  resumed.restore_checkpoint(path);
  EXPECT_EQ(resumed.steps_done(), 20);
  for (int s = 0; s < 20; ++s) resumed.step();

  ASSERT_EQ(resumed.steps_done(), straight.steps_done());
  const auto& fa = straight.fluid().populations();
  const auto& fb = resumed.fluid().populations();
  ASSERT_EQ(fa.size(), fb.size());
  for (std::size_t i = 0; i < fa.size(); ++i) ASSERT_EQ(fa[i], fb[i]) << "population " << i;
  for (std::size_t n = 0; n < straight.positions()[0].size(); ++n) {
    ASSERT_EQ(straight.positions()[0][n], resumed.positions()[0][n]) << "node " << n;
    ASSERT_EQ(straight.velocities()[0][n], resumed.velocities()[0][n]) << "node " << n;
  }
  EXPECT_EQ(straight.observe().eta_re_stresslet, resumed.observe().eta_re_stresslet);
  std::filesystem::remove(path);
}

TEST(Checkpoint, RefusesDamagedOrForeignFiles) {
  const std::string path = "checkpoint_damaged.bin";
  ShearFlowSimulation sim(tiny_case());
  sim.step();
  sim.save_checkpoint(path);
  // Another case (different Ca) must not accept it.
  SimulationCase other = tiny_case();
  other.flow.capillary_number = 0.3;
  ShearFlowSimulation foreign(other);
  EXPECT_THROW(foreign.restore_checkpoint(path), std::runtime_error);
  // A truncated file is refused, and the message names it.
  const auto size = std::filesystem::file_size(path);
  std::filesystem::resize_file(path, size / 2);
  try {
    sim.restore_checkpoint(path);
    FAIL() << "truncated checkpoint accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos);
  }
  std::filesystem::remove(path);
}
