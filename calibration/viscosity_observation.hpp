#pragma once
// The model's prediction for one measured point at given (G_s, lambda): the bridge between
// physical shear rates and the dimensionless model, shared by the direct fit and the posterior.
#include <cmath>

#include "calibration/calibration_input.hpp"
#include "calibration/capillary_number.hpp"
#include "surrogate/viscosity_model.hpp"

namespace rbcal::calibration {

struct ViscosityObservation {
  const surrogate::ViscosityModel* model = nullptr;
  double plasma_viscosity = 0.0;            // eta0 [Pa s]
  double cell_radius = kDefaultCellRadius;  // a [m]

  double capillary_number_at(const RelativeViscosityPoint& point, double shear_modulus) const {
    return capillary_number(plasma_viscosity, point.shear_rate, cell_radius, shear_modulus);
  }
  surrogate::ViscosityPrediction predict(const RelativeViscosityPoint& point, double shear_modulus,
                                         double lambda) const {
    return model->predict(point.phi, capillary_number_at(point, shear_modulus), lambda);
  }
  // Whether the point's (phi, Ca, lambda) lies in the box the model was built on.
  bool inside_range(const RelativeViscosityPoint& point, double shear_modulus, double lambda) const {
    const surrogate::ParameterRange r = model->range();
    const double ca = capillary_number_at(point, shear_modulus);
    return point.phi >= r.phi_min && point.phi <= r.phi_max && ca >= r.ca_min && ca <= r.ca_max &&
           lambda >= r.lambda_min && lambda <= r.lambda_max;
  }
};

}  // namespace rbcal::calibration
