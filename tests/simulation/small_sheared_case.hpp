#pragma once
// One spherical capsule (320 triangles) in a 4a box at N_a 4, sheared to strain 0.2 with
// checkpoints every 0.05: the smallest case that exercises stop and resume.
#include "solver/simulation/simulation_case.hpp"

namespace rbcal::solver::test_cases {

inline SimulationCase small_sheared_case(MembraneLaw law) {
  SimulationCase c;
  c.shape = CellShape::Sphere;
  c.triangles = 320;
  c.law = law;
  c.flow.capillary_number = 0.1;
  c.flow.viscosity_ratio = 3.0;
  c.resolution.nodes_per_radius = 4;
  c.resolution.box_in_radii = {4.0, 4.0, 4.0};
  c.cells.push_back({});
  c.strain_end = 0.2;
  c.window = {0.05, 0.2};
  c.record_interval = 0.01;
  c.checkpoint_interval = 0.05;
  return c;
}

}  // namespace rbcal::solver::test_cases
