#pragma once
// A known analytic stand-in for the surrogate, shaped like the seed study's exp(alpha phi) law:
//   ln eta_re = phi (c0 - c1 ln Ca + c2 ln lambda) + c3 ln(lambda) phi^2
// so alpha(Ca, lambda) falls with Ca (shear thinning); c3 != 0 lets lambda be told apart from G_s.
// Predictive sd = relative_sd * eta_re.
#include <cmath>

#include "surrogate/viscosity_model.hpp"

namespace rbcal::calibration::test_models {

class AnalyticViscosityModel : public surrogate::PointwiseViscosityModel {
 public:
  double c0 = 2.0, c1 = 0.3, c2 = 0.1, c3 = 0.0;
  double relative_sd = 0.01;
  surrogate::ParameterRange box{0.02, 0.6, 0.003, 20.0, 0.1, 20.0};

  surrogate::ViscosityPrediction predict_point(double phi, double ca, double lambda,
                                              const surrogate::NuisanceValues&) const override {
    const double l = std::log(lambda);
    const double alpha = c0 - c1 * std::log(ca) + c2 * l;
    surrogate::ViscosityPrediction p;
    p.eta_re = std::exp(phi * alpha + c3 * l * phi * phi);
    p.sd = relative_sd * p.eta_re;
    p.d_phi = p.eta_re * (alpha + 2.0 * c3 * l * phi);
    p.d_ln_ca = -p.eta_re * c1 * phi;
    p.d_ln_lambda = p.eta_re * (c2 * phi + c3 * phi * phi);
    p.inside_hull = phi >= box.phi_min && phi <= box.phi_max && ca >= box.ca_min && ca <= box.ca_max;
    return p;
  }
  surrogate::ParameterRange range() const override { return box; }
};

// The law of the tests' synthetic rheometer file (data/make_synthetic_rheometer.py):
// c0 2.5, c1 0.4, no lambda dependence.
inline AnalyticViscosityModel synthetic_rheometer_law() {
  AnalyticViscosityModel m;
  m.c0 = 2.5;
  m.c1 = 0.4;
  m.c2 = 0.0;
  return m;
}

}  // namespace rbcal::calibration::test_models
