#pragma once
// One training point of the viscosity surrogate: input x = (phi_actual, ln Ca, ln lambda),
// target y = ln eta_re with the observation noise variance of y taken from the case's
// standard error by the delta method, (eta_re_sem / eta_re)^2 (heteroscedastic).
#include <string>
#include <vector>

#include "surrogate/simulation_library.hpp"

namespace rbcal::surrogate {

struct TrainingCase {
  std::string id;
  double phi = 0.0;             // the case's actual volume fraction
  double ln_ca = 0.0;           // ln Ca
  double ln_lambda = 0.0;       // ln lambda
  double ln_eta_re = 0.0;       // y
  double noise_variance = 0.0;  // var(y) = (eta_re_sem / eta_re)^2
  // The run's own share of it (without an offset's share; library_case.hpp run_sd): what a new
  // run at the same point scatters by. Negative: the whole noise_variance.
  double run_noise_variance = -1.0;
};

TrainingCase training_case(const LibraryCase& c);
std::vector<TrainingCase> training_cases(const SimulationLibrary& library);

}  // namespace rbcal::surrogate
