#include "solver/simulation/window_drift.hpp"

#include <cmath>
#include <numeric>

namespace rbcal::solver {

WindowDrift window_drift(const std::vector<double>& series, double relative_sem) {
  WindowDrift d;
  const std::size_t half = series.size() / 2;
  // Below 32 samples the window's blocking error (which keeps 8 blocks at least) reaches
  // blocks of two samples only: too short a correlation to trust for the drift's sd.
  if (half < 16) return d;
  const double early = std::accumulate(series.begin(), series.begin() + half, 0.0) / half;
  const double late = std::accumulate(series.end() - half, series.end(), 0.0) / half;
  if (early <= 0.0 || late <= 0.0) return d;
  d.available = true;
  d.drift = std::log(late / early);
  d.sd = 2.0 * relative_sem;
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
