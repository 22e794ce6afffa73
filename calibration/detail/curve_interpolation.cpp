#include "calibration/detail/curve_interpolation.hpp"

#include <algorithm>
#include <cmath>

namespace rbcal::calibration {

SortedCurve::SortedCurve(std::vector<RelativeViscosityPoint> curve) : curve_(std::move(curve)) {
  std::sort(curve_.begin(), curve_.end(), [](const auto& a, const auto& b) { return a.shear_rate < b.shear_rate; });
}

std::optional<double> SortedCurve::at(double shear_rate) const {
  if (curve_.empty() || !(shear_rate >= curve_.front().shear_rate && shear_rate <= curve_.back().shear_rate))
    return std::nullopt;
  if (curve_.size() == 1) return curve_.front().eta_re;  // a single-point curve at exactly this rate
  // The first point at or above the rate closes the interval; at the lowest rate, the first one.
  const auto above = std::lower_bound(curve_.begin(), curve_.end(), shear_rate,
                                      [](const RelativeViscosityPoint& p, double rate) { return p.shear_rate < rate; });
  const std::size_t b_index = std::max<std::size_t>(1, static_cast<std::size_t>(above - curve_.begin()));
  const RelativeViscosityPoint& a = curve_[b_index - 1];
  const RelativeViscosityPoint& b = curve_[b_index];
  if (!(b.shear_rate > a.shear_rate)) return a.eta_re;  // a repeated lowest rate: no interval to interpolate in
  const double t = std::log(shear_rate / a.shear_rate) / std::log(b.shear_rate / a.shear_rate);
  return std::exp((1.0 - t) * std::log(a.eta_re) + t * std::log(b.eta_re));
}

std::optional<double> curve_at(std::vector<RelativeViscosityPoint> curve, double shear_rate) {
  return SortedCurve(std::move(curve)).at(shear_rate);
}

}  // namespace rbcal::calibration
