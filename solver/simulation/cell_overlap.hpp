#pragma once
// Membrane nodes that lie inside another cell: the check that a dense suspension, seeded
// shrunken and grown in the flow, ends with no interpenetrating membranes. The immersed
// boundary has no contact force; only the flow keeps membranes apart.
#include <vector>

#include "solver/membrane/triangle_mesh.hpp"

namespace rbcal::solver {

struct OverlapCount {
  long nodes_inside = 0;  // nodes of any cell inside another (winding number > 1/2)
  int cell_pairs = 0;     // ordered pairs (i, j) with a node of cell i inside cell j
};

// x: node positions per cell, in lattice units; the box is periodic in x and z with
// lengths period_x and period_z (positions may lie outside [0, period)).
OverlapCount count_overlaps(const std::vector<std::vector<Vec3>>& x, const std::vector<Triangle>& triangles,
                            double period_x, double period_z);

}  // namespace rbcal::solver
