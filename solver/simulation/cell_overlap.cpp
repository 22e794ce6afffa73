#include "solver/simulation/cell_overlap.hpp"

#include <algorithm>
#include <cmath>

namespace rbcal::solver {

namespace {

struct NodesInside {
  long count = 0;
  double max_depth = 0.0;  // largest distance from such a node to the other cell's nearest node
};

// The nodes of cell i (its image nearest to cell j across the periodic x and z) inside cell j.
NodesInside nodes_of_inside(std::size_t i, std::size_t j, const std::vector<std::vector<Vec3>>& x,
                            const std::vector<Bounds>& bounds, const std::vector<Triangle>& triangles, double period_x,
                            double period_z) {
  NodesInside out;
  const Vec3 gap = 0.5 * (bounds[i].lo + bounds[i].hi - bounds[j].lo - bounds[j].hi);
  const Vec3 shift(-period_x * std::round(gap.x() / period_x), 0.0, -period_z * std::round(gap.z() / period_z));
  const Vec3 lo = bounds[i].lo + shift, hi = bounds[i].hi + shift;
  if ((lo.array() > bounds[j].hi.array()).any() || (hi.array() < bounds[j].lo.array()).any()) return out;
  for (const Vec3& p : x[i]) {
    const Vec3 q = p + shift;
    if (!bounds[j].contains(q)) continue;
    if (winding_number(q, x[j], triangles) <= 0.5) continue;
    ++out.count;
    double nearest = 1e300;
    for (const Vec3& r : x[j]) nearest = std::min(nearest, (q - r).squaredNorm());
    out.max_depth = std::max(out.max_depth, std::sqrt(nearest));
  }
  return out;
}

std::vector<Bounds> bounds_of(const std::vector<std::vector<Vec3>>& x) {
  std::vector<Bounds> bounds;
  for (const auto& cell : x) bounds.push_back(bounding_box(cell));
  return bounds;
}

}  // namespace

OverlapCount count_overlaps(const std::vector<std::vector<Vec3>>& x, const std::vector<Triangle>& triangles,
                            double period_x, double period_z) {
  const std::size_t cells = x.size();
  const std::vector<Bounds> bounds = bounds_of(x);
  long nodes_inside = 0;
  int cell_pairs = 0;
  double max_depth = 0.0;
#pragma omp parallel for schedule(dynamic) reduction(+ : nodes_inside, cell_pairs) reduction(max : max_depth)
  for (std::size_t i = 0; i < cells; ++i) {
    for (std::size_t j = 0; j < cells; ++j) {
      if (i == j) continue;
      const NodesInside n = nodes_of_inside(i, j, x, bounds, triangles, period_x, period_z);
      nodes_inside += n.count;
      if (n.count > 0) ++cell_pairs;
      max_depth = std::max(max_depth, n.max_depth);
    }
  }
  return {nodes_inside, cell_pairs, max_depth};
}

std::optional<std::array<std::size_t, 2>> first_overlapping_pair(const std::vector<std::vector<Vec3>>& x,
                                                                 const std::vector<Triangle>& triangles,
                                                                 double period_x, double period_z) {
  const std::vector<Bounds> bounds = bounds_of(x);
  for (std::size_t i = 0; i < x.size(); ++i)
    for (std::size_t j = i + 1; j < x.size(); ++j)
      if (nodes_of_inside(i, j, x, bounds, triangles, period_x, period_z).count > 0 ||
          nodes_of_inside(j, i, x, bounds, triangles, period_x, period_z).count > 0)
        return std::array<std::size_t, 2>{i, j};
  return std::nullopt;
}

double overlap_volume_fraction(const std::vector<std::vector<Vec3>>& x, const std::vector<Triangle>& triangles,
                               double period_x, double height, double period_z, double spacing) {
  std::vector<Bounds> bounds;
  double cells_volume = 0.0;
  for (const auto& cell : x) {
    bounds.push_back(bounding_box(cell));
    cells_volume += enclosed_volume(cell, triangles);
  }
  const int nx = static_cast<int>(std::ceil(period_x / spacing));
  const int ny = static_cast<int>(std::ceil(height / spacing));
  const int nz = static_cast<int>(std::ceil(period_z / spacing));
  long extra = 0;  // grid points inside a second, third ... cell
#pragma omp parallel for schedule(dynamic) reduction(+ : extra)
  for (int i = 0; i < nx; ++i)
    for (int j = 0; j < ny; ++j)
      for (int k = 0; k < nz; ++k) {
        const Vec3 p((i + 0.5) * spacing, (j + 0.5) * spacing, (k + 0.5) * spacing);
        int inside = 0;
        for (std::size_t c = 0; c < x.size(); ++c) {
          // The image of the point nearest to the cell across the periodic x and z.
          const Vec3 d = p - 0.5 * (bounds[c].lo + bounds[c].hi);
          const Vec3 q = p - Vec3(period_x * std::round(d.x() / period_x), 0.0, period_z * std::round(d.z() / period_z));
          if (!bounds[c].contains(q)) continue;
          if (winding_number(q, x[c], triangles) > 0.5) ++inside;
        }
        if (inside > 1) extra += inside - 1;
      }
  return cells_volume > 0.0 ? extra * spacing * spacing * spacing / cells_volume : 0.0;
}

}  // namespace rbcal::solver
