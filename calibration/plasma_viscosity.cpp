#include "calibration/plasma_viscosity.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

#include "calibration/sample_mean.hpp"

namespace rbcal::calibration {

PlasmaViscosity estimate_plasma_viscosity(const std::vector<RheometerRow>& plasma_rows,
                                          const std::string& source, const PlasmaViscosityOptions& options) {
  std::vector<const RheometerRow*> plateau;
  for (const auto& row : plasma_rows)
    if (row.kind == MeasurementKind::plasma && row.shear_rate > options.plateau_min_shear_rate)
      plateau.push_back(&row);
  if (plateau.empty()) {
    std::ostringstream what;
    what << "sample '" << (plasma_rows.empty() ? std::string("?") : plasma_rows.front().sample)
         << "' has no plasma rows on the plateau (shear rate > " << options.plateau_min_shear_rate << " 1/s)";
    throw RheometerDataError(source, plasma_rows.empty() ? 0 : plasma_rows.front().line, "shear_rate_per_s",
                             what.str());
  }
  const double m = static_cast<double>(plateau.size());
  PlasmaViscosity result;
  result.plateau_rows = static_cast<int>(plateau.size());
  std::vector<double> viscosities;
  double variance_of_sum = 0.0;
  for (const auto* row : plateau) {
    viscosities.push_back(row->viscosity);
    variance_of_sum += row->viscosity_sd * row->viscosity_sd / row->repeats;
  }
  const SampleMean scatter = sample_mean(viscosities);
  result.eta0 = scatter.mean;
  result.propagated_standard_error = std::sqrt(variance_of_sum) / m;
  result.scatter_standard_error = scatter.standard_error;
  result.standard_error = std::max(result.scatter_standard_error, result.propagated_standard_error);
  return result;
}

}  // namespace rbcal::calibration
