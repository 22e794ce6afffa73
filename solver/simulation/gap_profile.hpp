#pragma once
// Where the cells sit across the gap of a wall-bounded shear flow: a histogram of the cell
// centres' wall-normal coordinate. Dense suspensions in a gap of a few cell diameters can
// order in layers that slide past each other (docs/library.md), which lowers eta_re; the
// histogram shows such layers as peaks, and `layering` condenses them into one number.
#include <vector>

#include "solver/membrane/triangle_mesh.hpp"

namespace rbcal::solver {

struct GapProfile {
  double bin_width = 0.0;   // lattice spacings; bin 0 starts at the lower wall, y = -1/2
  std::vector<int> counts;  // cell centres per bin
  // sd of the counts over their mean, over the bins whose centres lie at least
  // `wall_margin` from both walls (a cell centre cannot come closer than its half-thickness):
  // about 1 / sqrt(mean) for centres spread at random, much larger for layers.
  double layering = 0.0;
};

// positions: node positions per cell (lattice units); walls at y = -1/2 and ny - 1/2.
// Throws std::invalid_argument for a non-positive bin width or ny.
GapProfile cell_centres_across_gap(const std::vector<std::vector<Vec3>>& positions, int ny, double bin_width,
                                   double wall_margin);

}  // namespace rbcal::solver
