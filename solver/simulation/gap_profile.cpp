#include "solver/simulation/gap_profile.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace rbcal::solver {

GapProfile cell_centres_across_gap(const std::vector<std::vector<Vec3>>& positions, int ny, double bin_width,
                                   double wall_margin) {
  if (!(bin_width > 0.0) || ny <= 0) throw std::invalid_argument("gap profile: bin width and ny must be positive");
  GapProfile p;
  p.bin_width = bin_width;
  const double gap = static_cast<double>(ny);
  const int bins = std::max(1, static_cast<int>(std::ceil(gap / bin_width - 1e-9)));
  p.counts.assign(bins, 0);
  for (const auto& cell : positions) {
    if (cell.empty()) continue;
    const double y = vertex_centroid(cell).y() + 0.5;  // from the lower wall
    const int bin = std::clamp(static_cast<int>(std::floor(y / bin_width)), 0, bins - 1);
    ++p.counts[bin];
  }
  std::vector<int> inner;
  for (int b = 0; b < bins; ++b) {
    const double centre = (b + 0.5) * bin_width;
    if (centre >= wall_margin && gap - centre >= wall_margin) inner.push_back(p.counts[b]);
  }
  if (inner.size() >= 2) {
    double mean = 0.0;
    for (int c : inner) mean += c;
    mean /= static_cast<double>(inner.size());
    double var = 0.0;
    for (int c : inner) var += (c - mean) * (c - mean);
    var /= static_cast<double>(inner.size() - 1);
    p.layering = mean > 0.0 ? std::sqrt(var) / mean : 0.0;
  }
  return p;
}

}  // namespace rbcal::solver
