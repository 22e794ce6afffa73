#include "calibration/direct_fit.hpp"

#include <ceres/ceres.h>

#include <algorithm>
#include <boost/math/distributions/normal.hpp>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "calibration/viscosity_observation.hpp"

namespace rbcal::calibration {

namespace {

// (eta_re - model) / sqrt(measurement var + model var); differentiated numerically so that the
// dependence of the model's sd on the parameters is part of the Jacobian too.
struct WeightedResidual {
  ViscosityObservation observation;
  RelativeViscosityPoint point;
  bool operator()(const double* ln_shear_modulus, const double* ln_lambda, double* residual) const {
    const auto p = observation.predict(point, std::exp(ln_shear_modulus[0]), std::exp(ln_lambda[0]));
    residual[0] = (point.eta_re - p.eta_re) / std::sqrt(point.eta_re_sd * point.eta_re_sd + p.sd * p.sd);
    return std::isfinite(residual[0]);
  }
};

double weighted_residual(const ViscosityObservation& obs, const RelativeViscosityPoint& point, double ln_gs,
                         double ln_lambda) {
  double r = 0.0;
  WeightedResidual{obs, point}(&ln_gs, &ln_lambda, &r);
  return r;
}

std::vector<bool> select_inside(const ViscosityObservation& obs, const std::vector<RelativeViscosityPoint>& points,
                                double ln_gs, double lambda) {
  std::vector<bool> inside(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) inside[i] = obs.inside_range(points[i], std::exp(ln_gs), lambda);
  return inside;
}

// The grid node with the smallest mean squared weighted residual among those where at least half
// as many points as at the best-covered node are inside the model's range.
double scan_start(const ViscosityObservation& obs, const std::vector<RelativeViscosityPoint>& points,
                  const DirectFitOptions& options, double ln_lambda) {
  const double lo = std::log(options.shear_modulus_min), hi = std::log(options.shear_modulus_max);
  const int n = std::max(2, options.start_grid_points);
  std::vector<int> counts(n);
  std::vector<double> scores(n);
  for (int k = 0; k < n; ++k) {
    const double x = lo + (hi - lo) * k / (n - 1);
    const auto inside = select_inside(obs, points, x, std::exp(ln_lambda));
    double sum = 0.0;
    for (std::size_t i = 0; i < points.size(); ++i)
      if (inside[i]) {
        sum += std::pow(weighted_residual(obs, points[i], x, ln_lambda), 2);
        ++counts[k];
      }
    scores[k] = counts[k] > 0 ? sum / counts[k] : std::numeric_limits<double>::infinity();
  }
  const int most = *std::max_element(counts.begin(), counts.end());
  int best = -1;
  for (int k = 0; k < n; ++k)
    if (2 * counts[k] >= most && (best < 0 || scores[k] < scores[best])) best = k;
  return lo + (hi - lo) * best / (n - 1);
}

ceres::LossFunction* make_loss(const DirectFitOptions& options) {
  switch (options.loss) {
    case RobustLoss::huber: return new ceres::HuberLoss(options.loss_scale);
    case RobustLoss::cauchy: return new ceres::CauchyLoss(options.loss_scale);
    case RobustLoss::none: break;
  }
  return nullptr;
}

}  // namespace

DirectFitResult fit_direct(const SampleData& sample, const surrogate::ViscosityModel& model,
                           const DirectFitOptions& options) {
  const ViscosityObservation obs{&model, sample.plasma.eta0, options.cell_radius};
  const surrogate::ParameterRange range = model.range();
  DirectFitResult result;
  result.plasma_viscosity = sample.plasma.eta0;
  result.parameter_names = {"ln_G_s"};
  if (options.fit_lambda) result.parameter_names.push_back("ln_lambda");
  const int parameters = static_cast<int>(result.parameter_names.size());

  double ln_lambda = std::log(options.lambda);
  const double ln_lambda_lo = std::log(std::max(range.lambda_min, 1e-300));
  const double ln_lambda_hi = std::log(std::max(range.lambda_max, 1e-300));
  if (options.fit_lambda) ln_lambda = std::clamp(ln_lambda, ln_lambda_lo, ln_lambda_hi);
  double ln_gs = scan_start(obs, sample.points, options, ln_lambda);
  const double ln_gs_lo = std::log(options.shear_modulus_min), ln_gs_hi = std::log(options.shear_modulus_max);

  std::vector<bool> used = select_inside(obs, sample.points, ln_gs, std::exp(ln_lambda));
  ceres::Solver::Summary summary;
  for (int round = 0; round < std::max(1, options.max_selection_rounds); ++round) {
    const int n_used = static_cast<int>(std::count(used.begin(), used.end(), true));
    if (n_used < parameters) {
      std::ostringstream what;
      what << "sample '" << sample.name << "': " << n_used << " point(s) inside the model's range, need at least "
           << parameters;
      throw std::invalid_argument(what.str());
    }
    ceres::Problem problem;
    for (std::size_t i = 0; i < sample.points.size(); ++i) {
      if (!used[i]) continue;
      auto* cost = new ceres::NumericDiffCostFunction<WeightedResidual, ceres::CENTRAL, 1, 1, 1>(
          new WeightedResidual{obs, sample.points[i]});
      problem.AddResidualBlock(cost, make_loss(options), &ln_gs, &ln_lambda);
    }
    problem.SetParameterLowerBound(&ln_gs, 0, ln_gs_lo);
    problem.SetParameterUpperBound(&ln_gs, 0, ln_gs_hi);
    if (options.fit_lambda) {
      problem.SetParameterLowerBound(&ln_lambda, 0, ln_lambda_lo);
      problem.SetParameterUpperBound(&ln_lambda, 0, ln_lambda_hi);
    } else {
      problem.SetParameterBlockConstant(&ln_lambda);
    }
    ceres::Solver::Options solver_options;
    solver_options.minimizer_type = ceres::TRUST_REGION;  // bounds need it
    solver_options.linear_solver_type = ceres::DENSE_QR;
    solver_options.num_threads = 1;
    solver_options.logging_type = ceres::SILENT;
    solver_options.max_num_iterations = 200;
    solver_options.function_tolerance = 1e-12;
    solver_options.parameter_tolerance = 1e-12;
    solver_options.gradient_tolerance = 1e-14;
    ceres::Solve(solver_options, &problem, &summary);

    const std::vector<bool> now_inside = select_inside(obs, sample.points, ln_gs, std::exp(ln_lambda));
    const bool last_round = round + 1 == std::max(1, options.max_selection_rounds);
    if (now_inside == used || last_round) {
      if (now_inside != used)
        result.messages.push_back("the set of points inside the model's range still changed after the last refit");
      result.converged = summary.IsSolutionUsable() && summary.termination_type == ceres::CONVERGENCE;
      result.solver_report = summary.BriefReport();
      // Laplace covariance from the Jacobian at the estimate (Ceres: (J^T J)^-1).
      ceres::Covariance::Options cov_options;
      cov_options.num_threads = 1;
      // SPARSE_QR (the default) reports a rank-deficient Jacobian as a failure; DENSE_SVD would not
      // for an all-zero Jacobian (its relative singular-value test has nothing to compare with).
      cov_options.algorithm_type = ceres::SPARSE_QR;
      ceres::Covariance covariance(cov_options);
      std::vector<std::pair<const double*, const double*>> blocks = {{&ln_gs, &ln_gs}};
      if (options.fit_lambda) {
        blocks.push_back({&ln_gs, &ln_lambda});
        blocks.push_back({&ln_lambda, &ln_lambda});
      }
      result.covariance = Eigen::MatrixXd::Zero(parameters, parameters);
      result.covariance_ok = covariance.Compute(blocks, &problem);
      if (result.covariance_ok) {
        covariance.GetCovarianceBlock(&ln_gs, &ln_gs, &result.covariance(0, 0));
        if (options.fit_lambda) {
          covariance.GetCovarianceBlock(&ln_gs, &ln_lambda, &result.covariance(0, 1));
          covariance.GetCovarianceBlock(&ln_lambda, &ln_lambda, &result.covariance(1, 1));
          result.covariance(1, 0) = result.covariance(0, 1);
        }
        result.covariance_ok = result.covariance.allFinite() && (result.covariance.diagonal().array() > 0.0).all();
      }
      if (!result.covariance_ok) {
        result.covariance.setConstant(std::numeric_limits<double>::quiet_NaN());
        result.messages.push_back("Laplace covariance failed (Jacobian rank deficient): no interval");
      }
      break;
    }
    used = now_inside;
  }

  result.estimate.resize(parameters);
  result.estimate(0) = ln_gs;
  if (options.fit_lambda) result.estimate(1) = ln_lambda;
  result.shear_modulus = std::exp(ln_gs);
  result.lambda = std::exp(ln_lambda);
  const double bound_tolerance = 1e-6;
  result.at_bound = ln_gs - ln_gs_lo < bound_tolerance || ln_gs_hi - ln_gs < bound_tolerance ||
                    (options.fit_lambda &&
                     (ln_lambda - ln_lambda_lo < bound_tolerance || ln_lambda_hi - ln_lambda < bound_tolerance));
  if (result.at_bound) result.messages.push_back("an estimate sits on its bound: the Laplace interval is unreliable");

  for (std::size_t i = 0; i < sample.points.size(); ++i) {
    FittedPoint f;
    f.point = sample.points[i];
    f.used = used[i];
    f.capillary_number = obs.capillary_number_at(f.point, result.shear_modulus);
    const auto p = obs.predict(f.point, result.shear_modulus, result.lambda);
    f.predicted_eta_re = p.eta_re;
    f.predicted_sd = p.sd;
    f.weighted_residual = weighted_residual(obs, f.point, ln_gs, ln_lambda);
    if (!f.used) {
      std::ostringstream why;
      why << "outside the model's range (phi " << f.point.phi << ", Ca " << f.capillary_number << ", lambda "
          << result.lambda << ")";
      f.reason = why.str();
    } else {
      result.chi_square += f.weighted_residual * f.weighted_residual;
      ++result.degrees_of_freedom;
    }
    result.points.push_back(f);
  }
  result.degrees_of_freedom -= parameters;
  const int skipped = static_cast<int>(std::count(used.begin(), used.end(), false));
  if (skipped > 0)
    result.messages.push_back(std::to_string(skipped) + " point(s) outside the model's range were not fitted");

  if (options.scale_covariance_by_reduced_chi_square && result.degrees_of_freedom > 0)
    result.covariance *= result.chi_square / result.degrees_of_freedom;
  const double z = boost::math::quantile(boost::math::normal(), 0.5 * (1.0 + options.interval_level));
  result.ln_shear_modulus_sd = std::sqrt(result.covariance(0, 0));
  result.shear_modulus_interval = {std::exp(ln_gs - z * result.ln_shear_modulus_sd),
                                   std::exp(ln_gs + z * result.ln_shear_modulus_sd), options.interval_level};
  if (options.fit_lambda) {
    const double sd = std::sqrt(result.covariance(1, 1));
    result.lambda_interval = {std::exp(ln_lambda - z * sd), std::exp(ln_lambda + z * sd), options.interval_level};
  } else {
    result.lambda_interval = {result.lambda, result.lambda, options.interval_level};
  }
  return result;
}

}  // namespace rbcal::calibration
