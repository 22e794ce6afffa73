#pragma once
// A point of the model's parameter space: volume fraction phi, capillary number
// Ca = eta0 gamma_dot a / G_s and viscosity ratio lambda = eta1 / eta0. The one type for such a
// point: a plan's grid node, a library's nominal point, a query of the model, a proposed case.
namespace rbcal::formats {

struct ParameterPoint {
  double phi = 0.0, capillary_number = 0.0, viscosity_ratio = 0.0;
};

}  // namespace rbcal::formats
