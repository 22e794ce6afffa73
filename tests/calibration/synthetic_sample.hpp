#pragma once
// Synthetic rheometer samples drawn from a known model at a known G_s, with Gaussian noise.
#include <cmath>
#include <random>
#include <vector>

#include "calibration/calibration_input.hpp"
#include "calibration/capillary_number.hpp"
#include "surrogate/viscosity_model.hpp"

namespace rbcal::calibration::test_models {

struct SyntheticDesign {
  std::vector<double> phis = {0.1, 0.2, 0.3, 0.4};
  std::vector<double> shear_rates = {1.0, 2.2, 4.6, 10.0, 22.0, 46.0, 100.0, 220.0};  // [1/s]
  double plasma_viscosity = 1.569e-3;  // [Pa s], seed study
  double shear_modulus = 0.5e-6;       // [N/m]
  double lambda = 5.0;
  double relative_measurement_sd = 0.02;  // sd of eta_re / eta_re
  bool add_model_noise = true;            // also draw the model's predictive sd (as the likelihood assumes)
};

inline SampleData synthetic_sample(const surrogate::ViscosityModel& model, const SyntheticDesign& design,
                                   std::mt19937_64& rng) {
  std::normal_distribution<double> normal;
  SampleData sample;
  sample.name = "synthetic";
  sample.plasma.eta0 = design.plasma_viscosity;
  for (double phi : design.phis)
    for (double rate : design.shear_rates) {
      const double ca = capillary_number(design.plasma_viscosity, rate, kDefaultCellRadius, design.shear_modulus);
      const auto p = model.predict(phi, ca, design.lambda);
      RelativeViscosityPoint point;
      point.phi = phi;
      point.shear_rate = rate;
      point.eta_re_sd = design.relative_measurement_sd * p.eta_re;
      point.eta_re = p.eta_re + point.eta_re_sd * normal(rng) + (design.add_model_noise ? p.sd * normal(rng) : 0.0);
      sample.points.push_back(point);
    }
  return sample;
}

}  // namespace rbcal::calibration::test_models
