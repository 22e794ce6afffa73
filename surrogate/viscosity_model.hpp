#pragma once
// What the calibration needs from a model of the suspension's relative viscosity:
// eta_re(phi, Ca, lambda) with a predictive standard deviation and derivatives.
// The Gaussian-process surrogate implements it; tests implement it with known
// analytic functions. All quantities are dimensionless (docs/reference.md).

#include <string>
#include <vector>

#include <Eigen/Core>

#include "formats/parameter_point.hpp"
#include "surrogate/joint_covariance.hpp"

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

  // The one rule for "inside the model's range", bounds included, used by every method.
  bool contains_phi(double phi) const { return phi >= phi_min && phi <= phi_max; }
  bool contains_ca(double ca) const { return ca >= ca_min && ca <= ca_max; }
  bool contains_lambda(double lambda) const { return lambda >= lambda_min && lambda <= lambda_max; }
  bool contains(double phi, double ca, double lambda) const {
    return contains_phi(phi) && contains_ca(ca) && contains_lambda(lambda);
  }
};

// A point at which the model is asked: (phi, Ca, lambda).
using formats::ParameterPoint;

// The model at several points at once: each point's prediction, and the joint covariance of the
// predicted eta_re (model uncertainty only; its diagonal is each point's sd^2).
struct JointViscosityPrediction {
  std::vector<ViscosityPrediction> points;
  JointCovariance covariance;  // of the eta_re errors
};

// Up to this many points a surrogate gives its joint covariance exactly, as one n x n matrix;
// beyond, as a diagonal plus a low-rank factor (joint_covariance.hpp), whose likelihood costs
// O(n r^2) instead of O(n^3).
inline constexpr std::size_t kExactJointCovarianceLimit = 256;

// A parameter of the model that is not known exactly and that the calibration therefore
// carries as a nuisance parameter with this prior: normal(mean, sd) truncated to [min, max].
// One exists (surrogate/offset_family.hpp): the immersed boundary's offset c, in lattice
// spacings, which sets the volume fraction a finite-resolution run stands for (docs/library.md,
// "The effective volume fraction").
struct ModelNuisance {
  std::string name;  // parameter name in reports: "offset_c"
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
  // predict at each query (a model may batch them: the same numbers, faster).
  virtual std::vector<ViscosityPrediction> predict_many(const std::vector<ParameterPoint>& queries) const {
    std::vector<ViscosityPrediction> out;
    out.reserve(queries.size());
    for (const ParameterPoint& q : queries) out.push_back(predict(q.phi, q.capillary_number, q.viscosity_ratio));
    return out;
  }

  // The model's nuisance parameters (none for a plain surrogate), and its prediction at given
  // values of them (one per nuisances(), in that order; predict() uses their means).
  virtual std::vector<ModelNuisance> nuisances() const { return {}; }
  virtual ViscosityPrediction predict_with(double phi, double capillary_number, double viscosity_ratio,
                                           const std::vector<double>& /*nuisance_values*/) const {
    return predict(phi, capillary_number, viscosity_ratio);
  }
  // predict_with at each query (empty values: predict_many); a model may batch them.
  virtual std::vector<ViscosityPrediction> predict_many_with(const std::vector<ParameterPoint>& queries,
                                                             const std::vector<double>& nuisance_values) const {
    if (nuisance_values.empty()) return predict_many(queries);
    std::vector<ViscosityPrediction> out;
    out.reserve(queries.size());
    for (const ParameterPoint& q : queries)
      out.push_back(predict_with(q.phi, q.capillary_number, q.viscosity_ratio, nuisance_values));
    return out;
  }

  // The model at several points with the joint covariance of its errors there, at given nuisance
  // values (empty: their means). The errors of a surrogate at neighbouring points are not
  // independent: the same runs inform both, and a systematic error common to every run moves all
  // points together. A likelihood that treats them as independent lets them average away over a
  // sample's points. This default knows no correlation: the covariance is diagonal.
  virtual JointViscosityPrediction predict_joint(const std::vector<ParameterPoint>& queries,
                                                 const std::vector<double>& nuisance_values,
                                                 CovarianceForm /*form*/ = CovarianceForm::automatic) const {
    JointViscosityPrediction out;
    const auto n = static_cast<Eigen::Index>(queries.size());
    Eigen::VectorXd variances(n);
    for (Eigen::Index i = 0; i < n; ++i) {
      const ParameterPoint& q = queries[static_cast<std::size_t>(i)];
      out.points.push_back(nuisance_values.empty()
                               ? predict(q.phi, q.capillary_number, q.viscosity_ratio)
                               : predict_with(q.phi, q.capillary_number, q.viscosity_ratio, nuisance_values));
      variances(i) = out.points.back().sd * out.points.back().sd;
    }
    out.covariance = JointCovariance::diagonal_only(std::move(variances));
    return out;
  }
};

}  // namespace rbcal::surrogate
