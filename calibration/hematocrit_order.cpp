#include "calibration/hematocrit_order.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <optional>

namespace rbcal::calibration {

namespace {

// ln eta_re against ln shear rate, linearly between the measured rates.
std::optional<double> curve_at(std::vector<RelativeViscosityPoint> curve, double shear_rate) {
  std::sort(curve.begin(), curve.end(), [](const auto& a, const auto& b) { return a.shear_rate < b.shear_rate; });
  if (curve.empty() || shear_rate < curve.front().shear_rate || shear_rate > curve.back().shear_rate)
    return std::nullopt;
  for (std::size_t i = 0; i + 1 < curve.size(); ++i) {
    const auto& a = curve[i];
    const auto& b = curve[i + 1];
    if (shear_rate > b.shear_rate) continue;
    const double t = std::log(shear_rate / a.shear_rate) / std::log(b.shear_rate / a.shear_rate);
    return std::exp((1.0 - t) * std::log(a.eta_re) + t * std::log(b.eta_re));
  }
  return curve.back().eta_re;  // a single-point curve at exactly this rate
}

}  // namespace

std::string OutOfOrderPoint::reason() const {
  char buffer[256];
  std::snprintf(buffer, sizeof buffer, "line %d: eta_re %.4g at phi %.4g, %.4g 1/s is not above %.4g at phi %.4g",
                point.line, point.eta_re, point.phi, point.shear_rate, lower_eta_re, lower_phi);
  return buffer;
}

std::vector<OutOfOrderPoint> points_out_of_hematocrit_order(const std::vector<RelativeViscosityPoint>& points) {
  std::map<double, std::vector<RelativeViscosityPoint>> by_phi;
  for (const auto& p : points) by_phi[p.phi].push_back(p);
  std::vector<OutOfOrderPoint> out;
  for (auto it = by_phi.begin(); it != by_phi.end(); ++it) {
    if (it == by_phi.begin()) continue;
    const auto& [lower_phi, lower_curve] = *std::prev(it);
    for (const auto& p : it->second)
      if (const auto lower = curve_at(lower_curve, p.shear_rate); lower && !(p.eta_re > *lower))
        out.push_back({p, lower_phi, *lower});
  }
  return out;
}

}  // namespace rbcal::calibration
