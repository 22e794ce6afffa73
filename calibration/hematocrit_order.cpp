#include "calibration/hematocrit_order.hpp"

#include "calibration/detail/curve_interpolation.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

namespace rbcal::calibration {

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
    const auto& [lower_phi, lower_points] = *std::prev(it);
    const SortedCurve lower_curve(lower_points);
    for (const auto& p : it->second)
      if (const auto lower = lower_curve.at(p.shear_rate); lower && !(p.eta_re > *lower))
        out.push_back({p, lower_phi, *lower});
  }
  return out;
}

}  // namespace rbcal::calibration
