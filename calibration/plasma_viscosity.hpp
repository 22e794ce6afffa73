#pragma once
// Plasma viscosity eta0 of one sample: the mean over the shear-rate plateau (the seed study
// used gamma_dot > 10 1/s and found 1.569 +- 0.033 mPa s at 22 C), with its standard error.
#include <string>
#include <vector>

#include "calibration/rheometer_data.hpp"

namespace rbcal::calibration {

struct PlasmaViscosityOptions {
  double plateau_min_shear_rate = 10.0;  // [1/s]; rows with gamma_dot > this value are averaged
};

struct PlasmaViscosity {
  double eta0 = 0.0;                       // [Pa s], unweighted mean of the plateau rows
  double standard_error = 0.0;             // [Pa s], the larger of the two below (conservative)
  double scatter_standard_error = 0.0;     // s / sqrt(m) over the m plateau rows (0 if m = 1)
  double propagated_standard_error = 0.0;  // sqrt(sum sd_i^2 / n_i) / m, from the rows' own sd
  int plateau_rows = 0;
  bool assumed = false;  // given as an assumption (plasma_assumed row), not measured
};

// plasma_rows: the rows of one sample whose kind is plasma. Throws RheometerDataError naming
// the sample's first plasma line if no row lies on the plateau.
PlasmaViscosity estimate_plasma_viscosity(const std::vector<RheometerRow>& plasma_rows,
                                          const std::string& source,
                                          const PlasmaViscosityOptions& options = {});

}  // namespace rbcal::calibration
