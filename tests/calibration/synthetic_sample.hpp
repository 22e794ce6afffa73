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
  // > 0: eta0 is itself measured with this relative standard error (the seed study's 0.033 / 1.569
  // is 2.1 %); the points then carry absolute viscosities and eta_re = eta / eta0_hat.
  double plasma_relative_standard_error = 0.0;
};

inline SampleData synthetic_sample(const surrogate::ViscosityModel& model, const SyntheticDesign& design,
                                   std::mt19937_64& rng) {
  std::normal_distribution<double> normal;
  SampleData sample;
  sample.name = "synthetic";
  const double rel0 = design.plasma_relative_standard_error;
  const double eta0_hat = design.plasma_viscosity * (1.0 + rel0 * normal(rng));
  sample.plasma.eta0 = eta0_hat;
  sample.plasma.standard_error = rel0 * eta0_hat;
  for (double phi : design.phis)
    for (double rate : design.shear_rates) {
      const double ca = capillary_number(design.plasma_viscosity, rate, kDefaultCellRadius, design.shear_modulus);
      const auto p = model.predict(phi, ca, design.lambda);
      RelativeViscosityPoint point;
      point.phi = phi;
      point.shear_rate = rate;
      point.eta_re_sd = design.relative_measurement_sd * p.eta_re;
      point.eta_re = p.eta_re + point.eta_re_sd * normal(rng) + (design.add_model_noise ? p.sd * normal(rng) : 0.0);
      if (rel0 > 0.0) {
        point.viscosity = design.plasma_viscosity * point.eta_re;
        point.viscosity_se = design.plasma_viscosity * point.eta_re_sd;
        point.eta_re = point.viscosity / eta0_hat;
        point.eta_re_sd = point.eta_re * std::hypot(design.relative_measurement_sd, rel0);
      }
      sample.points.push_back(point);
    }
  return sample;
}

}  // namespace rbcal::calibration::test_models
