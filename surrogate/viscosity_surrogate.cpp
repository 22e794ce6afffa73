#include "surrogate/viscosity_surrogate.hpp"

#include <cmath>
#include <string>
#include <Eigen/QR>
#include <stdexcept>

#include "surrogate/detail/hyperparameter_fit.hpp"

namespace rbcal::surrogate {

namespace {

Eigen::Vector3d input_of(const TrainingCase& c) { return {c.phi, c.ln_ca, c.ln_lambda}; }

void check_cases(const std::vector<TrainingCase>& cases) {
  if (cases.size() < 4) throw std::invalid_argument("viscosity surrogate: needs at least 4 cases, got " + std::to_string(cases.size()));
  for (const TrainingCase& c : cases)
    if (!(std::isfinite(c.phi) && std::isfinite(c.ln_ca) && std::isfinite(c.ln_lambda) && std::isfinite(c.ln_eta_re) &&
          c.noise_variance >= 0.0 && std::isfinite(c.noise_variance) && c.phi > 0.0))
      throw std::invalid_argument("viscosity surrogate: case " + c.id + " has a non-finite or invalid value");
}

}  // namespace

ViscositySurrogate::Terms ViscositySurrogate::terms_for(const std::vector<TrainingCase>& cases) {
  check_cases(cases);
  Terms t;
  for (const TrainingCase& c : cases) {
    t.ca = t.ca || c.ln_ca != cases.front().ln_ca;
    t.lambda = t.lambda || c.ln_lambda != cases.front().ln_lambda;
  }
  return t;
}

Eigen::VectorXd ViscositySurrogate::basis_of(const Eigen::VectorXd& x, Terms terms) {
  Eigen::VectorXd h(1 + terms.ca + terms.lambda);
  Eigen::Index k = 0;
  h(k++) = x(0);
  if (terms.ca) h(k++) = x(0) * x(1);
  if (terms.lambda) h(k++) = x(0) * x(2);
  return h;
}

GaussianProcessData ViscositySurrogate::process_data(const std::vector<TrainingCase>& cases, Terms terms) {
  const Eigen::Index n = static_cast<Eigen::Index>(cases.size());
  GaussianProcessData d;
  d.inputs.resize(n, 3);
  d.targets.resize(n);
  d.noise_variances.resize(n);
  d.basis.resize(n, 1 + terms.ca + terms.lambda);
  for (Eigen::Index i = 0; i < n; ++i) {
    const TrainingCase& c = cases[static_cast<std::size_t>(i)];
    d.inputs.row(i) = input_of(c).transpose();
    d.targets(i) = c.ln_eta_re;
    d.noise_variances(i) = c.noise_variance;
    d.basis.row(i) = basis_of(input_of(c), terms).transpose();
  }
  return d;
}

ViscositySurrogate ViscositySurrogate::fit(std::vector<TrainingCase> cases, std::string source_library) {
  const Terms terms = terms_for(cases);
  const GaussianProcessData data = process_data(cases, terms);
  const Eigen::VectorXd ranges = data.inputs.colwise().maxCoeff() - data.inputs.colwise().minCoeff();
  // Start the signal variance at the variance of y about its ordinary least-squares mean.
  const Eigen::VectorXd ols = data.basis.colPivHouseholderQr().solve(data.targets);
  const Eigen::VectorXd residual = data.targets - data.basis * ols;
  const double residual_variance = residual.squaredNorm() / static_cast<double>(residual.size());
  const HyperparameterFitResult result =
      fit_hyperparameters(data, default_hyperparameter_fit_options(ranges, residual_variance));
  ViscositySurrogate fitted(std::move(cases), result.hyperparameters, std::move(source_library),
                            {result.log_marginal_likelihood, result.starts_tried, result.starts_converged});
  fitted.predictive_sd_scale_ = std::max(1.0, fitted.held_out_rms());
  return fitted;
}

ViscositySurrogate ViscositySurrogate::with_hyperparameters_of(std::vector<TrainingCase> cases,
                                                             const ViscositySurrogate& reference,
                                                             std::string source_library) {
  const SurrogateFitInfo shared{reference.fit_info_.log_marginal_likelihood, 0, 0};  // no starts of its own
  ViscositySurrogate s(std::move(cases), reference.process_.hyperparameters(), std::move(source_library), shared);
  s.predictive_sd_scale_ = std::max(1.0, s.held_out_rms());
  return s;
}

ViscositySurrogate::ViscositySurrogate(std::vector<TrainingCase> cases, GaussianProcessHyperparameters hyperparameters,
                                       std::string source_library, SurrogateFitInfo fit_info,
                                       double predictive_sd_scale)
    : cases_(std::move(cases)),
      source_library_(std::move(source_library)),
      fit_info_(fit_info),
      predictive_sd_scale_(predictive_sd_scale),
      terms_(terms_for(cases_)),
      process_(process_data(cases_, terms_), std::move(hyperparameters)) {
  if (!(predictive_sd_scale_ >= 1.0 && std::isfinite(predictive_sd_scale_)))
    throw std::invalid_argument("viscosity surrogate: the predictive sd scale must be finite and at least 1");
  mean_terms_.push_back("phi");
  if (terms_.ca) mean_terms_.push_back("phi ln Ca");
  if (terms_.lambda) mean_terms_.push_back("phi ln lambda");
  lower_ = process_.data().inputs.colwise().minCoeff().transpose();
  upper_ = process_.data().inputs.colwise().maxCoeff().transpose();
  // exp(ln x) may miss x by a few ulps; widen by 1e-12 so the library's own Ca and lambda
  // values (0.01, 10) compare as inside.
  const double slack = 1e-12;
  range_ = {lower_(0),
            upper_(0),
            std::exp(lower_(1)) * (1.0 - slack),
            std::exp(upper_(1)) * (1.0 + slack),
            std::exp(lower_(2)) * (1.0 - slack),
            std::exp(upper_(2)) * (1.0 + slack)};
}

Eigen::VectorXd ViscositySurrogate::input(double phi, double capillary_number, double viscosity_ratio) const {
  // An infinite Ca or lambda would pass "> 0" and come back as NaN predictions.
  if (!(capillary_number > 0.0 && std::isfinite(capillary_number)) ||
      !(viscosity_ratio > 0.0 && std::isfinite(viscosity_ratio)) || !std::isfinite(phi))
    throw std::invalid_argument("viscosity surrogate: need finite phi, finite Ca > 0 and finite lambda > 0 (got phi " +
                                std::to_string(phi) + ", Ca " + std::to_string(capillary_number) + ", lambda " +
                                std::to_string(viscosity_ratio) + ")");
  return Eigen::Vector3d(phi, std::log(capillary_number), std::log(viscosity_ratio));
}

Eigen::VectorXd ViscositySurrogate::basis(const Eigen::VectorXd& x) const { return basis_of(x, terms_); }

Eigen::MatrixXd ViscositySurrogate::basis_jacobian(const Eigen::VectorXd& x) const {
  Eigen::MatrixXd j = Eigen::MatrixXd::Zero(1 + terms_.ca + terms_.lambda, 3);
  Eigen::Index k = 0;
  j(k++, 0) = 1.0;  // d phi / d phi
  if (terms_.ca) j(k, 0) = x(1), j(k++, 1) = x(0);
  if (terms_.lambda) j(k, 0) = x(2), j(k++, 2) = x(0);
  return j;
}

bool ViscositySurrogate::inside_hull(double phi, double capillary_number, double viscosity_ratio) const {
  const Eigen::VectorXd x = input(phi, capillary_number, viscosity_ratio);
  for (int d = 0; d < 3; ++d) {
    // phi: the seeded phi_actual scatters about the planned phi (the seeding stops within 0.5 %),
    // so the planned grid's edges count as inside up to 1 %; ln Ca, ln lambda: round-off only.
    const double tolerance = d == 0 ? 0.01 * std::max(std::abs(lower_(d)), std::abs(upper_(d)))
                                    : 1e-9 * (1.0 + std::abs(lower_(d)) + std::abs(upper_(d)));
    if (x(d) < lower_(d) - tolerance || x(d) > upper_(d) + tolerance) return false;
  }
  return true;
}

ViscosityPrediction ViscositySurrogate::prediction_from(double mean, double variance, const Eigen::VectorXd& mean_gradient,
                                                        double phi, double capillary_number, double viscosity_ratio) const {
  ViscosityPrediction out;
  out.eta_re = std::exp(mean);
  out.sd = out.eta_re * predictive_sd_scale_ * std::sqrt(variance);  // delta method: sd(exp y) ~ exp(E y) sd(y)
  out.d_phi = out.eta_re * mean_gradient(0);
  out.d_ln_ca = out.eta_re * mean_gradient(1);
  out.d_ln_lambda = out.eta_re * mean_gradient(2);
  out.inside_hull = inside_hull(phi, capillary_number, viscosity_ratio);
  return out;
}

ViscosityPrediction ViscositySurrogate::predict_one(double phi, double capillary_number, double viscosity_ratio) const {
  const Eigen::VectorXd x = input(phi, capillary_number, viscosity_ratio);
  const GaussianProcessPrediction p = process_.predict(x, basis(x), basis_jacobian(x));
  return prediction_from(p.mean, p.variance, p.mean_gradient, phi, capillary_number, viscosity_ratio);
}

std::vector<ViscosityPrediction> ViscositySurrogate::predict_rows(const std::vector<ParameterPoint>& queries,
                                                                 LatentCovariance form, JointCovariance* covariance) const {
  const auto n = static_cast<Eigen::Index>(queries.size());
  Eigen::MatrixXd x_rows(n, 3), h_rows(n, 1 + terms_.ca + terms_.lambda);
  for (Eigen::Index i = 0; i < n; ++i) {
    const ParameterPoint& q = queries[static_cast<std::size_t>(i)];
    const Eigen::VectorXd x = input(q.phi, q.capillary_number, q.viscosity_ratio);
    x_rows.row(i) = x.transpose();
    h_rows.row(i) = basis(x).transpose();
  }
  GaussianProcessPredictions p = process_.predict_many(x_rows, h_rows, form);
  if (covariance) *covariance = std::move(p.covariance);
  std::vector<ViscosityPrediction> out;
  out.reserve(queries.size());
  for (Eigen::Index i = 0; i < n; ++i) {
    const ParameterPoint& q = queries[static_cast<std::size_t>(i)];
    const Eigen::VectorXd x = x_rows.row(i).transpose();
    const Eigen::VectorXd gradient =
        p.kernel_gradient.row(i).transpose() + basis_jacobian(x).transpose() * process_.mean_coefficients();
    out.push_back(prediction_from(p.mean(i), p.variance(i), gradient, q.phi, q.capillary_number, q.viscosity_ratio));
  }
  return out;
}

JointViscosityPrediction ViscositySurrogate::joint_prediction(const std::vector<ParameterPoint>& queries,
                                                             const NuisanceValues& /*nuisances: none*/,
                                                             CovarianceForm form) const {
  if (form == CovarianceForm::none)
    return without_correlation(
        queries.size() == 1u
            ? std::vector{predict_one(queries[0].phi, queries[0].capillary_number, queries[0].viscosity_ratio)}
            : predict_rows(queries, LatentCovariance::none, nullptr));
  const bool exact = form == CovarianceForm::exact ||
                     (form == CovarianceForm::automatic && queries.size() <= kExactJointCovarianceLimit);
  JointViscosityPrediction out;
  out.points = predict_rows(queries, exact ? LatentCovariance::exact : LatentCovariance::low_rank, &out.covariance);
  Eigen::VectorXd eta(static_cast<Eigen::Index>(queries.size()));
  for (Eigen::Index i = 0; i < eta.size(); ++i) eta(i) = out.points[static_cast<std::size_t>(i)].eta_re;
  out.covariance.scale(predictive_sd_scale_ * eta);  // delta method, as predict's sd
  return out;
}

double ViscositySurrogate::log_viscosity_sd(double phi, double capillary_number, double viscosity_ratio) const {
  const Eigen::VectorXd x = input(phi, capillary_number, viscosity_ratio);
  return predictive_sd_scale_ * std::sqrt(process_.latent_variance(x, basis(x)));
}

Eigen::VectorXd ViscositySurrogate::mean_coefficient_sds() const {
  return process_.mean_coefficient_covariance().diagonal().cwiseSqrt();
}

double ViscositySurrogate::held_out_rms() const {
  const LeaveOneOutPredictions loo = process_.leave_one_out();
  double sum = 0.0;
  for (std::size_t i = 0; i < cases_.size(); ++i) {
    const auto k = static_cast<Eigen::Index>(i);
    const TrainingCase& c = cases_[i];
    const double run = c.run_noise_variance >= 0.0 ? c.run_noise_variance : c.noise_variance;
    const double variance = loo.variance(k) - c.noise_variance + run;  // the case's noise swapped for its run's
    const double r = c.ln_eta_re - loo.mean(k);
    sum += r * r / variance;
  }
  return std::sqrt(sum / static_cast<double>(cases_.size()));
}

LeaveOneOutReport ViscositySurrogate::leave_one_out() const {
  const LeaveOneOutPredictions loo = process_.leave_one_out();
  LeaveOneOutReport report;
  double sum_relative = 0.0, sum_z = 0.0;
  for (std::size_t i = 0; i < cases_.size(); ++i) {
    const Eigen::Index k = static_cast<Eigen::Index>(i);
    const double sd_y = std::sqrt(loo.variance(k));
    LeaveOneOutCase c;
    c.id = cases_[i].id;
    c.eta_re = std::exp(cases_[i].ln_eta_re);
    c.eta_re_predicted = std::exp(loo.mean(k));
    c.sd = c.eta_re_predicted * sd_y;
    c.standardised_residual = (cases_[i].ln_eta_re - loo.mean(k)) / sd_y;
    c.relative_error = (c.eta_re_predicted - c.eta_re) / c.eta_re;
    sum_relative += c.relative_error * c.relative_error;
    sum_z += c.standardised_residual * c.standardised_residual;
    report.max_abs_standardised_residual = std::max(report.max_abs_standardised_residual, std::abs(c.standardised_residual));
    report.cases.push_back(c);
  }
  const double n = static_cast<double>(cases_.size());
  report.rms_relative_error = std::sqrt(sum_relative / n);
  report.rms_standardised_residual = std::sqrt(sum_z / n);
  return report;
}

}  // namespace rbcal::surrogate
