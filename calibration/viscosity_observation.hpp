#pragma once
// The model's prediction for one measured point at given (G_s, lambda): the bridge between
// physical shear rates and the dimensionless model, shared by the direct fit and the posterior.
#include <cmath>
#include <vector>

#include "calibration/calibration_input.hpp"
#include "calibration/capillary_number.hpp"
#include "surrogate/viscosity_model.hpp"

namespace rbcal::calibration {

// eta_re of a measured point and its measurement sd.
struct ObservedRelativeViscosity {
  double eta_re = 1.0;
  double sd = 0.0;
};

// The sd of a measured eta_re about the model's at one point: the model's own predictive sd,
// the discrepancy term (a relative sd) and the measurement error, in quadrature. What the
// posterior predictive check draws its noise from.
inline double predictive_sd(const surrogate::ViscosityPrediction& p, double discrepancy, double measured_sd) {
  return std::sqrt(p.sd * p.sd + std::pow(discrepancy * p.eta_re, 2) + measured_sd * measured_sd);
}

// With eta0 fixed at the sample's estimate: the point's eta_re and eta_re_sd (eta0's error folded
// in). With eta0 a parameter: viscosity / eta0 and viscosity_se / eta0 (eta0's error is then in
// its prior, common to all points).
inline ObservedRelativeViscosity observed_relative_viscosity(const RelativeViscosityPoint& point,
                                                             bool plasma_viscosity_is_parameter,
                                                             double plasma_viscosity) {
  if (!plasma_viscosity_is_parameter) return {point.eta_re, point.eta_re_sd};
  return {point.viscosity / plasma_viscosity, point.viscosity_se / plasma_viscosity};
}

// Whether eta0 can be a nuisance parameter for this sample: it has a standard error and every
// point carries its absolute viscosity.
inline bool plasma_viscosity_can_be_parameter(const SampleData& sample) {
  if (!(sample.plasma.standard_error > 0.0) || !(sample.plasma.eta0 > 0.0)) return false;
  for (const auto& p : sample.points)
    if (!(p.viscosity > 0.0)) return false;
  return true;
}

struct ViscosityObservation {
  const surrogate::ViscosityModel* model = nullptr;
  double plasma_viscosity = 0.0;            // eta0 [Pa s]
  double cell_radius = kDefaultCellRadius;  // a [m]
  // Values of the model's nuisance parameters by name (surrogate/viscosity_model.hpp); empty: their means.
  surrogate::NuisanceValues nuisance;

  double capillary_number_at(const RelativeViscosityPoint& point, double shear_modulus) const {
    return capillary_number(plasma_viscosity, point.shear_rate, cell_radius, shear_modulus);
  }
  surrogate::ViscosityPrediction predict(const RelativeViscosityPoint& point, double shear_modulus,
                                         double lambda) const {
    return model->predict(point.phi, capillary_number_at(point, shear_modulus), lambda, nuisance);
  }
  // predict at every point (batched by the model).
  std::vector<surrogate::ViscosityPrediction> predict_many(const std::vector<RelativeViscosityPoint>& points,
                                                           double shear_modulus, double lambda) const {
    std::vector<surrogate::ParameterPoint> queries;
    queries.reserve(points.size());
    for (const auto& point : points) queries.push_back({point.phi, capillary_number_at(point, shear_modulus), lambda});
    return model->predict_many(queries, nuisance);
  }
  // Whether the point's (phi, Ca, lambda) lies in the box the model was built on.
  bool inside_range(const RelativeViscosityPoint& point, double shear_modulus, double lambda) const {
    const surrogate::ParameterRange r = model->range();
    const double ca = capillary_number_at(point, shear_modulus);
    return r.contains(point.phi, ca, lambda);
  }
};

}  // namespace rbcal::calibration
