#pragma once
// The seed study's approximation eta_re = exp(alpha * phi) at one shear rate (or one Ca),
// with the coefficient of determination R^2 of the fit.
#include <vector>

namespace rbcal::calibration {

enum class AlphaFitSpace {
  linear,              // seed study: least squares on [eta_re - exp(alpha phi)] (Takeishi et al., Fig. 5 caption)
  log_through_origin,  // least squares on [ln eta_re - alpha phi]: closed form alpha = sum(phi ln y) / sum(phi^2)
};

struct ExponentialAlphaFit {
  double alpha = 0.0;
  double r_squared = 0.0;  // 1 - SS_res / SS_tot in the space of the fit (SS_tot about the mean)
  int points = 0;
};

// Throws std::invalid_argument for fewer than one point, sizes that differ, or eta_re <= 0.
ExponentialAlphaFit fit_exponential_alpha(const std::vector<double>& phi, const std::vector<double>& eta_re,
                                          AlphaFitSpace space = AlphaFitSpace::linear);

}  // namespace rbcal::calibration
