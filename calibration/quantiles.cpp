#include "calibration/quantiles.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace rbcal::calibration {

double quantile(std::vector<double> values, double p) {
  if (values.empty()) throw std::invalid_argument("quantile of an empty set");
  p = std::clamp(p, 0.0, 1.0);
  const double h = p * static_cast<double>(values.size() - 1);
  const auto lo = static_cast<std::size_t>(std::floor(h));
  const std::size_t hi = std::min(lo + 1, values.size() - 1);
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(lo), values.end());
  const double x_lo = values[lo];
  if (hi == lo) return x_lo;
  const double x_hi = *std::min_element(values.begin() + static_cast<std::ptrdiff_t>(hi), values.end());
  return x_lo + (h - static_cast<double>(lo)) * (x_hi - x_lo);
}

Interval central_interval(const std::vector<double>& values, double level) {
  return {quantile(values, 0.5 * (1.0 - level)), quantile(values, 0.5 * (1.0 + level)), level};
}

}  // namespace rbcal::calibration
