#include "surrogate/training_case.hpp"

#include <cmath>

namespace rbcal::surrogate {

TrainingCase training_case(const LibraryCase& c) {
  const double relative_sem = c.eta_re_sem / c.eta_re;
  const double relative_run = c.run_sd / c.eta_re;
  return {c.id,
          c.phi_actual,
          std::log(c.capillary_number),
          std::log(c.viscosity_ratio),
          std::log(c.eta_re),
          relative_sem * relative_sem,
          c.run_sd > 0.0 ? relative_run * relative_run : -1.0};
}

std::vector<TrainingCase> training_cases(const SimulationLibrary& library) {
  std::vector<TrainingCase> out;
  out.reserve(library.cases.size());
  for (const LibraryCase& c : library.cases) out.push_back(training_case(c));
  return out;
}

}  // namespace rbcal::surrogate
