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
// The prior of a fitted lambda: ln lambda ~ normal(ln 5, 0.375), truncated to the model's
// lambda range. The cytoplasm's viscosity is 6.07 +- 3.8 mPa s (Tomaiuolo, Biomicrofluidics
// 8 (2014) 051501, as summarised by the seed study), which over a plasma of 1.2 mPa s gives
// the seed study's physiological range lambda 1.89-8.23; 0.375 makes that range the 95 %
// interval in ln lambda (ln(8.23 / 1.89) / 3.92), centred on the seed study's 5.
inline constexpr double kLambdaPriorLogSd = 0.375;

struct ModelSetup {
  double cell_radius = kDefaultCellRadius;  // a [m]
  double lambda = kDefaultViscosityRatio;   // fixed, or the start when fit_lambda
  // Fitted by the direct fit and the MCMC as a nuisance parameter (the alpha method uses
  // lambda), with the prior ln lambda ~ normal(ln lambda, lambda_prior_log_sd); a prior sd of
  // 0 makes it uniform in ln lambda over the model's range. rbcal calibrate fits it under
  // kLambdaPriorLogSd by default (product_model_setup); these plain defaults hold it fixed.
  bool fit_lambda = false;
  double lambda_prior_log_sd = 0.0;

  // Empty when usable, else what is wrong (Ceres' Options::IsValid, as a message).
  std::string invalid_reason() const {
    if (!(cell_radius > 0.0 && std::isfinite(cell_radius))) return "cell radius must be a positive length";
    if (!(lambda > 0.0 && std::isfinite(lambda))) return "lambda must be positive";
    if (!(lambda_prior_log_sd >= 0.0 && std::isfinite(lambda_prior_log_sd)))
      return "lambda's prior sd must be zero or positive";
    return "";
  }
};

// The setup rbcal calibrate (and the Python API) start from: lambda fitted under its sourced
// prior.
inline ModelSetup product_model_setup() {
  ModelSetup s;
  s.fit_lambda = true;
  s.lambda_prior_log_sd = kLambdaPriorLogSd;
  return s;
}

}  // namespace rbcal::calibration
