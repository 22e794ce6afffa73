#pragma once
// What the calibration needs from a model of the suspension's relative viscosity:
// eta_re(phi, Ca, lambda) with a predictive standard deviation and derivatives.
// The Gaussian-process surrogate implements it; tests implement it with known
// analytic functions. All quantities are dimensionless (docs/reference.md).

#include <algorithm>
#include <initializer_list>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
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

// Predictions whose errors are independent: the covariance is the diagonal of each sd^2.
inline JointViscosityPrediction without_correlation(std::vector<ViscosityPrediction> points) {
  Eigen::VectorXd variances(static_cast<Eigen::Index>(points.size()));
  for (std::size_t i = 0; i < points.size(); ++i) variances(static_cast<Eigen::Index>(i)) = points[i].sd * points[i].sd;
  return {std::move(points), JointCovariance::diagonal_only(std::move(variances))};
}

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

// Values of a model's nuisance parameters, by name (ModelNuisance::name). A nuisance not named
// is taken at its prior mean; a name the model does not have is an error.
class NuisanceValues {
 public:
  NuisanceValues() = default;
  NuisanceValues(std::initializer_list<std::pair<std::string, double>> values) : values_(values) {}
  // values[k] for nuisances[k]: a parameter vector in the model's order, named.
  NuisanceValues(const std::vector<ModelNuisance>& nuisances, const std::vector<double>& values) {
    if (values.size() != nuisances.size())
      throw std::invalid_argument("nuisance values: " + std::to_string(values.size()) + " values for " +
                                  std::to_string(nuisances.size()) + " nuisance parameters");
    for (std::size_t k = 0; k < values.size(); ++k) values_.emplace_back(nuisances[k].name, values[k]);
  }
  // Sets (or replaces) one value.
  void set(const std::string& name, double value) {
    for (auto& [n, v] : values_)
      if (n == name) {
        v = value;
        return;
      }
    values_.emplace_back(name, value);
  }
  std::optional<double> find(const std::string& name) const {
    for (const auto& [n, v] : values_)
      if (n == name) return v;
    return std::nullopt;
  }
  // The value given for the nuisance, else its prior mean.
  double value_or_mean(const ModelNuisance& nuisance) const { return find(nuisance.name).value_or(nuisance.mean); }
  bool empty() const { return values_.empty(); }
  const std::vector<std::pair<std::string, double>>& entries() const { return values_; }

 private:
  std::vector<std::pair<std::string, double>> values_;
};

class ViscosityModel {
 public:
  virtual ~ViscosityModel() = default;
  virtual ParameterRange range() const = 0;
  // The model's nuisance parameters (none for a plain surrogate).
  virtual std::vector<ModelNuisance> nuisances() const { return {}; }

  // The one question a model answers: eta_re at each point (phi: volume fraction, Ca =
  // eta0 gamma_dot a / G_s, lambda = eta1 / eta0) at the given nuisance values, with the joint
  // covariance of its errors there. The errors of a surrogate at neighbouring points are not
  // independent: the same runs inform both, and a systematic error common to every run moves
  // all points together; a likelihood that treats them as independent lets them average away
  // over a sample's points. CovarianceForm::none asks for each point's own sd only (the
  // covariance is then its diagonal), the cheap answer for point-wise use.
  // Throws std::invalid_argument for a nuisance name the model does not have.
  JointViscosityPrediction predict_joint(const std::vector<ParameterPoint>& points, const NuisanceValues& nuisances = {},
                                         CovarianceForm form = CovarianceForm::automatic) const {
    check_names(nuisances);
    return joint_prediction(points, nuisances, form);
  }
  // The same question at one point, and at several points without their covariance.
  ViscosityPrediction predict(double phi, double capillary_number, double viscosity_ratio,
                              const NuisanceValues& nuisances = {}) const {
    return predict_joint({{phi, capillary_number, viscosity_ratio}}, nuisances, CovarianceForm::none).points.front();
  }
  std::vector<ViscosityPrediction> predict_many(const std::vector<ParameterPoint>& points,
                                                const NuisanceValues& nuisances = {}) const {
    return predict_joint(points, nuisances, CovarianceForm::none).points;
  }

 private:
  // What a model implements (names already checked).
  virtual JointViscosityPrediction joint_prediction(const std::vector<ParameterPoint>& points,
                                                    const NuisanceValues& nuisances, CovarianceForm form) const = 0;

  void check_names(const NuisanceValues& values) const {
    if (values.empty()) return;
    const std::vector<ModelNuisance> known = nuisances();
    for (const auto& entry : values.entries()) {
      const std::string& name = entry.first;  // not a structured binding: clang 14 cannot capture one
      if (std::none_of(known.begin(), known.end(), [&](const ModelNuisance& n) { return n.name == name; }))
        throw std::invalid_argument("the model has no nuisance parameter '" + name + "'");
    }
  }
};

// A model whose errors at different points are independent, asked point by point (analytic
// laws, test models): the covariance is the diagonal of each point's sd^2.
class PointwiseViscosityModel : public ViscosityModel {
 protected:
  virtual ViscosityPrediction predict_point(double phi, double capillary_number, double viscosity_ratio,
                                            const NuisanceValues& nuisances) const = 0;

 private:
  JointViscosityPrediction joint_prediction(const std::vector<ParameterPoint>& points, const NuisanceValues& nuisances,
                                            CovarianceForm /*form*/) const override {
    std::vector<ViscosityPrediction> out;
    out.reserve(points.size());
    for (const ParameterPoint& q : points)
      out.push_back(predict_point(q.phi, q.capillary_number, q.viscosity_ratio, nuisances));
    return without_correlation(std::move(out));
  }
};

}  // namespace rbcal::surrogate
