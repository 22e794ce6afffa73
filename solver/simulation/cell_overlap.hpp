#pragma once
// Membranes that lie inside other cells at the end of a dense run: how many nodes, how
// deep, and how much volume two cells claim at once. The immersed boundary has no contact
// force and does not resolve gaps below its kernel width, so touching membranes overlap by
// a fraction of a lattice spacing (docs/library.md: contact models tried and dropped).
#include <array>
#include <optional>
#include <vector>

#include "solver/membrane/triangle_mesh.hpp"

namespace rbcal::solver {

struct OverlapCount {
  long nodes_inside = 0;  // nodes of any cell inside another (winding number > 1/2)
  int cell_pairs = 0;     // ordered pairs (i, j) with a node of cell i inside cell j
  // Largest distance from a node inside another cell to that cell's nearest node, in
  // lattice spacings: an upper bound on how deep any membrane reaches into another cell.
  double max_depth = 0.0;
};

// x: node positions per cell, in lattice units; the box is periodic in x and z with
// lengths period_x and period_z (positions may lie outside [0, period)).
OverlapCount count_overlaps(const std::vector<std::vector<Vec3>>& x, const std::vector<Triangle>& triangles,
                            double period_x, double period_z);

// The first pair of cells (i < j) of which one has a node inside the other, or none; the
// same periodic images as count_overlaps.
std::optional<std::array<std::size_t, 2>> first_overlapping_pair(const std::vector<std::vector<Vec3>>& x,
                                                                 const std::vector<Triangle>& triangles,
                                                                 double period_x, double period_z);

// The volume inside two or more cells (counted once per extra cell), as a fraction of the
// cells' summed volume: winding numbers at the centres of a grid of the given spacing over
// the box [0, period_x) x [0, height) x [0, period_z) (lattice units). With spacing 1 about
// 10 s for 102 cells of 642 nodes on one core; the sampling error is about one over the
// square root of the number of grid points counted twice.
// The grid spacing both result.json and `rbcal overlaps` use: a / 6 in lattice units (one
// lattice spacing at N_a 6), so that the cost follows the box in cell radii, not N_a.
inline double overlap_grid_spacing(int nodes_per_radius) { return nodes_per_radius / 6.0; }

double overlap_volume_fraction(const std::vector<std::vector<Vec3>>& x, const std::vector<Triangle>& triangles,
                               double period_x, double height, double period_z, double spacing);

}  // namespace rbcal::solver
