// Checkpoint and restart: a run interrupted after N steps and restarted from its
// checkpoint ends bit-identical to an uninterrupted run, also when the inside fraction
// is rebuilt only every few steps; damaged or foreign checkpoints are refused with a
// message naming the file.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

#include "solver/coupling/immersed_boundary.hpp"
#include "solver/simulation/shear_flow_simulation.hpp"
#include "../scratch_path.hpp"

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


double largest_displacement(const std::vector<std::vector<Vec3>>& a, const std::vector<std::vector<Vec3>>& b) {
  double d = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t m = 0; m < a[i].size(); ++m) d = std::max(d, (a[i][m] - b[i][m]).norm());
  return d;
}

// Nodes of the tiny case move up to about 0.008 lattice spacings per step: a tolerance
// of 0.02 rebuilds the inside fraction every few steps, the lagging state that a
// checkpoint must carry.
constexpr double kLaggingTolerance = 0.02;

}  // namespace

class CheckpointAtIndicatorTolerance : public ::testing::TestWithParam<double> {};

// Runs c for 40 steps straight and as 20 + checkpoint + restore + 20; expects the two to
// agree bit for bit.
void expect_restart_bit_identical(const SimulationCase& c) {
  const std::string path = rbcal::testing_support::scratch_path("checkpoint.bin").string();
  ShearFlowSimulation straight(c);
  for (int s = 0; s < 40; ++s) straight.step();

  {
    ShearFlowSimulation first_half(c);
    for (int s = 0; s < 20; ++s) first_half.step();
    first_half.save_checkpoint(path);
  }
  ShearFlowSimulation resumed(c);
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
  const auto& alpha_a = straight.inside_fraction().alpha();
  const auto& alpha_b = resumed.inside_fraction().alpha();
  for (std::size_t n = 0; n < alpha_a.size(); ++n) ASSERT_EQ(alpha_a[n], alpha_b[n]) << "inside fraction at node " << n;
  std::filesystem::remove(path);
}

TEST_P(CheckpointAtIndicatorTolerance, RestartContinuesBitIdentically) {
  SimulationCase c = tiny_case();
  c.indicator_tolerance = GetParam();
  expect_restart_bit_identical(c);
}

// With numerics.coupling_interval 3 the checkpoint at step 20 falls inside an interval,
// whose force field the restore must rebuild from the saved positions and forces, and
// (under the interval mean) whose velocity summed over its first two steps it must keep.
class CheckpointInsideACouplingInterval : public ::testing::TestWithParam<NodeVelocity> {};

TEST_P(CheckpointInsideACouplingInterval, RestartContinuesBitIdentically) {
  SimulationCase c = tiny_case();
  c.coupling_interval = 3;
  c.node_velocity = GetParam();
  expect_restart_bit_identical(c);
}

std::string node_velocity_name(const ::testing::TestParamInfo<NodeVelocity>& info) {
  return info.param == NodeVelocity::IntervalMean ? "IntervalMean" : "LastStep";
}

INSTANTIATE_TEST_SUITE_P(BothNodeVelocities, CheckpointInsideACouplingInterval,
                         ::testing::Values(NodeVelocity::IntervalMean, NodeVelocity::LastStep), node_velocity_name);

// A checkpoint of the other node velocity is refused, and the message says how to resume.
TEST(CheckpointInsideACouplingInterval, RefusesTheOtherNodeVelocityNamingTheField) {
  const std::string path = rbcal::testing_support::scratch_path("node_velocity.bin").string();
  SimulationCase c = tiny_case();
  c.coupling_interval = 2;
  c.node_velocity = NodeVelocity::LastStep;
  {
    ShearFlowSimulation sim(c);
    for (int s = 0; s < 4; ++s) sim.step();
    sim.save_checkpoint(path);
  }
  c.node_velocity = NodeVelocity::IntervalMean;
  ShearFlowSimulation other(c);
  try {
    other.restore_checkpoint(path);
    ADD_FAILURE() << "restored a checkpoint of the other node velocity";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("numerics.node_velocity \"last_step\""), std::string::npos) << e.what();
  }
  std::filesystem::remove(path);
}

// numerics.node_velocity: written (and allowed) where the interval is above 1, read back,
// and a bad value is named with its file and field.
TEST(IntervalVelocity, ReadWrittenBackAndChecked) {
  SimulationCase c = tiny_case();
  c.coupling_interval = 1;
  EXPECT_FALSE(case_to_json(c)["numerics"].contains("node_velocity"));  // k = 1: no meaning
  c.coupling_interval = 2;
  c.node_velocity = NodeVelocity::LastStep;
  nlohmann::json j = case_to_json(c);
  EXPECT_EQ(j["numerics"]["node_velocity"], "last_step");
  EXPECT_EQ(case_from_json(j, "k2.json").node_velocity, NodeVelocity::LastStep);
  j["numerics"].erase("node_velocity");
  EXPECT_EQ(case_from_json(j, "k2.json").node_velocity, NodeVelocity::IntervalMean);  // the default
  j["numerics"]["node_velocity"] = "mean";
  try {
    case_from_json(j, "k2.json");
    ADD_FAILURE() << "accepted node_velocity \"mean\"";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("k2.json: field numerics.node_velocity"), std::string::npos) << e.what();
  }
}

// Under the interval mean the membrane moves by the mean of the velocities interpolated
// after each fluid step of the interval (at the positions of its start); under the last
// step's, by the velocity after the last one. Reference: the fluid's own moments.
class IntervalVelocity : public ::testing::TestWithParam<NodeVelocity> {};

TEST_P(IntervalVelocity, IsTheMeanOrTheLastOfTheStepsVelocities) {
  SimulationCase c = tiny_case();
  c.coupling_interval = 3;
  c.node_velocity = GetParam();
  ShearFlowSimulation sim(c);
  for (int s = 0; s < 6; ++s) sim.step();  // two intervals: the cell is moving
  const std::vector<Vec3> start = sim.positions()[0];
  std::vector<std::vector<Vec3>> per_step;
  for (int s = 0; s < 3; ++s) {
    sim.step();
    std::vector<Vec3> u;
    for (const Vec3& x : start) u.push_back(interpolate_velocity(c.kernel, sim.fluid(), x));
    per_step.push_back(u);
  }
  double largest_gap = 0.0, scale = 0.0;  // between the mean and the last step's velocity
  for (std::size_t n = 0; n < start.size(); ++n) {
    const Vec3 mean = (per_step[0][n] + per_step[1][n] + per_step[2][n]) / 3.0;
    const Vec3 expected = GetParam() == NodeVelocity::IntervalMean ? mean : per_step[2][n];
    EXPECT_LT((sim.velocities()[0][n] - expected).norm(), 1e-12 * (1.0 + expected.norm())) << "node " << n;
    largest_gap = std::max(largest_gap, (mean - per_step[2][n]).norm());
    scale = std::max(scale, mean.norm());
  }
  // The two schemes differ here by far more than the tolerance above.
  EXPECT_GT(largest_gap, 1e-6 * scale);
}

INSTANTIATE_TEST_SUITE_P(BothNodeVelocities, IntervalVelocity,
                         ::testing::Values(NodeVelocity::IntervalMean, NodeVelocity::LastStep), node_velocity_name);

// The membrane moves only at the end of each interval, by k times the interpolated velocity.
TEST(CouplingInterval, MovesTheMembraneEveryKStepsByKTimesItsVelocity) {
  SimulationCase c = tiny_case();
  c.coupling_interval = 3;
  ShearFlowSimulation sim(c);
  for (int s = 0; s < 3; ++s) sim.step();
  for (int interval = 0; interval < 3; ++interval) {
    const auto start = sim.positions()[0];
    sim.step();
    sim.step();
    EXPECT_EQ(sim.positions()[0], start) << "moved inside interval " << interval;
    sim.step();
    // The volume correction moves nodes along the volume gradient, whose sum over a closed
    // surface vanishes, so the mean node displacement is exactly k times the mean velocity.
    Vec3 moved = Vec3::Zero(), velocity = Vec3::Zero();
    double scale = 0.0;  // of the single displacements, for the round-off of the sums
    for (std::size_t n = 0; n < start.size(); ++n) {
      moved += sim.positions()[0][n] - start[n];
      velocity += sim.velocities()[0][n];
      scale += 3.0 * sim.velocities()[0][n].norm();
    }
    EXPECT_GT(scale, 1e-3);
    EXPECT_NEAR((moved - 3.0 * velocity).norm(), 0.0, 1e-10 * scale) << "interval " << interval;
  }
}

INSTANTIATE_TEST_SUITE_P(EveryStepAndLagging, CheckpointAtIndicatorTolerance,
                         ::testing::Values(0.0, kLaggingTolerance));

// The inside fraction is rebuilt exactly when a node has moved more than the tolerance
// since the last build, from the positions at the start of that step: for a cell at the
// centre, which turns in place, and one half a radius above it, which the shear carries
// along. (Most steps settle the question by a bound on the drift; the answer must not
// change: a bound scaled by 0.7 fails this test.)
class IndicatorTolerance : public ::testing::TestWithParam<double> {};

TEST_P(IndicatorTolerance, RebuildsOnceANodeHasMovedFartherThanTheTolerance) {
  SimulationCase c = tiny_case();
  c.indicator_tolerance = kLaggingTolerance;
  c.cells[0].center[1] = GetParam();
  ShearFlowSimulation sim(c);
  int rebuilds = 0;
  const int steps = 60;
  for (int s = 0; s < steps; ++s) {
    const auto before = sim.positions();
    const auto built_from = sim.indicator_positions();
    const std::int64_t builds = sim.timings().indicator_builds;
    sim.step();
    const double moved = largest_displacement(before, built_from);
    if (sim.timings().indicator_builds > builds) {
      ++rebuilds;
      EXPECT_GT(moved, kLaggingTolerance) << "step " << s;
      EXPECT_EQ(largest_displacement(sim.indicator_positions(), before), 0.0) << "step " << s;
    } else {
      EXPECT_LE(moved, kLaggingTolerance) << "step " << s;
    }
  }
  EXPECT_GT(rebuilds, 3);
  EXPECT_LT(rebuilds, steps / 2);
}

INSTANTIATE_TEST_SUITE_P(CentredAndCarried, IndicatorTolerance, ::testing::Values(0.0, 0.5));

// (At every membrane step: every step at coupling interval 1, every k-th at k.)
TEST(IndicatorToleranceZero, RebuildsEveryMembraneStep) {
  for (const int interval : {1, 2}) {
    SimulationCase c = tiny_case();
    c.indicator_tolerance = 0.0;
    c.coupling_interval = interval;
    ShearFlowSimulation sim(c);
    const std::int64_t at_start = sim.timings().indicator_builds;
    for (int s = 0; s < 10; ++s) sim.step();
    EXPECT_EQ(sim.timings().indicator_builds - at_start, 10 / interval) << "interval " << interval;
  }
}

TEST(Checkpoint, RefusesDamagedOrForeignFiles) {
  const std::string path = rbcal::testing_support::scratch_path("checkpoint.bin").string();
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

// When the node-speed guard trips, the run keeps the state it tripped on
// (checkpoint_failed.bin): the nodes where they stood before the runaway velocities.
TEST(NodeSpeedGuard, LeavesTheNodesWhereTheyStoodWhenItTrips) {
  SimulationCase c = tiny_case();
  c.flow.capillary_number = 1e-4;  // far too stiff for the explicit coupling: blows up in steps
  c.flow.viscosity_ratio = 1.0;
  ShearFlowSimulation sim(c);
  bool tripped = false;
  for (int s = 0; s < 200 && !tripped; ++s) {
    const std::vector<std::vector<Vec3>> before = sim.positions();
    try {
      sim.step();
    } catch (const std::runtime_error& e) {
      tripped = true;
      EXPECT_NE(std::string(e.what()).find("Mach"), std::string::npos) << e.what();
      EXPECT_EQ(sim.positions(), before);
    }
  }
  EXPECT_TRUE(tripped);
}
