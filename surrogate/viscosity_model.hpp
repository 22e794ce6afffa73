#pragma once
// What the calibration needs from a model of the suspension's relative viscosity:
// eta_re(phi, Ca, lambda) with a predictive standard deviation and derivatives.
// The Gaussian-process surrogate implements it; tests implement it with known
// analytic functions. All quantities are dimensionless (DESIGN.md section 2).

#include <string>
#include <vector>

namespace rbcal::surrogate {

struct ViscosityPrediction {
  double eta_re = 1.0;       // predicted relative viscosity eta / eta0
  double sd = 0.0;           // predictive standard deviation of eta_re (model uncertainty only)
  double d_phi = 0.0;        // d eta_re / d phi
  double d_ln_ca = 0.0;      // d eta_re / d ln Ca
  double d_ln_lambda = 0.0;  // d eta_re / d ln lambda
  bool inside_hull = true;   // false where the query leaves the range the model was built on
};

// The box of (phi, Ca, lambda) the model was built on.
struct ParameterRange {
  double phi_min = 0.0, phi_max = 0.0;
  double ca_min = 0.0, ca_max = 0.0;
  double lambda_min = 0.0, lambda_max = 0.0;
};

// A parameter of the model that is not known exactly and that the calibration therefore
// carries as a nuisance parameter with this prior: normal(mean, sd) truncated to [min, max].
// Two exist (surrogate/offset_family.hpp): the immersed boundary's offset c, in lattice
// spacings, which sets the volume fraction a finite-resolution run stands for (docs/library.md,
// "The effective volume fraction"), and the box correction beta, ln eta_bulk = (1 + beta) ln
// eta_re, which carries the library's 8a gap to a bulk suspension.
struct ModelNuisance {
  std::string name;  // parameter name in reports: "offset_c", "box_beta"
  std::string what;  // one line for the report
  double mean = 0.0, sd = 0.0;
  double min = 0.0, max = 0.0;
};

class ViscosityModel {
 public:
  virtual ~ViscosityModel() = default;
  // phi: volume fraction, capillary_number: Ca = eta0 gamma_dot a / G_s, viscosity_ratio: lambda = eta1 / eta0.
  // A model with nuisance parameters predicts at their prior means here.
  virtual ViscosityPrediction predict(double phi, double capillary_number, double viscosity_ratio) const = 0;
  virtual ParameterRange range() const = 0;

  // The model's nuisance parameters (none for a plain surrogate), and its prediction at given
  // values of them (one per nuisances(), in that order; predict() uses their means).
  virtual std::vector<ModelNuisance> nuisances() const { return {}; }
  virtual ViscosityPrediction predict_with(double phi, double capillary_number, double viscosity_ratio,
                                           const std::vector<double>& /*nuisance_values*/) const {
    return predict(phi, capillary_number, viscosity_ratio);
  }
};

}  // namespace rbcal::surrogate
