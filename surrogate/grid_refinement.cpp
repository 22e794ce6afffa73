#include "surrogate/grid_refinement.hpp"

#include <algorithm>
#include <cmath>

namespace rbcal::surrogate {

namespace {

std::vector<double> sorted_unique(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
  return v;
}

std::vector<double> with_midpoints(const std::vector<double>& axis_values, bool geometric) {
  const std::vector<double> v = sorted_unique(axis_values);
  std::vector<double> out;
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (i > 0) out.push_back(geometric ? std::sqrt(v[i - 1] * v[i]) : 0.5 * (v[i - 1] + v[i]));
    out.push_back(v[i]);
  }
  return out;
}

}  // namespace

ParameterGrid refined(const ParameterGrid& grid) {
  // The refinement is a grid over the axes (of a listed design too: its distinct values).
  return {with_midpoints(grid.phi, false), with_midpoints(grid.capillary_number, true),
          with_midpoints(grid.viscosity_ratio, true), {}};
}

}  // namespace rbcal::surrogate
