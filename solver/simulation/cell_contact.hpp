#pragma once
// A short-range repulsion between the membranes of different cells. The immersed boundary
// does not resolve a gap narrower than its kernel, so nothing resists two membranes that
// come closer than a lattice spacing or two, and in dense suspensions they creep into each
// other (docs/library.md). Nodes of different cells closer than `range` push each other
// apart with |F| = strength (range / r - 1) (r floored at range / 5); the pair forces are
// added to the membrane forces, so they are spread into the fluid and enter the stresslet
// like any other membrane force (equal and opposite: no net force on the fluid).
#include <vector>

#include "solver/membrane/triangle_mesh.hpp"

namespace rbcal::solver {

struct ContactCount {
  long node_pairs = 0;  // ordered pairs (node, node of another cell) within range
};

// x: node positions per cell in lattice units, periodic in x and z with periods period_x,
// period_z (positions may lie outside [0, period)); range in lattice spacings; strength in
// lattice force units. Adds each node's contact force to f (same layout as x).
ContactCount add_contact_forces(const std::vector<std::vector<Vec3>>& x, double range, double strength,
                                double period_x, double period_z, std::vector<std::vector<Vec3>>& f);

}  // namespace rbcal::solver
