#include "solver/simulation/window_drift.hpp"

#include <cmath>
#include <numeric>

#include "solver/simulation/detail/block_average.hpp"

namespace rbcal::solver {

WindowDrift window_drift(const std::vector<double>& series) {
  WindowDrift d;
  const std::size_t half = series.size() / 2;
  if (half < 16) return d;  // block_average keeps at least 8 blocks: two levels at least
  const double early = std::accumulate(series.begin(), series.begin() + half, 0.0) / half;
  const double late = std::accumulate(series.end() - half, series.end(), 0.0) / half;
  const MeanWithError whole = block_average(series);
  if (early <= 0.0 || late <= 0.0 || whole.mean <= 0.0) return d;
  d.available = true;
  d.drift = std::log(late / early);
  d.sd = 2.0 * whole.sem / whole.mean;
  return d;
}

bool drifts(const WindowDrift& d) {
  return d.available && std::abs(d.drift) > kDriftFloor && std::abs(d.z()) > kDriftZ;
}

WindowDrift drift_of_result(const nlohmann::json& result) {
  WindowDrift d;
  if (!result.contains("eta_re_drift") || !result.contains("eta_re_drift_sd")) return d;
  d.available = true;
  d.drift = result["eta_re_drift"].get<double>();
  d.sd = result["eta_re_drift_sd"].get<double>();
  return d;
}

}  // namespace rbcal::solver
