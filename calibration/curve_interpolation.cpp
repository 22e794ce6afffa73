#include "calibration/curve_interpolation.hpp"

#include <algorithm>
#include <cmath>

namespace rbcal::calibration {

std::optional<double> curve_at(std::vector<RelativeViscosityPoint> curve, double shear_rate) {
  std::sort(curve.begin(), curve.end(), [](const auto& a, const auto& b) { return a.shear_rate < b.shear_rate; });
  if (curve.empty() || shear_rate < curve.front().shear_rate || shear_rate > curve.back().shear_rate)
    return std::nullopt;
  for (std::size_t i = 0; i + 1 < curve.size(); ++i) {
    const auto& a = curve[i];
    const auto& b = curve[i + 1];
    if (shear_rate > b.shear_rate) continue;
    if (!(b.shear_rate > a.shear_rate)) {  // a repeated rate: no interval to interpolate in
      if (shear_rate == a.shear_rate) return a.eta_re;
      continue;
    }
    const double t = std::log(shear_rate / a.shear_rate) / std::log(b.shear_rate / a.shear_rate);
    return std::exp((1.0 - t) * std::log(a.eta_re) + t * std::log(b.eta_re));
  }
  return curve.back().eta_re;  // a single-point curve at exactly this rate
}

}  // namespace rbcal::calibration
