#include "surrogate/offset_family.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <stdexcept>
#include <string>

#include "formats/parallel_for.hpp"

namespace rbcal::surrogate {

namespace {

constexpr double kBoxMin = -0.5, kBoxMax = 1.0;  // where the box correction's prior mean may lie

}  // namespace

OffsetFamilyModel::OffsetFamilyModel(std::vector<OffsetFamilyMember> members, double prior_mean, double prior_sd,
                                     std::optional<BoxCorrectionPrior> box)
    : members_(std::move(members)), box_(box) {
  if (members_.size() < 2) throw std::invalid_argument("offset family: needs at least two members");
  for (const auto& m : members_) {
    if (!m.model) throw std::invalid_argument("offset family: a member has no model");
    if (!std::isfinite(m.offset)) throw std::invalid_argument("offset family: offsets must be finite");
    if (!m.model->nuisances().empty())
      throw std::invalid_argument("offset family: a member has nuisance parameters of its own");
  }
  const double step = members_[1].offset - members_[0].offset;
  if (!(step > 0.0)) throw std::invalid_argument("offset family: offsets must increase");
  for (std::size_t i = 1; i < members_.size(); ++i) {
    const double d = members_[i].offset - members_[i - 1].offset;
    if (std::abs(d - step) > 1e-9 * std::max(1.0, std::abs(step)))
      throw std::invalid_argument("offset family: offsets must be equally spaced (member " + std::to_string(i) +
                                  " is " + std::to_string(members_[i].offset) + ")");
  }
  offset_ = {"offset_c", "immersed-boundary offset, lattice spacings", prior_mean, prior_sd, members_.front().offset,
             members_.back().offset};
  if (!(prior_sd > 0.0 && std::isfinite(prior_sd))) throw std::invalid_argument("offset family: prior sd must be positive");
  if (!(prior_mean >= offset_.min && prior_mean <= offset_.max))
    throw std::invalid_argument("offset family: prior mean must lie between the first and last offsets");
  if (box_ && !(box_->sd > 0.0 && std::isfinite(box_->sd) && box_->mean > kBoxMin && box_->mean < kBoxMax))
    throw std::invalid_argument("offset family: the box correction's prior needs sd > 0 and a mean in (-0.5, 1)");
  if (box_ && !(box_->ca_knee >= 0.0 && std::isfinite(box_->ca_knee) && std::isfinite(box_->ca_slope) &&
                box_->ca_slope_sd >= 0.0 && std::isfinite(box_->ca_slope_sd)))
    throw std::invalid_argument("offset family: the box correction's Ca knee and slope sd must be finite and not negative");
  if (box_ && !box_->depends_on_ca() && (box_->ca_slope != 0.0 || box_->ca_slope_sd != 0.0))
    throw std::invalid_argument("offset family: the box correction has a Ca slope but no Ca knee");
  range_ = members_.front().model->range();
  for (const auto& m : members_) {
    const ParameterRange r = m.model->range();
    range_.phi_min = std::max(range_.phi_min, r.phi_min);
    range_.phi_max = std::min(range_.phi_max, r.phi_max);
    range_.ca_min = std::max(range_.ca_min, r.ca_min);
    range_.ca_max = std::min(range_.ca_max, r.ca_max);
    range_.lambda_min = std::max(range_.lambda_min, r.lambda_min);
    range_.lambda_max = std::min(range_.lambda_max, r.lambda_max);
  }
}

std::vector<double> OffsetFamilyModel::weights(double offset) const {
  const int n = static_cast<int>(members_.size());
  const double c0 = members_.front().offset;
  const double h = members_[1].offset - c0;
  double s = (offset - c0) / h;
  if (std::abs(s - std::round(s)) < 1e-9) s = std::round(s);  // at a member: that member alone, exactly
  const int i = std::clamp(static_cast<int>(std::floor(s)), 0, n - 2);
  const double u = s - i;  // in [0, 1] inside the family, beyond at the ends
  // Hermite basis on [c_i, c_{i+1}]: value = h00 y_i + h01 y_{i+1} + h (h10 m_i + h11 m_{i+1}).
  const double h00 = (1.0 + 2.0 * u) * (1.0 - u) * (1.0 - u);
  const double h01 = u * u * (3.0 - 2.0 * u);
  const double h10 = u * (1.0 - u) * (1.0 - u);
  const double h11 = -u * u * (1.0 - u);
  std::vector<double> w(static_cast<std::size_t>(n), 0.0);
  w[i] += h00;
  w[i + 1] += h01;
  // h m_k as weights on the members: central inside, one-sided at the ends.
  auto add_slope = [&](int k, double factor) {
    if (k == 0) {
      w[1] += factor;
      w[0] -= factor;
    } else if (k == n - 1) {
      w[n - 1] += factor;
      w[n - 2] -= factor;
    } else {
      w[k + 1] += 0.5 * factor;
      w[k - 1] -= 0.5 * factor;
    }
  };
  add_slope(i, h10);
  add_slope(i + 1, h11);
  return w;
}

std::vector<ModelNuisance> OffsetFamilyModel::nuisances() const { return {offset_}; }

OffsetFamilyModel::Boxed OffsetFamilyModel::boxed(const ViscosityPrediction& p, double capillary_number) const {
  if (!box_) return {p, p.sd, 0.0, 0.0};
  const double lever = box_->lever(capillary_number);
  Boxed b{with_box_correction(p, box_->at(capillary_number)), 0.0, 0.0, 0.0};
  b.sd_without_box = b.prediction.sd;
  b.box_gradient = b.prediction.eta_re * std::log(p.eta_re);
  b.slope_gradient = b.box_gradient * lever;
  // Above the knee beta itself moves with ln Ca: d eta / d ln Ca gains d eta / d beta * ca_slope.
  if (lever > 0.0) b.prediction.d_ln_ca += b.box_gradient * box_->ca_slope;
  b.prediction.sd = std::hypot(b.sd_without_box, box_->sd * b.box_gradient, box_->ca_slope_sd * b.slope_gradient);
  return b;
}

JointViscosityPrediction OffsetFamilyModel::joint_prediction(const std::vector<ParameterPoint>& queries,
                                                            const NuisanceValues& values, CovarianceForm form) const {
  const double offset = values.value_or_mean(offset_);
  if (form == CovarianceForm::none) {
    const std::vector<double> w = weights(offset);
    std::vector<std::vector<ViscosityPrediction>> member(members_.size());
    for (std::size_t k = 0; k < members_.size(); ++k)
      if (w[k] != 0.0) member[k] = members_[k].model->predict_many(queries);
    std::vector<ViscosityPrediction> points;
    points.reserve(queries.size());
    for (std::size_t i = 0; i < queries.size(); ++i)
      points.push_back(boxed(combined(w, [&](std::size_t k) { return member[k][i]; }), queries[i].capillary_number).prediction);
    return without_correlation(std::move(points));
  }
  JointViscosityPrediction out;
  const auto n = static_cast<Eigen::Index>(queries.size());
  // The bracketing members' correlations, weighted linearly in c.
  const double h = members_[1].offset - members_[0].offset;
  const double s = std::clamp((offset - members_.front().offset) / h, 0.0, static_cast<double>(members_.size() - 1));
  const auto lower = std::min(static_cast<std::size_t>(std::floor(s)), members_.size() - 2);
  const double t = s - static_cast<double>(lower);
  const auto correlation_weight = [&](std::size_t k) { return k == lower ? 1.0 - t : k == lower + 1 ? t : 0.0; };
  // Each member is asked once: jointly where its correlation is needed, point by point elsewhere.
  const std::vector<double> w = weights(offset);
  // In parallel over members for many points (the low-rank path, milliseconds a member), unless
  // inside a parallel region already (the MCMC's chains, even one thread of them): for a few
  // points a parallel region costs more than the members.
  std::vector<JointViscosityPrediction> member(members_.size());
  const bool parallel = omp_get_level() == 0 && queries.size() > kExactJointCovarianceLimit;
  formats::parallel_for(
      static_cast<std::ptrdiff_t>(members_.size()), 0,
      [&](std::ptrdiff_t i) {
        const auto k = static_cast<std::size_t>(i);
        if (correlation_weight(k) != 0.0) {
          member[k] = members_[k].model->predict_joint(queries, {}, form);
        } else if (w[k] != 0.0) {
          member[k].points = members_[k].model->predict_many(queries);
        }
      },
      parallel);
  Eigen::VectorXd sd(n), box_gradient(n), slope_gradient(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const auto at = static_cast<std::size_t>(i);
    const Boxed b = boxed(combined(w, [&](std::size_t k) { return member[k].points[at]; }), queries[at].capillary_number);
    out.points.push_back(b.prediction);
    sd(i) = b.sd_without_box;
    box_gradient(i) = b.box_gradient;
    slope_gradient(i) = b.slope_gradient;
  }
  JointCovariance correlation;
  for (std::size_t k : {lower, lower + 1})
    if (correlation_weight(k) != 0.0) correlation.add(correlation_of(member[k].covariance), correlation_weight(k));
  out.covariance = std::move(correlation);
  out.covariance.scale(sd);
  if (box_) out.covariance.add_rank_one(box_gradient, box_->sd * box_->sd);
  if (box_ && box_->ca_slope_sd > 0.0) out.covariance.add_rank_one(slope_gradient, box_->ca_slope_sd * box_->ca_slope_sd);
  return out;
}

ViscosityPrediction with_box_correction(const ViscosityPrediction& p, double beta) {
  // eta' = eta^(1 + beta): d eta' / d eta = (1 + beta) eta^beta.
  ViscosityPrediction q = p;
  q.eta_re = std::pow(p.eta_re, 1.0 + beta);
  const double slope = (1.0 + beta) * q.eta_re / p.eta_re;
  q.sd = slope * p.sd;
  q.d_phi = slope * p.d_phi;
  q.d_ln_ca = slope * p.d_ln_ca;
  q.d_ln_lambda = slope * p.d_ln_lambda;
  return q;
}

ViscosityPrediction OffsetFamilyModel::predict_at_offset(double phi, double capillary_number, double viscosity_ratio,
                                                         double offset) const {
  return combined(weights(offset), [&](std::size_t k) {
    return members_[k].model->predict(phi, capillary_number, viscosity_ratio);
  });
}

ViscosityPrediction OffsetFamilyModel::combined(const std::vector<double>& w,
                                                const std::function<ViscosityPrediction(std::size_t)>& member) const {
  ViscosityPrediction out;
  out.eta_re = out.sd = 0.0;
  for (std::size_t k = 0; k < members_.size(); ++k) {
    if (w[k] == 0.0) continue;
    const ViscosityPrediction p = member(k);
    out.eta_re += w[k] * p.eta_re;
    out.sd += w[k] * p.sd;
    out.d_phi += w[k] * p.d_phi;
    out.d_ln_ca += w[k] * p.d_ln_ca;
    out.d_ln_lambda += w[k] * p.d_ln_lambda;
    out.inside_hull = out.inside_hull && p.inside_hull;
  }
  out.sd = std::max(out.sd, 0.0);  // the cubic's small negative weights cannot make it negative in practice
  return out;
}

}  // namespace rbcal::surrogate
