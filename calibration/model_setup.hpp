#pragma once
// What the three calibration methods (alpha matching, direct fit, MCMC) share about the
// model, set once and passed to each: the cell radius a that maps a shear rate to the
// capillary number, Ca = eta0 gamma_dot a / G_s, and the viscosity ratio lambda at which
// the surrogate is evaluated (fixed, or fitted by the direct fit and the MCMC).
#include <cmath>
#include <string>

#include "calibration/capillary_number.hpp"

namespace rbcal::calibration {

// The seed study's lambda for intact cells (cytoplasm about five times plasma viscosity).
inline constexpr double kDefaultViscosityRatio = 5.0;

struct ModelSetup {
  double cell_radius = kDefaultCellRadius;  // a [m]
  double lambda = kDefaultViscosityRatio;   // fixed, or the start when fit_lambda
  bool fit_lambda = false;                  // direct fit and MCMC; the alpha method uses lambda

  // Empty when usable, else what is wrong (Ceres' Options::IsValid, as a message).
  std::string invalid_reason() const {
    if (!(cell_radius > 0.0 && std::isfinite(cell_radius))) return "cell radius must be a positive length";
    if (!(lambda > 0.0 && std::isfinite(lambda))) return "lambda must be positive";
    return "";
  }
};

}  // namespace rbcal::calibration
