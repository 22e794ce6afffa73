// A capsule in a fluid at rest stays at rest: no spurious currents from the coupling, the
// viscosity contrast or the volume penalty.
#include <gtest/gtest.h>

#include "solver/simulation/shear_flow_simulation.hpp"

using namespace rbcal::solver;

TEST(CapsuleAtRest, StaysAtRest) {
  for (double lambda : {1.0, 5.0}) {
    SimulationCase c;
    c.shape = CellShape::Biconcave;
    c.triangles = 320;
    c.flow.viscosity_ratio = lambda;
    c.flow.capillary_number = 0.1;
    c.quiescent = true;
    c.resolution.nodes_per_radius = 5;
    c.resolution.box_in_radii = {3.2, 3.2, 3.2};
    c.cells.push_back({});
    ShearFlowSimulation sim(c);
    const std::vector<Vec3> start = sim.positions()[0];
    for (int s = 0; s < 200; ++s) sim.step();
    double moved = 0.0, speed = 0.0;
    for (std::size_t i = 0; i < start.size(); ++i) {
      moved = std::max(moved, (sim.positions()[0][i] - start[i]).norm());
      speed = std::max(speed, sim.velocities()[0][i].norm());
    }
    EXPECT_LT(moved, 1e-6) << "lambda " << lambda;
    EXPECT_LT(speed, 1e-8) << "lambda " << lambda;
  }
}
