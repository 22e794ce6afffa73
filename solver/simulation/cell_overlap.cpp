#include "solver/simulation/cell_overlap.hpp"

#include <cmath>

namespace rbcal::solver {

OverlapCount count_overlaps(const std::vector<std::vector<Vec3>>& x, const std::vector<Triangle>& triangles,
                            double period_x, double period_z) {
  const std::size_t cells = x.size();
  std::vector<Bounds> bounds;
  for (const auto& cell : x) bounds.push_back(bounding_box(cell));
  long nodes_inside = 0;
  int cell_pairs = 0;
#pragma omp parallel for schedule(dynamic) reduction(+ : nodes_inside, cell_pairs)
  for (std::size_t i = 0; i < cells; ++i) {
    for (std::size_t j = 0; j < cells; ++j) {
      if (i == j) continue;
      // The image of cell i nearest to cell j across the periodic x and z.
      const Vec3 gap = 0.5 * (bounds[i].lo + bounds[i].hi - bounds[j].lo - bounds[j].hi);
      const Vec3 shift(-period_x * std::round(gap.x() / period_x), 0.0, -period_z * std::round(gap.z() / period_z));
      const Vec3 lo = bounds[i].lo + shift, hi = bounds[i].hi + shift;
      if ((lo.array() > bounds[j].hi.array()).any() || (hi.array() < bounds[j].lo.array()).any()) continue;
      long inside = 0;
      for (const Vec3& p : x[i]) {
        const Vec3 q = p + shift;
        if ((q.array() < bounds[j].lo.array()).any() || (q.array() > bounds[j].hi.array()).any()) continue;
        if (winding_number(q, x[j], triangles) > 0.5) ++inside;
      }
      nodes_inside += inside;
      if (inside > 0) ++cell_pairs;
    }
  }
  return {nodes_inside, cell_pairs};
}

}  // namespace rbcal::solver
