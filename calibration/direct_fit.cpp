#include "calibration/direct_fit.hpp"

#include <ceres/ceres.h>

#include <algorithm>
#include <array>
#include <boost/math/distributions/normal.hpp>
#include <cmath>
#include <deque>
#include <limits>
#include <memory>
#include <mutex>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <tuple>
#include <utility>

#include "calibration/joint_likelihood.hpp"
#include "formats/units.hpp"
#include "calibration/viscosity_observation.hpp"

namespace rbcal::calibration {

namespace {

// The parameters as Ceres sees them: three blocks of size one (some held constant).
struct FitParameters {
  double ln_shear_modulus = 0.0;
  double ln_lambda = 0.0;
  double ln_plasma_viscosity = 0.0;
  // The model's nuisance parameters (viscosity_model.hpp), as many as it has; the rest unused.
  std::array<double, kMaxModelNuisances> nuisance{};
};

// One point at the parameters as Ceres passes them: its measured eta_re (with sd, which depends on
// eta0 when eta0 is a parameter) and the model's prediction.
struct PointAtParameters {
  ViscosityObservation observation;
  RelativeViscosityPoint point;
  bool plasma_viscosity_is_parameter = false;
  std::vector<std::string> nuisances;  // the names of the model's nuisance blocks in use
  std::pair<ObservedRelativeViscosity, surrogate::ViscosityPrediction> operator()(
      const double* ln_shear_modulus, const double* ln_lambda, const double* ln_plasma_viscosity,
      const double* nuisance0, const double* nuisance1) const {
    ViscosityObservation at = observation;
    at.plasma_viscosity = std::exp(ln_plasma_viscosity[0]);
    const double* values[kMaxModelNuisances] = {nuisance0, nuisance1};
    for (std::size_t k = 0; k < nuisances.size(); ++k) at.nuisance.set(nuisances[k], values[k][0]);
    return {observed_relative_viscosity(point, plasma_viscosity_is_parameter, at.plasma_viscosity),
            at.predict(point, std::exp(ln_shear_modulus[0]), std::exp(ln_lambda[0]))};
  }
};

// (eta_re - model) / sqrt(measurement var + model var); differentiated numerically so that the
// dependence of the model's sd on the parameters is part of the Jacobian too.
struct WeightedResidual {
  PointAtParameters at;
  bool operator()(const double* ln_shear_modulus, const double* ln_lambda, const double* ln_plasma_viscosity,
                  const double* nuisance0, const double* nuisance1, double* residual) const {
    const auto [measured, p] = at(ln_shear_modulus, ln_lambda, ln_plasma_viscosity, nuisance0, nuisance1);
    residual[0] = (measured.eta_re - p.eta_re) / std::sqrt(measured.sd * measured.sd + p.sd * p.sd);
    return std::isfinite(residual[0]);
  }
  double operator()(const FitParameters& x) const {
    double r = 0.0;
    (*this)(&x.ln_shear_modulus, &x.ln_lambda, &x.ln_plasma_viscosity, &x.nuisance[0], &x.nuisance[1], &r);
    return r;
  }
};

// Every used point at once with the model's errors correlated between them (joint_likelihood.hpp):
// the whitened residuals L^-1 r (Sigma = L L^T), or, as a separate block, the likelihood's
// normalisation 1/2 ln det Sigma, written as the residual sqrt(ln det Sigma - ln det Sigma_ref + K n)
// whose half square is that term up to a constant. Without it a least-squares fit is drawn to where
// the model is least certain (a large Sigma shrinks every residual), while the posterior
// (posterior.hpp) keeps the term; with it the fit is the posterior's mode, and the direct fit and
// the MCMC answer the same question. Sigma_ref is Sigma at the start; K = 10 per point keeps the
// root real unless det Sigma falls by a factor e^(10 n) from there.
// The likelihood's last evaluations by parameter values, shared by the whitened residuals and the
// normalisation: Ceres asks both blocks at the same points (every numerical-derivative step), and
// each evaluation costs a joint prediction at every point.
class JointEvaluationCache {
 public:
  using Key = std::array<double, 3 + kMaxModelNuisances>;
  template <typename Compute>
  WhitenedResiduals get(const Key& key, Compute compute) {
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      for (const auto& [k, value] : entries_)
        if (k == key) return value;
    }
    WhitenedResiduals value = compute();
    const std::lock_guard<std::mutex> lock(mutex_);
    entries_.emplace_front(key, value);
    if (entries_.size() > kEntries) entries_.pop_back();
    return value;
  }

 private:
  static constexpr std::size_t kEntries = 4 * (3 + kMaxModelNuisances) + 4;  // one Jacobian's steps and more
  std::mutex mutex_;
  std::deque<std::pair<Key, WhitenedResiduals>> entries_;
};

// Parameters as the per-point residuals: ln G_s, ln lambda, ln eta0, the two nuisance blocks.
struct JointResidualBlock {
  ViscosityObservation observation;
  std::vector<RelativeViscosityPoint> points;
  bool plasma_viscosity_is_parameter = false;
  std::vector<std::string> nuisances;  // the names of the model's nuisance blocks in use
  bool normalisation = false;           // false: the whitened residuals; true: the normalisation
  double ln_reference_determinant = 0.0;
  static constexpr double kShiftPerPoint = 10.0;
  std::shared_ptr<JointEvaluationCache> cache = std::make_shared<JointEvaluationCache>();

  WhitenedResiduals at(double const* const* parameters) const {
    JointEvaluationCache::Key key;
    for (std::size_t k = 0; k < key.size(); ++k) key[k] = parameters[k][0];
    return cache->get(key, [&] {
      ViscosityObservation with = observation;
      with.plasma_viscosity = std::exp(parameters[2][0]);
      for (std::size_t k = 0; k < nuisances.size(); ++k) with.nuisance.set(nuisances[k], parameters[3 + k][0]);
      return whiten(joint_residuals(with, points, std::exp(parameters[0][0]), std::exp(parameters[1][0]),
                                    plasma_viscosity_is_parameter));
    });
  }
  bool operator()(double const* const* parameters, double* residuals) const {
    const WhitenedResiduals w = at(parameters);
    if (!w.ok) return false;
    if (!normalisation) {
      for (Eigen::Index i = 0; i < w.whitened.size(); ++i) residuals[i] = w.whitened(i);
      return true;
    }
    const double argument =
        w.log_determinant - ln_reference_determinant + kShiftPerPoint * static_cast<double>(points.size());
    if (!(argument > 0.0)) return false;
    residuals[0] = std::sqrt(argument);
    return std::isfinite(residuals[0]);
  }
};

ceres::CostFunction* joint_cost(JointResidualBlock block) {
  const int residuals = block.normalisation ? 1 : static_cast<int>(block.points.size());
  auto* cost = new ceres::DynamicNumericDiffCostFunction<JointResidualBlock, ceres::CENTRAL>(
      new JointResidualBlock(std::move(block)));
  for (int k = 0; k < 3 + kMaxModelNuisances; ++k) cost->AddParameterBlock(1);
  cost->SetNumResiduals(residuals);
  return cost;
}

// A Gaussian prior on one parameter written as a residual: the plateau estimate of eta0 on
// ln eta0, a model nuisance's prior.
struct GaussianPrior {
  double mean;
  double sd;
  template <typename T>
  bool operator()(const T* parameter, T* residual) const {
    residual[0] = (parameter[0] - mean) / sd;
    return true;
  }
};

std::vector<RelativeViscosityPoint> used_subset(const std::vector<RelativeViscosityPoint>& points,
                                               const std::vector<bool>& used) {
  std::vector<RelativeViscosityPoint> subset;
  for (std::size_t i = 0; i < points.size(); ++i)
    if (used[i]) subset.push_back(points[i]);
  return subset;
}

std::vector<bool> select_inside(const ViscosityObservation& obs, const std::vector<RelativeViscosityPoint>& points,
                                const FitParameters& x) {
  ViscosityObservation at = obs;
  at.plasma_viscosity = std::exp(x.ln_plasma_viscosity);
  std::vector<bool> inside(points.size());
  for (std::size_t i = 0; i < points.size(); ++i)
    inside[i] = at.inside_range(points[i], std::exp(x.ln_shear_modulus), std::exp(x.ln_lambda));
  return inside;
}

// The mean squared weighted residual of the points in `set` at x, and how many they are (the
// mean is infinite for none).
std::pair<double, int> mean_squared_residual(const std::vector<WeightedResidual>& residuals,
                                             const std::vector<bool>& set, const FitParameters& x) {
  double sum = 0.0;
  int count = 0;
  for (std::size_t i = 0; i < set.size(); ++i)
    if (set[i]) {
      sum += std::pow(residuals[i](x), 2);
      ++count;
    }
  return {count > 0 ? sum / count : std::numeric_limits<double>::infinity(), count};
}

// The grid node of ln G_s with the smallest mean squared weighted residual among those where at
// least half as many points as at the best-covered node are inside the model's range.
double scan_start(const std::vector<WeightedResidual>& residuals, const ViscosityObservation& obs,
                  const std::vector<RelativeViscosityPoint>& points, const DirectFitOptions& options,
                  FitParameters x) {
  const double lo = std::log(options.shear_modulus_min), hi = std::log(options.shear_modulus_max);
  const int n = std::max(2, options.start_grid_points);
  std::vector<int> counts(n);
  std::vector<double> scores(n);
  for (int k = 0; k < n; ++k) {
    x.ln_shear_modulus = lo + (hi - lo) * k / (n - 1);
    std::tie(scores[k], counts[k]) = mean_squared_residual(residuals, select_inside(obs, points, x), x);
  }
  const int most = *std::max_element(counts.begin(), counts.end());
  int best = -1;
  for (int k = 0; k < n; ++k)
    if (2 * counts[k] >= most && (best < 0 || scores[k] < scores[best])) best = k;
  return lo + (hi - lo) * best / (n - 1);
}

// The ln G_s interval over which every used point keeps its Ca inside the model's range
// [ca_min, ca_max] at the given eta0 (Ca = eta0 gamma_dot a / G_s falls as G_s grows); empty
// (first > second) when the used shear rates span more than ca_max / ca_min.
std::pair<double, double> ln_shear_modulus_keeping_ca_inside(const ViscosityObservation& obs,
                                                             const std::vector<RelativeViscosityPoint>& points,
                                                             const std::vector<bool>& used,
                                                             const surrogate::ParameterRange& range) {
  double rate_min = std::numeric_limits<double>::infinity(), rate_max = 0.0;
  for (std::size_t i = 0; i < points.size(); ++i)
    if (used[i]) {
      rate_min = std::min(rate_min, points[i].shear_rate);
      rate_max = std::max(rate_max, points[i].shear_rate);
    }
  const double k = obs.plasma_viscosity * obs.cell_radius;
  return {std::log(k * rate_max / range.ca_max), std::log(k * rate_min / range.ca_min)};
}

// The largest sets of points that one G_s keeps inside the model's Ca range together: for
// each distinct shear rate of a covered point (phi inside the model's range) as the lowest,
// every covered point whose rate is at most ca_max / ca_min times larger. Two pointers over the
// points sorted by rate (O(n log n)); sets only for the windows of the largest count, at most
// kMaxCoverableSets of them, spread evenly (a held fit scans each).
constexpr std::size_t kMaxCoverableSets = 64;
std::vector<std::vector<bool>> largest_coverable_sets(const std::vector<RelativeViscosityPoint>& points,
                                                      const surrogate::ParameterRange& range) {
  std::vector<std::size_t> covered;
  for (std::size_t i = 0; i < points.size(); ++i)
    if (range.contains_phi(points[i].phi)) covered.push_back(i);
  std::sort(covered.begin(), covered.end(),
            [&](std::size_t a, std::size_t b) { return points[a].shear_rate < points[b].shear_rate; });
  const double span = range.ca_max / range.ca_min;
  std::vector<std::pair<std::size_t, std::size_t>> windows;  // [first, last) in covered
  std::size_t most = 0, end = 0;
  for (std::size_t first = 0; first < covered.size(); ++first) {
    const double low = points[covered[first]].shear_rate;
    if (first > 0 && points[covered[first - 1]].shear_rate == low) continue;  // the same window's start
    end = std::max(end, first);
    while (end < covered.size() && points[covered[end]].shear_rate <= low * span) ++end;
    if (end - first > most) windows.clear();
    if (end - first >= most) windows.push_back({first, end});
    most = std::max(most, end - first);
  }
  const std::size_t stride = std::max<std::size_t>(1, (windows.size() + kMaxCoverableSets - 1) / kMaxCoverableSets);
  std::vector<std::vector<bool>> sets;
  for (std::size_t w = 0; w < windows.size(); w += stride) {
    std::vector<bool> set(points.size());
    for (std::size_t k = windows[w].first; k < windows[w].second; ++k) set[covered[k]] = true;
    sets.push_back(std::move(set));
  }
  return sets;
}

ceres::LossFunction* make_loss(const DirectFitOptions& options) {
  switch (options.loss) {
    case RobustLoss::huber: return new ceres::HuberLoss(options.loss_scale);
    case RobustLoss::cauchy: return new ceres::CauchyLoss(options.loss_scale);
    case RobustLoss::none: break;
  }
  return nullptr;
}

// Laplace covariance (J^T J)^-1 of the free blocks at the estimate; false if Ceres reports a
// rank-deficient Jacobian or the result is not a finite, positive-diagonal matrix.
bool laplace_covariance(ceres::Problem& problem, const std::vector<double*>& free_blocks, Eigen::MatrixXd* out) {
  ceres::Covariance::Options cov_options;
  cov_options.num_threads = 1;
  // SPARSE_QR (the default) reports a rank-deficient Jacobian as a failure; DENSE_SVD would not
  // for an all-zero Jacobian (its relative singular-value test has nothing to compare with).
  cov_options.algorithm_type = ceres::SPARSE_QR;
  ceres::Covariance covariance(cov_options);
  std::vector<std::pair<const double*, const double*>> pairs;
  for (std::size_t i = 0; i < free_blocks.size(); ++i)
    for (std::size_t j = i; j < free_blocks.size(); ++j) pairs.push_back({free_blocks[i], free_blocks[j]});
  const auto n = static_cast<Eigen::Index>(free_blocks.size());
  *out = Eigen::MatrixXd::Constant(n, n, std::numeric_limits<double>::quiet_NaN());
  if (!covariance.Compute(pairs, &problem)) return false;
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index j = i; j < n; ++j) {
      covariance.GetCovarianceBlock(free_blocks[i], free_blocks[j], &(*out)(i, j));
      (*out)(j, i) = (*out)(i, j);
    }
  return out->allFinite() && (out->diagonal().array() > 0.0).all();
}

// The direct fit as named steps, in the order run() takes them: set up the parameters and
// start from a scan over ln G_s; fit the points inside the model's range, and again on the
// set the fit moves inside, for a few rounds (or, when no G_s keeps enough points inside,
// once more with G_s held at the edge of the model's Ca range); then read off the estimate,
// the diagnoses (edge fit, a bound reached), the fitted points with chi^2, and the intervals.
class DirectFit {
 public:
  DirectFit(const SampleData& sample, const surrogate::ViscosityModel& model, const DirectFitOptions& options)
      : sample_(sample),
        options_(options),
        obs_{&model, sample.plasma.eta0, options.setup.cell_radius, {}},
        range_(model.range()),
        fit_eta0_(options.plasma_viscosity_as_parameter && plasma_viscosity_can_be_parameter(sample)),
        nuisances_(options.model_nuisances_as_parameters ? model.nuisances() : std::vector<surrogate::ModelNuisance>{}) {
    if (nuisances_.size() > kMaxModelNuisances)
      throw std::invalid_argument("direct fit: the model has more than " + std::to_string(kMaxModelNuisances) +
                                  " nuisance parameters");
    n_nuisances_ = static_cast<int>(nuisances_.size());
    name_parameters();
    start();
  }

  DirectFitResult run() {
    for (int round = 0; round < rounds(); ++round) {
      choose_points_and_bounds();
      ceres::Problem problem;
      std::vector<ceres::ResidualBlockId> normalisation_blocks;
      add_likelihood(problem, normalisation_blocks);
      const std::vector<double*> free_blocks = add_priors_and_bounds(problem);
      const ceres::Solver::Summary summary = solve(problem);
      const std::vector<bool> now_inside = select_inside(obs_, sample_.points, x_);
      const bool last_round = edge_fit_ || round + 1 == rounds();
      if (now_inside == used_ || last_round) {
        settle(now_inside, summary, problem, normalisation_blocks, free_blocks);
        break;
      }
      if (held_) continue;  // the set stays; the next round bounds G_s at the new eta0
      if (first_set_.empty()) first_set_ = used_;
      used_ = now_inside;
    }
    read_estimate();
    diagnose_edge_fit();
    diagnose_bounds();
    fitted_points();
    intervals();
    return result_;
  }

 private:
  // The names of the model's nuisances in use, in the order of their parameter blocks.
  std::vector<std::string> nuisance_names() const {
    std::vector<std::string> names;
    for (const auto& n : nuisances_) names.push_back(n.name);
    return names;
  }

  static constexpr double kBoundTolerance = 1e-6;
  static constexpr double kEdgeMargin = 1e-9;  // in ln G_s

  int rounds() const { return std::max(1, options_.max_selection_rounds); }

  void name_parameters() {
    result_.plasma_viscosity_fitted = fit_eta0_;
    result_.parameter_names = ParameterLayout(options_.setup.fit_lambda, false, fit_eta0_, nuisances_).names;
    // Parameters the data alone must fix: eta0, and lambda under its prior, have prior residuals.
    fitted_to_data_ = options_.setup.fit_lambda && options_.setup.lambda_prior_log_sd <= 0.0 ? 2 : 1;
  }

  // The start: eta0 at its plateau estimate, lambda at the setup's (inside the model's range),
  // the nuisances at their prior means, ln G_s from the scan; the points inside there.
  void start() {
    x_.ln_plasma_viscosity = std::log(sample_.plasma.eta0);
    x_.ln_lambda = std::log(options_.setup.lambda);
    for (int k = 0; k < n_nuisances_; ++k) x_.nuisance[k] = nuisances_[k].mean;  // unused ones stay 0 (finite)
    ln_lambda_lo_ = std::log(std::max(range_.lambda_min, 1e-300));
    ln_lambda_hi_ = std::log(std::max(range_.lambda_max, 1e-300));
    if (options_.setup.fit_lambda) x_.ln_lambda = std::clamp(x_.ln_lambda, ln_lambda_lo_, ln_lambda_hi_);
    for (const auto& p : sample_.points) residuals_.push_back({{obs_, p, fit_eta0_, nuisance_names()}});
    x_.ln_shear_modulus = scan_start(residuals_, obs_, sample_.points, options_, x_);
    ln_gs_lo_ = std::log(options_.shear_modulus_min);
    ln_gs_hi_ = std::log(options_.shear_modulus_max);
    lo_ = ln_gs_lo_;
    hi_ = ln_gs_hi_;
    edge_ = {ln_gs_lo_, ln_gs_hi_};
    used_ = select_inside(obs_, sample_.points, x_);
    const std::vector<std::vector<bool>> coverable = largest_coverable_sets(sample_.points, range_);
    if (!coverable.empty())
      result_.coverable_points = static_cast<int>(std::count(coverable.front().begin(), coverable.front().end(), true));
    if (options_.hold_coverable_points) hold_largest_coverable_set(coverable);
  }

  // The held set (options_.hold_coverable_points): of the largest sets one G_s can keep inside
  // the Ca range, the one with the smallest mean squared weighted residual at the best node of
  // a scan of ln G_s over its window; the start moves to that node. Not held when no such
  // window meets the G_s bounds.
  void hold_largest_coverable_set(const std::vector<std::vector<bool>>& coverable) {
    ViscosityObservation at = obs_;
    at.plasma_viscosity = std::exp(x_.ln_plasma_viscosity);
    const int n = std::max(2, options_.start_grid_points);
    double best = std::numeric_limits<double>::infinity();
    for (const auto& set : coverable) {
      const auto window = ln_shear_modulus_keeping_ca_inside(at, sample_.points, set, range_);
      const double lo = std::max(ln_gs_lo_, window.first + kEdgeMargin);
      const double hi = std::min(ln_gs_hi_, window.second - kEdgeMargin);
      if (!(lo <= hi)) continue;
      FitParameters x = x_;
      for (int k = 0; k < n; ++k) {
        x.ln_shear_modulus = lo + (hi - lo) * k / (n - 1);
        const double score = mean_squared_residual(residuals_, set, x).first;
        if (score < best) {
          best = score;
          used_ = set;
          x_.ln_shear_modulus = x.ln_shear_modulus;
        }
      }
    }
    held_ = std::isfinite(best);
  }

  // A fit that carries every point out of the model's Ca range means that the data lie beyond
  // the model (below it, in practice) at any G_s inside it. The fit is then repeated on every
  // point whose phi the model covers (else on the first round's set), with G_s held where all
  // of them stay inside the Ca range: the constrained optimum, which sits on that edge (an
  // edge fit).
  void choose_points_and_bounds() {
    const int n_used = static_cast<int>(std::count(used_.begin(), used_.end(), true));
    if (n_used < fitted_to_data_) {
      if (first_set_.empty()) {
        std::ostringstream what;
        what << "sample '" << sample_.name << "': " << n_used << " point(s) inside the model's range, need at least "
             << fitted_to_data_;
        throw std::invalid_argument(what.str());
      }
      edge_fit_ = true;
      for (std::size_t i = 0; i < sample_.points.size(); ++i) used_[i] = range_.contains_phi(sample_.points[i].phi);
    }
    lo_ = ln_gs_lo_;
    hi_ = ln_gs_hi_;
    if (!edge_fit_ && !held_) return;
    ViscosityObservation at = obs_;
    at.plasma_viscosity = std::exp(x_.ln_plasma_viscosity);
    edge_ = ln_shear_modulus_keeping_ca_inside(at, sample_.points, used_, range_);
    if (edge_fit_ && (!(edge_.first <= edge_.second) || std::count(used_.begin(), used_.end(), true) < fitted_to_data_)) {
      used_ = first_set_;
      edge_ = ln_shear_modulus_keeping_ca_inside(at, sample_.points, used_, range_);
    }
    if (held_) {  // strictly inside, so that rounding keeps the held points in
      edge_.first += kEdgeMargin;
      edge_.second -= kEdgeMargin;
    }
    if (edge_.first <= edge_.second) {
      lo_ = std::max(lo_, edge_.first);
      hi_ = std::min(hi_, edge_.second);
    }
    x_.ln_shear_modulus = std::clamp(x_.ln_shear_modulus, lo_, hi_);
  }

  // The parameter blocks as every residual block takes them.
  std::vector<double*> blocks() {
    return {&x_.ln_shear_modulus, &x_.ln_lambda, &x_.ln_plasma_viscosity, &x_.nuisance[0], &x_.nuisance[1]};
  }

  // The joint likelihood of the used points (whitened residuals and normalisation), or, under
  // a robust loss, each point's own residual (the points then taken as independent).
  void add_likelihood(ceres::Problem& problem, std::vector<ceres::ResidualBlockId>& normalisation_blocks) {
    const std::vector<double*> b = blocks();
    if (options_.loss == RobustLoss::none) {
      JointResidualBlock joint{obs_, used_subset(sample_.points, used_), fit_eta0_, nuisance_names()};
      problem.AddResidualBlock(joint_cost(joint), nullptr, b);
      joint.normalisation = true;
      const WhitenedResiduals start = joint.at(b.data());
      joint.ln_reference_determinant = start.ok ? start.log_determinant : 0.0;
      normalisation_blocks.push_back(problem.AddResidualBlock(joint_cost(joint), nullptr, b));
      return;
    }
    for (std::size_t i = 0; i < sample_.points.size(); ++i) {
      if (!used_[i]) continue;
      auto* cost = new ceres::NumericDiffCostFunction<WeightedResidual, ceres::CENTRAL, 1, 1, 1, 1, 1, 1>(
          new WeightedResidual(residuals_[i]));
      problem.AddResidualBlock(cost, make_loss(options_), b);
    }
  }

  // Bounds, priors as residuals, the held blocks constant; returns the free blocks in the
  // order of the result's parameters.
  std::vector<double*> add_priors_and_bounds(ceres::Problem& problem) {
    std::vector<double*> free_blocks = {&x_.ln_shear_modulus};
    problem.SetParameterLowerBound(&x_.ln_shear_modulus, 0, lo_);
    problem.SetParameterUpperBound(&x_.ln_shear_modulus, 0, hi_);
    if (options_.setup.fit_lambda) {
      problem.SetParameterLowerBound(&x_.ln_lambda, 0, ln_lambda_lo_);
      problem.SetParameterUpperBound(&x_.ln_lambda, 0, ln_lambda_hi_);
      free_blocks.push_back(&x_.ln_lambda);
      if (options_.setup.lambda_prior_log_sd > 0.0)
        problem.AddResidualBlock(new ceres::AutoDiffCostFunction<GaussianPrior, 1, 1>(new GaussianPrior{
                                     std::log(options_.setup.lambda), options_.setup.lambda_prior_log_sd}),
                                 nullptr, &x_.ln_lambda);
    } else {
      problem.SetParameterBlockConstant(&x_.ln_lambda);
    }
    if (fit_eta0_) {
      problem.AddResidualBlock(new ceres::AutoDiffCostFunction<GaussianPrior, 1, 1>(new GaussianPrior{
                                   std::log(sample_.plasma.eta0), sample_.plasma.standard_error / sample_.plasma.eta0}),
                               nullptr, &x_.ln_plasma_viscosity);
      free_blocks.push_back(&x_.ln_plasma_viscosity);
    } else {
      problem.SetParameterBlockConstant(&x_.ln_plasma_viscosity);
    }
    for (int k = 0; k < kMaxModelNuisances; ++k) {
      if (k >= n_nuisances_) {
        problem.SetParameterBlockConstant(&x_.nuisance[k]);
        continue;
      }
      problem.AddResidualBlock(new ceres::AutoDiffCostFunction<GaussianPrior, 1, 1>(
                                   new GaussianPrior{nuisances_[k].mean, nuisances_[k].sd}),
                               nullptr, &x_.nuisance[k]);
      problem.SetParameterLowerBound(&x_.nuisance[k], 0, nuisances_[k].min);
      problem.SetParameterUpperBound(&x_.nuisance[k], 0, nuisances_[k].max);
      free_blocks.push_back(&x_.nuisance[k]);
    }
    return free_blocks;
  }

  static ceres::Solver::Summary solve(ceres::Problem& problem) {
    ceres::Solver::Options solver_options;
    solver_options.minimizer_type = ceres::TRUST_REGION;  // bounds need it
    solver_options.linear_solver_type = ceres::DENSE_QR;
    solver_options.num_threads = 1;
    solver_options.logging_type = ceres::SILENT;
    solver_options.max_num_iterations = 200;
    solver_options.function_tolerance = 1e-12;
    solver_options.parameter_tolerance = 1e-12;
    solver_options.gradient_tolerance = 1e-14;
    ceres::Solver::Summary summary;
    ceres::Solve(solver_options, &problem, &summary);
    return summary;
  }

  // The last round: convergence, and the covariance of the weighted residuals and priors
  // (Gauss-Newton; the normalisation terms are not sums of squares, and their Gauss-Newton
  // part would depend on K).
  void settle(const std::vector<bool>& now_inside, const ceres::Solver::Summary& summary, ceres::Problem& problem,
              const std::vector<ceres::ResidualBlockId>& normalisation_blocks, const std::vector<double*>& free_blocks) {
    if (now_inside != used_ && !edge_fit_) {
      result_.point_set_settled = false;
      result_.messages.push_back(kPointSetUnsettled);
    }
    result_.converged = summary.IsSolutionUsable() && summary.termination_type == ceres::CONVERGENCE;
    result_.solver_report = summary.BriefReport();
    for (ceres::ResidualBlockId id : normalisation_blocks) problem.RemoveResidualBlock(id);
    result_.covariance_ok = laplace_covariance(problem, free_blocks, &result_.covariance);
    if (!result_.covariance_ok) {
      result_.covariance.setConstant(std::numeric_limits<double>::quiet_NaN());
      result_.messages.push_back("Laplace covariance failed (Jacobian rank deficient): no interval");
    }
  }

  void read_estimate() {
    result_.estimate.resize(static_cast<Eigen::Index>(result_.parameter_names.size()));
    result_.estimate(0) = x_.ln_shear_modulus;
    if (options_.setup.fit_lambda) result_.estimate(1) = x_.ln_lambda;
    if (fit_eta0_) result_.estimate(result_.index_of("ln_eta0")) = x_.ln_plasma_viscosity;
    for (int k = 0; k < n_nuisances_; ++k) result_.estimate(result_.index_of(nuisances_[k].name)) = x_.nuisance[k];
    result_.shear_modulus = std::exp(x_.ln_shear_modulus);
    result_.lambda = std::exp(x_.ln_lambda);
    result_.plasma_viscosity = std::exp(x_.ln_plasma_viscosity);
  }

  // An edge fit that ends on the edge is a limit, not an estimate, and says which.
  void diagnose_edge_fit() {
    if (!edge_fit_ && !held_) return;
    const bool low_edge = x_.ln_shear_modulus - edge_.first < kBoundTolerance;
    const bool high_edge = edge_.second - x_.ln_shear_modulus < kBoundTolerance;
    if (!low_edge && !high_edge) return;
    result_.model_edge = low_edge ? ModelEdge::largest_ca : ModelEdge::smallest_ca;
    std::ostringstream what;
    what << "no G_s fits the data inside the model's Ca range " << range_.ca_min << " to " << range_.ca_max
         << ": the best fit carries " << (edge_fit_ ? "every point" : "points it could hold")
         << " out of it, so G_s is held where the "
         << (low_edge ? "highest" : "lowest") << " shear rate used reaches Ca " << (low_edge ? range_.ca_max : range_.ca_min)
         << "; read G_s = " << std::exp(x_.ln_shear_modulus) * kMicro << " uN/m as an "
         << limit_kind(result_.model_edge) << " limit, not an estimate (the data lie "
         << (low_edge ? "below" : "above") << " the model)";
    result_.model_edge_reason = what.str();
    result_.messages.push_back(result_.model_edge_reason);
  }

  void diagnose_bounds() {
    auto near = [](double a, double b) { return a - b < kBoundTolerance; };
    bool at_bound = near(x_.ln_shear_modulus, lo_) || near(hi_, x_.ln_shear_modulus);
    if (options_.setup.fit_lambda)
      at_bound = at_bound || near(x_.ln_lambda, ln_lambda_lo_) || near(ln_lambda_hi_, x_.ln_lambda);
    for (int k = 0; k < n_nuisances_; ++k)
      at_bound = at_bound || near(x_.nuisance[k], nuisances_[k].min) || near(nuisances_[k].max, x_.nuisance[k]);
    result_.at_bound = at_bound;
    if (at_bound) result_.messages.push_back("an estimate sits on its bound: the Laplace interval is unreliable");
  }

  // Every point at the estimate, used or left out and why; chi^2 of the used ones (of the
  // joint likelihood's whitened residuals without a robust loss) and its degrees of freedom.
  void fitted_points() {
    ViscosityObservation at_estimate = obs_;
    at_estimate.plasma_viscosity = result_.plasma_viscosity;
    for (int k = 0; k < n_nuisances_; ++k) at_estimate.nuisance.set(nuisances_[k].name, x_.nuisance[k]);
    for (std::size_t i = 0; i < sample_.points.size(); ++i) {
      FittedPoint f;
      f.point = sample_.points[i];
      f.used = used_[i];
      f.capillary_number = at_estimate.capillary_number_at(f.point, result_.shear_modulus);
      const auto p = at_estimate.predict(f.point, result_.shear_modulus, result_.lambda);
      f.predicted_eta_re = p.eta_re;
      f.predicted_sd = p.sd;
      f.weighted_residual = residuals_[i](x_);
      if (!f.used) {
        std::ostringstream why;
        why << "outside the model's range (phi " << f.point.phi << ", Ca " << f.capillary_number << ", lambda "
            << result_.lambda << ")";
        f.reason = why.str();
      } else {
        result_.chi_square += f.weighted_residual * f.weighted_residual;
        ++result_.degrees_of_freedom;
      }
      result_.points.push_back(f);
    }
    if (options_.loss == RobustLoss::none) {
      const std::vector<double*> b = blocks();
      const WhitenedResiduals w =
          JointResidualBlock{obs_, used_subset(sample_.points, used_), fit_eta0_, nuisance_names()}.at(b.data());
      if (w.ok) result_.chi_square = w.whitened.squaredNorm();
    }
    result_.degrees_of_freedom -= fitted_to_data_;
    const int skipped = static_cast<int>(std::count(used_.begin(), used_.end(), false));
    if (skipped > 0)
      result_.messages.push_back(std::to_string(skipped) + " point(s) outside the model's range were not fitted");
  }

  // Laplace intervals (optionally scaled by the reduced chi^2), nuisances' clipped to their range.
  void intervals() {
    if (options_.scale_covariance_by_reduced_chi_square && result_.degrees_of_freedom > 0)
      result_.covariance *= result_.chi_square / result_.degrees_of_freedom;
    const double z = boost::math::quantile(boost::math::normal(), 0.5 * (1.0 + options_.interval_level));
    const double level = options_.interval_level;
    result_.ln_shear_modulus_sd = std::sqrt(result_.covariance(0, 0));
    result_.shear_modulus_interval = {std::exp(x_.ln_shear_modulus - z * result_.ln_shear_modulus_sd),
                                      std::exp(x_.ln_shear_modulus + z * result_.ln_shear_modulus_sd), level};
    if (options_.setup.fit_lambda) {
      const double sd = std::sqrt(result_.covariance(1, 1));
      result_.lambda_interval = {std::exp(x_.ln_lambda - z * sd), std::exp(x_.ln_lambda + z * sd), level};
    } else {
      result_.lambda_interval = {result_.lambda, result_.lambda, level};
    }
    for (int k = 0; k < n_nuisances_; ++k) {
      const int i = result_.index_of(nuisances_[k].name);
      const double sd = std::sqrt(result_.covariance(i, i));
      result_.nuisances.push_back({nuisances_[k], x_.nuisance[k],
                                   {std::max(nuisances_[k].min, x_.nuisance[k] - z * sd),
                                    std::min(nuisances_[k].max, x_.nuisance[k] + z * sd), level}});
    }
  }

  const SampleData& sample_;
  const DirectFitOptions& options_;
  const ViscosityObservation obs_;
  const surrogate::ParameterRange range_;
  const bool fit_eta0_;
  const std::vector<surrogate::ModelNuisance> nuisances_;
  int n_nuisances_ = 0;
  int fitted_to_data_ = 1;
  FitParameters x_;
  double ln_lambda_lo_ = 0.0, ln_lambda_hi_ = 0.0;
  double ln_gs_lo_ = 0.0, ln_gs_hi_ = 0.0;
  std::vector<WeightedResidual> residuals_;
  std::vector<bool> used_, first_set_;  // the points fitted; the first round's set
  bool edge_fit_ = false;
  bool held_ = false;  // options_.hold_coverable_points, and a set could be held
  double lo_ = 0.0, hi_ = 0.0;  // ln G_s bounds of the last solve
  std::pair<double, double> edge_;
  DirectFitResult result_;
};

}  // namespace

DirectFitResult fit_direct(const SampleData& sample, const surrogate::ViscosityModel& model,
                           const DirectFitOptions& options) {
  return DirectFit(sample, model, options).run();
}

}  // namespace rbcal::calibration
