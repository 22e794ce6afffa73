// The offset family (surrogate/offset_family.hpp): members at equally spaced offsets of the
// immersed boundary joined by a C1 cubic in c; its file (offset_family_file.hpp) and the
// loader that tells a family from a single surrogate.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <memory>
#include <stdexcept>

#include "formats/json_file.hpp"
#include "surrogate/offset_family.hpp"
#include "surrogate/offset_family_file.hpp"
#include "surrogate/surrogate_file.hpp"
#include "synthetic_library.hpp"

using namespace rbcal::surrogate;

namespace {

// A member whose prediction is a known function of its offset: eta_re = f(phi, Ca) + g(c).
class KnownMember final : public PointwiseViscosityModel {
 public:
  KnownMember(double offset, double (*g)(double), ParameterRange box = {0.02, 0.6, 0.01, 3.2, 0.1, 10.0})
      : offset_(offset), g_(g), box_(box) {}
  ViscosityPrediction predict_point(double phi, double ca, double lambda, const NuisanceValues&) const override {
    ViscosityPrediction p;
    p.eta_re = 1.0 + 2.0 * phi - 0.1 * std::log(ca) + 0.01 * lambda + g_(offset_);
    p.sd = 0.01 + 0.02 * g_(offset_) * g_(offset_);
    p.d_phi = 2.0;
    p.d_ln_ca = -0.1;
    p.d_ln_lambda = 0.01 * lambda;
    return p;
  }
  ParameterRange range() const override { return box_; }

 private:
  double offset_;
  double (*g_)(double);
  ParameterRange box_;
};

// A member whose errors are correlated in phi, with a correlation length that grows with its
// offset: corr = exp(-|phi_i - phi_j| / (0.1 + 0.2 c)).
class CorrelatedMember final : public ViscosityModel {
 public:
  explicit CorrelatedMember(double offset) : offset_(offset) {}
  ViscosityPrediction point(double phi, double ca, double lambda) const {
    ViscosityPrediction p;
    p.eta_re = std::exp(4.0 * phi * (1.0 + 0.2 * offset_)) * (1.0 - 0.05 * std::log(ca)) + 0.0 * lambda;
    p.sd = 0.02 * p.eta_re * (1.0 + offset_);
    p.d_ln_ca = -0.05 * std::exp(4.0 * phi * (1.0 + 0.2 * offset_));
    return p;
  }
  JointViscosityPrediction joint_prediction(const std::vector<ParameterPoint>& q, const NuisanceValues& /*nuisance*/,
                                            CovarianceForm form) const override {
    JointViscosityPrediction out;
    const auto n = static_cast<Eigen::Index>(q.size());
    for (const auto& x : q) out.points.push_back(point(x.phi, x.capillary_number, x.viscosity_ratio));
    if (form == CovarianceForm::none) return without_correlation(std::move(out.points));
    out.covariance.full.resize(n, n);
    for (Eigen::Index i = 0; i < n; ++i)
      for (Eigen::Index j = 0; j < n; ++j)
        out.covariance.full(i, j) = out.points[i].sd * out.points[j].sd * correlation(q[i].phi, q[j].phi);
    return out;
  }
  double correlation(double a, double b) const { return std::exp(-std::abs(a - b) / (0.1 + 0.2 * offset_)); }
  ParameterRange range() const override { return {0.02, 0.6, 0.01, 3.2, 0.1, 10.0}; }

 private:
  double offset_;
};

double linear(double c) { return 0.8 - 0.6 * c; }
double curved(double c) { return std::sin(3.0 * c); }

OffsetFamilyModel family_of(double (*g)(double), std::vector<double> offsets, double mean = 0.75, double sd = 0.15) {
  std::vector<OffsetFamilyMember> members;
  for (double c : offsets) members.push_back({c, std::make_shared<KnownMember>(c, g)});
  return OffsetFamilyModel(std::move(members), mean, sd);
}

}  // namespace

TEST(OffsetFamily, ReproducesEveryMemberAtItsOffset) {
  const OffsetFamilyModel f = family_of(curved, {0.45, 0.6, 0.75, 0.9, 1.05});
  for (const auto& m : f.members()) {
    const ViscosityPrediction expected = m.model->predict(0.3, 0.5, 5.0);
    const ViscosityPrediction got = f.predict_at_offset(0.3, 0.5, 5.0, m.offset);
    EXPECT_NEAR(got.eta_re, expected.eta_re, 1e-13) << "c " << m.offset;
    EXPECT_NEAR(got.sd, expected.sd, 1e-13) << "c " << m.offset;
  }
  // Without an offset it predicts at the prior mean (a member here).
  EXPECT_NEAR(f.predict(0.3, 0.5, 5.0).eta_re, f.members()[2].model->predict(0.3, 0.5, 5.0).eta_re, 1e-13);
  const std::vector<ModelNuisance> nuisances = f.nuisances();
  ASSERT_EQ(nuisances.size(), 1u);  // no box correction given
  EXPECT_EQ(nuisances[0].name, "offset_c");
  EXPECT_DOUBLE_EQ(nuisances[0].min, 0.45);
  EXPECT_DOUBLE_EQ(nuisances[0].max, 1.05);
  EXPECT_EQ(f.predict(0.3, 0.5, 5.0, {{"offset_c", 0.9}}).eta_re, f.predict_at_offset(0.3, 0.5, 5.0, 0.9).eta_re);
  EXPECT_THROW(f.predict(0.3, 0.5, 5.0, {{"offset_c", 0.9}, {"box", 0.1}}), std::invalid_argument);
}

TEST(OffsetFamily, IsExactForPredictionsLinearInTheOffset) {
  const OffsetFamilyModel f = family_of(linear, {0.45, 0.6, 0.75, 0.9, 1.05});
  for (double c = 0.45; c <= 1.05 + 1e-12; c += 0.0137) {
    EXPECT_NEAR(f.predict_at_offset(0.3, 0.5, 5.0, c).eta_re, KnownMember(c, linear).predict(0.3, 0.5, 5.0).eta_re,
                1e-12)
        << "c " << c;
    double sum = 0.0;
    for (double w : f.weights(c)) sum += w;
    EXPECT_NEAR(sum, 1.0, 1e-14) << "c " << c;
  }
}

// Catmull-Rom: the slope is continuous at the members, and a smooth g is followed to O(h^3).
TEST(OffsetFamily, IsSmoothInTheOffsetAndConvergesToASmoothDependence) {
  const OffsetFamilyModel f = family_of(curved, {0.45, 0.6, 0.75, 0.9, 1.05});
  const double eps = 1e-7;
  for (double c : {0.6, 0.75, 0.9}) {
    const double left = (f.predict_at_offset(0.3, 0.5, 5.0, c).eta_re -
                         f.predict_at_offset(0.3, 0.5, 5.0, c - eps).eta_re) / eps;
    const double right = (f.predict_at_offset(0.3, 0.5, 5.0, c + eps).eta_re -
                          f.predict_at_offset(0.3, 0.5, 5.0, c).eta_re) / eps;
    EXPECT_NEAR(left, right, 1e-5) << "slope jumps at member c " << c;
  }
  // Halving the spacing cuts the largest error between interior members by about 8.
  auto worst_interior_error = [](const OffsetFamilyModel& fam, double lo, double hi) {
    double worst = 0.0;
    for (double c = lo; c <= hi; c += 0.001)
      worst = std::max(worst, std::abs(fam.predict_at_offset(0.3, 0.5, 5.0, c).eta_re -
                                       KnownMember(c, curved).predict(0.3, 0.5, 5.0).eta_re));
    return worst;
  };
  const double coarse = worst_interior_error(f, 0.6, 0.9);
  const double fine = worst_interior_error(family_of(curved, {0.45, 0.525, 0.6, 0.675, 0.75, 0.825, 0.9, 0.975, 1.05}),
                                           0.6, 0.9);
  EXPECT_GT(coarse / fine, 5.0) << coarse << " " << fine;
  EXPECT_LT(coarse, 2e-3);
}

// ln eta -> (1 + beta) ln eta: eta^(1 + beta), and sd and derivatives by the chain rule
// (checked against a finite difference of the transform).
TEST(OffsetFamily, BoxCorrectionCarriesSdAndDerivativesByTheChainRule) {
  ViscosityPrediction p;
  p.eta_re = 3.0;
  p.sd = 0.1;
  p.d_phi = 7.0;
  p.d_ln_ca = -0.4;
  p.d_ln_lambda = 0.2;
  const double beta = 0.12, h = 1e-6;
  const ViscosityPrediction q = with_box_correction(p, beta);
  EXPECT_NEAR(q.eta_re, std::pow(3.0, 1.12), 1e-12);
  const double slope = (std::pow(3.0 + h, 1.12) - std::pow(3.0 - h, 1.12)) / (2.0 * h);
  EXPECT_NEAR(q.sd, slope * 0.1, 1e-8);
  EXPECT_NEAR(q.d_phi, slope * 7.0, 1e-7);
  EXPECT_NEAR(q.d_ln_ca, slope * -0.4, 1e-8);
  EXPECT_NEAR(q.d_ln_lambda, slope * 0.2, 1e-8);
  EXPECT_EQ(with_box_correction(p, 0.0).eta_re, 3.0);
}

// The batched predictions (predict_many, used by the predictive check and bands) are the
// point-by-point ones, box correction included, at the prior mean and elsewhere.
TEST(OffsetFamily, BatchedPredictionsArePointByPointOnes) {
  std::vector<OffsetFamilyMember> members;
  for (double c : {0.45, 0.6, 0.75, 0.9, 1.05}) members.push_back({c, std::make_shared<KnownMember>(c, curved)});
  const OffsetFamilyModel f(members, 0.75, 0.15, BoxCorrectionPrior{0.1, 0.07});
  const std::vector<ParameterPoint> q = {{0.1, 0.1, 5.0}, {0.25, 0.5, 2.0}, {0.45, 2.0, 8.0}};
  for (double c : {0.5, 0.75, 0.97}) {
    const std::vector<ViscosityPrediction> many = f.predict_many(q, {{"offset_c", c}});
    ASSERT_EQ(many.size(), q.size());
    for (std::size_t i = 0; i < q.size(); ++i) {
      const ViscosityPrediction one = f.predict(q[i].phi, q[i].capillary_number, q[i].viscosity_ratio, {{"offset_c", c}});
      EXPECT_DOUBLE_EQ(many[i].eta_re, one.eta_re) << c << " " << i;
      EXPECT_DOUBLE_EQ(many[i].sd, one.sd);
      EXPECT_DOUBLE_EQ(many[i].d_ln_ca, one.d_ln_ca);
    }
  }
  const std::vector<ViscosityPrediction> at_mean = f.predict_many(q);
  for (std::size_t i = 0; i < q.size(); ++i)
    EXPECT_DOUBLE_EQ(at_mean[i].eta_re, f.predict(q[i].phi, q[i].capillary_number, q[i].viscosity_ratio).eta_re);
  // The offset is its only nuisance.
  EXPECT_THROW(f.predict_many(q, {{"offset_c", 0.6}, {"box", 0.1}}), std::invalid_argument);
}

// The joint covariance: each point's sd as predict gives it, correlated as the bracketing
// members correlate (weighted linearly in c), plus the box correction's error sd_beta^2 g g^T with
// g_i = eta_i ln eta_plain_i, common to every point.
TEST(OffsetFamily, JointCovarianceCorrelatesAsItsMembersAndCarriesTheBoxToEveryPoint) {
  std::vector<OffsetFamilyMember> members;
  std::vector<std::shared_ptr<const CorrelatedMember>> known;
  for (double c : {0.5, 0.75, 1.0}) {
    known.push_back(std::make_shared<CorrelatedMember>(c));
    members.push_back({c, known.back()});
  }
  const std::vector<ParameterPoint> q = {{0.1, 0.1, 5.0}, {0.2, 0.5, 5.0}, {0.4, 2.0, 5.0}};
  const OffsetFamilyModel plain(members, 0.75, 0.15);
  const BoxCorrectionPrior box{0.1, 0.07};
  const OffsetFamilyModel boxed(members, 0.75, 0.15, box);
  for (double c : {0.75, 0.6}) {
    const double t = c == 0.75 ? 0.0 : 0.4;  // 0.6 lies 40 % of the way from 0.5 to 0.75
    const std::size_t lower = c == 0.75 ? 1 : 0;
    const Eigen::MatrixXd p_covariance = plain.predict_joint(q, {{"offset_c", c}}).covariance.dense();
    const Eigen::MatrixXd b_covariance = boxed.predict_joint(q, {{"offset_c", c}}).covariance.dense();
    const JointViscosityPrediction p = plain.predict_joint(q, {{"offset_c", c}});
    for (std::size_t i = 0; i < q.size(); ++i) {
      const ViscosityPrediction single = plain.predict(q[i].phi, q[i].capillary_number, 5.0, {{"offset_c", c}});
      const ViscosityPrediction single_boxed = boxed.predict(q[i].phi, q[i].capillary_number, 5.0, {{"offset_c", c}});
      EXPECT_EQ(p.points[i].eta_re, single.eta_re);
      EXPECT_NEAR(p_covariance(i, i), single.sd * single.sd, 1e-15);
      EXPECT_NEAR(b_covariance(i, i), single_boxed.sd * single_boxed.sd, 1e-13);  // the diagonal is predict's sd^2
      for (std::size_t j = 0; j < q.size(); ++j) {
        const double r = (1.0 - t) * known[lower]->correlation(q[i].phi, q[j].phi) +
                         t * known[lower + 1]->correlation(q[i].phi, q[j].phi);
        const double sd_i = std::sqrt(p_covariance(i, i)), sd_j = std::sqrt(p_covariance(j, j));
        EXPECT_NEAR(p_covariance(i, j), sd_i * sd_j * r, 1e-14) << c << " " << i << " " << j;
        // Boxed: the chain rule scales each sd by (1 + beta) eta^beta, beta's error adds g g^T.
        const double eta_i = p.points[i].eta_re, eta_j = p.points[j].eta_re;
        const double slope_i = 1.1 * std::pow(eta_i, 0.1), slope_j = 1.1 * std::pow(eta_j, 0.1);
        const double g_i = std::pow(eta_i, 1.1) * std::log(eta_i), g_j = std::pow(eta_j, 1.1) * std::log(eta_j);
        EXPECT_NEAR(b_covariance(i, j), slope_i * slope_j * p_covariance(i, j) + 0.07 * 0.07 * g_i * g_j, 1e-12);
      }
    }
  }
}

// A box step that depends on Ca: beta(Ca) = mean below the knee, mean + slope ln(Ca / knee)
// above it; d eta / d ln Ca carries the step's own Ca dependence; the slope's sd adds
// slope_sd^2 h h^T with h_i = g_i ln(Ca_i / knee), nothing for points below the knee.
TEST(OffsetFamily, BoxStepThatDependsOnCa) {
  std::vector<OffsetFamilyMember> members;
  for (double c : {0.5, 0.75, 1.0}) members.push_back({c, std::make_shared<CorrelatedMember>(c)});
  BoxCorrectionPrior box{0.09, 0.03};
  box.ca_knee = 1.0;
  box.ca_slope = -0.1;
  box.ca_slope_sd = 0.04;
  const OffsetFamilyModel plain(members, 0.75, 0.15);
  const OffsetFamilyModel stepped(members, 0.75, 0.15, box);
  const OffsetFamilyModel level(members, 0.75, 0.15, BoxCorrectionPrior{0.09, 0.03});
  // Below the knee: the one-step model exactly.
  const ViscosityPrediction low = stepped.predict(0.3, 0.5, 5.0), low_level = level.predict(0.3, 0.5, 5.0);
  EXPECT_EQ(low.eta_re, low_level.eta_re);
  EXPECT_EQ(low.sd, low_level.sd);
  EXPECT_EQ(low.d_ln_ca, low_level.d_ln_ca);
  // Above it: the step at beta(8) = 0.09 - 0.1 ln 8.
  const ViscosityPrediction raw = plain.predict(0.3, 8.0, 5.0), high = stepped.predict(0.3, 8.0, 5.0);
  const double beta8 = 0.09 - 0.1 * std::log(8.0);
  EXPECT_NEAR(high.eta_re, std::pow(raw.eta_re, 1.0 + beta8), 1e-13);
  const double g = high.eta_re * std::log(raw.eta_re), h = g * std::log(8.0);
  const double sd_without = (1.0 + beta8) * std::pow(raw.eta_re, beta8) * raw.sd;
  EXPECT_NEAR(high.sd, std::sqrt(sd_without * sd_without + 0.03 * 0.03 * g * g + 0.04 * 0.04 * h * h), 1e-13);
  // d eta / d ln Ca against a central difference of the prediction, across the members' own
  // Ca dependence and the step's.
  const double e = 1e-5;
  const double numeric =
      (stepped.predict(0.3, 8.0 * std::exp(e), 5.0).eta_re - stepped.predict(0.3, 8.0 * std::exp(-e), 5.0).eta_re) / (2 * e);
  EXPECT_NEAR(high.d_ln_ca, numeric, 1e-7);
  EXPECT_LT(high.d_ln_ca, (1.0 + beta8) * std::pow(raw.eta_re, beta8) * raw.d_ln_ca);  // the step thins it further
  // The joint covariance: the slope's share only between points above the knee.
  const std::vector<ParameterPoint> q = {{0.2, 0.5, 5.0}, {0.3, 4.0, 5.0}, {0.4, 8.0, 5.0}};
  const Eigen::MatrixXd with_slope = stepped.predict_joint(q).covariance.dense();
  BoxCorrectionPrior exact_slope = box;
  exact_slope.ca_slope_sd = 0.0;
  const Eigen::MatrixXd without_slope = OffsetFamilyModel(members, 0.75, 0.15, exact_slope).predict_joint(q).covariance.dense();
  const JointViscosityPrediction at = stepped.predict_joint(q), raw_at = plain.predict_joint(q);
  for (std::size_t i = 0; i < q.size(); ++i) {
    EXPECT_NEAR(with_slope(i, i), at.points[i].sd * at.points[i].sd, 1e-13);
    for (std::size_t j = 0; j < q.size(); ++j) {
      const auto lever = [&](std::size_t k) { return std::max(0.0, std::log(q[k].capillary_number)); };
      const double h_i = at.points[i].eta_re * std::log(raw_at.points[i].eta_re) * lever(i);
      const double h_j = at.points[j].eta_re * std::log(raw_at.points[j].eta_re) * lever(j);
      EXPECT_NEAR(with_slope(i, j) - without_slope(i, j), 0.04 * 0.04 * h_i * h_j, 1e-13) << i << " " << j;
    }
  }
  EXPECT_EQ(with_slope(0, 2), without_slope(0, 2));  // the point below the knee shares no slope error
  // A slope without a knee is refused.
  BoxCorrectionPrior no_knee{0.09, 0.03};
  no_knee.ca_slope = -0.1;
  EXPECT_THROW(OffsetFamilyModel(members, 0.75, 0.15, no_knee), std::invalid_argument);
}

// The one range rule: bounds included, each axis on its own, NaN outside.
TEST(ParameterRange, ContainsItsBoundsAndNothingBeyond) {
  const ParameterRange r{0.05, 0.62, 0.01, 3.2, 0.1, 10.0};
  EXPECT_TRUE(r.contains(0.05, 0.01, 0.1));
  EXPECT_TRUE(r.contains(0.62, 3.2, 10.0));
  EXPECT_FALSE(r.contains(0.621, 1.0, 5.0));
  EXPECT_FALSE(r.contains(0.3, 3.3, 5.0));
  EXPECT_FALSE(r.contains(0.3, 1.0, 0.09));
  EXPECT_TRUE(r.contains_phi(0.3) && !r.contains_phi(0.04));
  EXPECT_TRUE(r.contains_ca(0.5) && !r.contains_ca(0.009));
  EXPECT_TRUE(r.contains_lambda(5.0) && !r.contains_lambda(10.5));
  EXPECT_FALSE(r.contains(std::nan(""), 1.0, 5.0));
}

TEST(OffsetFamily, RangeIsTheMembersCommonRange) {
  std::vector<OffsetFamilyMember> members;
  members.push_back({0.6, std::make_shared<KnownMember>(0.6, linear, ParameterRange{0.05, 0.62, 0.01, 3.2, 0.1, 10.0})});
  members.push_back({0.9, std::make_shared<KnownMember>(0.9, linear, ParameterRange{0.06, 0.6, 0.02, 4.0, 0.2, 8.0})});
  const ParameterRange r = OffsetFamilyModel(std::move(members), 0.75, 0.15).range();
  EXPECT_DOUBLE_EQ(r.phi_min, 0.06);
  EXPECT_DOUBLE_EQ(r.phi_max, 0.6);
  EXPECT_DOUBLE_EQ(r.ca_min, 0.02);
  EXPECT_DOUBLE_EQ(r.ca_max, 3.2);
  EXPECT_DOUBLE_EQ(r.lambda_min, 0.2);
  EXPECT_DOUBLE_EQ(r.lambda_max, 8.0);
}

TEST(OffsetFamily, RefusesWhatItCannotInterpolate) {
  EXPECT_THROW(family_of(linear, {0.75}), std::invalid_argument);                  // one member
  EXPECT_THROW(family_of(linear, {0.6, 0.75, 0.95}), std::invalid_argument);       // unequal spacing
  EXPECT_THROW(family_of(linear, {0.9, 0.75, 0.6}), std::invalid_argument);        // decreasing
  EXPECT_THROW(family_of(linear, {0.6, 0.6}), std::invalid_argument);              // repeated
  EXPECT_THROW(family_of(linear, {0.6, 0.75, 0.9}, 1.2), std::invalid_argument);   // prior mean outside
  EXPECT_THROW(family_of(linear, {0.6, 0.75, 0.9}, 0.75, 0.0), std::invalid_argument);  // sd 0
  auto inner = std::make_shared<OffsetFamilyModel>(family_of(linear, {0.6, 0.9}));
  EXPECT_THROW(OffsetFamilyModel({{0.6, inner}, {0.9, inner}}, 0.75, 0.15), std::invalid_argument);  // nested
}

TEST(OffsetFamilyFile, RoundTripsAndIsToldFromASingleSurrogate) {
  const auto dir = rbcal::surrogate::testing::fresh_temp_folder("offset_family_file");
  std::vector<SurrogateFamilyMember> members;
  for (unsigned k = 0; k < 3; ++k)
    members.push_back({0.6 + 0.15 * k, ViscositySurrogate::fit(rbcal::surrogate::testing::synthetic_training_cases({}, 7 + k))});
  save_surrogate_family(members, 0.75, 0.15, dir / "family.json");
  save_surrogate(members[0].surrogate, dir / "single.json");

  const OffsetFamilyModel loaded = load_surrogate_family(dir / "family.json");
  ASSERT_EQ(loaded.members().size(), 3u);
  for (std::size_t k = 0; k < 3; ++k) {
    EXPECT_DOUBLE_EQ(loaded.members()[k].offset, members[k].offset);
    EXPECT_EQ(loaded.predict_at_offset(0.25, 0.2, 5.0, members[k].offset).eta_re,
              members[k].surrogate.predict(0.25, 0.2, 5.0).eta_re);  // bit-identical, as a single surrogate
  }
  const auto any_family = load_viscosity_model(dir / "family.json");
  ASSERT_EQ(any_family->nuisances().size(), 1u);
  EXPECT_DOUBLE_EQ(any_family->nuisances()[0].sd, 0.15);
  EXPECT_TRUE(load_viscosity_model(dir / "single.json")->nuisances().empty());

  // With a box correction: kept with its source; integrated out, not a second nuisance.
  save_surrogate_family(members, 0.75, 0.15, dir / "boxed.json", BoxCorrectionRecord{{0.05, 0.04}, "twin runs"});
  const OffsetFamilyModel boxed = load_surrogate_family(dir / "boxed.json");
  ASSERT_EQ(boxed.nuisances().size(), 1u);
  ASSERT_TRUE(boxed.box_correction());
  EXPECT_DOUBLE_EQ(boxed.box_correction()->mean, 0.05);
  EXPECT_DOUBLE_EQ(boxed.box_correction()->sd, 0.04);
  EXPECT_EQ(rbcal::formats::read_json_file(dir / "boxed.json")["box_correction"]["source"], "twin runs");
  const ViscosityPrediction plain = loaded.predict_at_offset(0.25, 0.2, 5.0, 0.75);
  const ViscosityPrediction at_mean = boxed.predict(0.25, 0.2, 5.0);
  EXPECT_NEAR(at_mean.eta_re, std::pow(plain.eta_re, 1.05), 1e-12);  // at beta's mean
  // sd: the chain rule's, and beta's own share sd_beta eta ln eta_plain, in quadrature.
  EXPECT_NEAR(at_mean.sd,
              std::hypot(1.05 * at_mean.eta_re / plain.eta_re * plain.sd, 0.04 * at_mean.eta_re * std::log(plain.eta_re)),
              1e-12);
  EXPECT_EQ(boxed.predict(0.25, 0.2, 5.0, {{"offset_c", 0.6}}).eta_re,
            boxed.predict_joint({{0.25, 0.2, 5.0}}, {{"offset_c", 0.6}}).points[0].eta_re);

  // A box step that depends on Ca is kept with its knee and slope.
  BoxCorrectionRecord stepped{{0.09, 0.03}, "twins at Ca 0.1-8"};
  stepped.prior.ca_knee = 1.0;
  stepped.prior.ca_slope = -0.1;
  stepped.prior.ca_slope_sd = 0.04;
  save_surrogate_family(members, 0.75, 0.15, dir / "stepped.json", stepped);
  const OffsetFamilyModel stepped_back = load_surrogate_family(dir / "stepped.json");
  ASSERT_TRUE(stepped_back.box_correction());
  EXPECT_DOUBLE_EQ(stepped_back.box_correction()->ca_knee, 1.0);
  EXPECT_DOUBLE_EQ(stepped_back.box_correction()->ca_slope, -0.1);
  EXPECT_DOUBLE_EQ(stepped_back.box_correction()->ca_slope_sd, 0.04);
  EXPECT_FALSE(rbcal::formats::read_json_file(dir / "boxed.json")["box_correction"].contains("ca_knee"));

  // A bad field inside a member is named with the member's path.
  nlohmann::json j = rbcal::formats::read_json_file(dir / "family.json");
  j["members"][1]["surrogate"]["training"][2]["noise_variance"] = -1.0;
  std::ofstream(dir / "bad.json") << j.dump();
  try {
    load_viscosity_model(dir / "bad.json");
    FAIL() << "a negative noise variance was accepted";
  } catch (const std::invalid_argument& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("bad.json (members.1.surrogate)"), std::string::npos) << what;
    EXPECT_NE(what.find("training.2.noise_variance"), std::string::npos) << what;
  }
  // A misspelt key is refused, not read as a family without a box correction.
  nlohmann::json misspelt = rbcal::formats::read_json_file(dir / "boxed.json");
  misspelt["box_corection"] = misspelt["box_correction"];
  misspelt.erase("box_correction");
  std::ofstream(dir / "misspelt.json") << misspelt.dump();
  try {
    load_viscosity_model(dir / "misspelt.json");
    FAIL() << "a misspelt box_correction was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("box_corection: unknown field"), std::string::npos) << e.what();
  }
  // Unequal spacing is refused before anything is written.
  members[2].offset = 1.2;
  EXPECT_THROW(save_surrogate_family(members, 0.75, 0.15, dir / "unequal.json"), std::invalid_argument);
  EXPECT_FALSE(std::filesystem::exists(dir / "unequal.json"));
}

// A family with its offset held (rbcal calibrate --hold offset_c=C): no nuisance left to fit,
// and every prediction, joint ones included, is the family's at C.
#include "surrogate/fixed_nuisance_model.hpp"

TEST(FixedNuisance, HoldsTheOffsetWhereItIsGiven) {
  const OffsetFamilyModel f = family_of(curved, {0.45, 0.6, 0.75, 0.9, 1.05});
  const FixedNuisanceModel held(f, "offset_c", 0.6);
  EXPECT_TRUE(held.nuisances().empty());
  EXPECT_EQ(held.predict(0.3, 0.5, 5.0).eta_re, f.predict_at_offset(0.3, 0.5, 5.0, 0.6).eta_re);
  EXPECT_EQ(held.predict(0.3, 0.5, 5.0).eta_re, f.predict_at_offset(0.3, 0.5, 5.0, 0.6).eta_re);
  const std::vector<ParameterPoint> q = {{0.2, 0.5, 5.0}, {0.3, 0.5, 5.0}};
  const JointViscosityPrediction a = held.predict_joint(q, {}), b = f.predict_joint(q, {{"offset_c", 0.6}});
  EXPECT_EQ(a.points[1].eta_re, b.points[1].eta_re);
  EXPECT_EQ(a.covariance.dense()(0, 1), b.covariance.dense()(0, 1));
  EXPECT_EQ(held.predict_many(q)[1].eta_re, f.predict_at_offset(0.3, 0.5, 5.0, 0.6).eta_re);
  EXPECT_EQ(held.predict_many(q)[0].eta_re, f.predict_at_offset(0.2, 0.5, 5.0, 0.6).eta_re);
  EXPECT_THROW(FixedNuisanceModel(f, "offset_c", 1.2), std::invalid_argument);  // outside 0.45 .. 1.05
  EXPECT_THROW(FixedNuisanceModel(f, "beta", 0.1), std::invalid_argument);      // no such nuisance here
}

namespace rbcal::surrogate {
namespace {

// The offset a model file records: a family's prior mean with its recipe's slope, a
// surrogate's recipe offset; nothing when neither is recorded.
TEST(RecordedOffset, FromTheFamilysPriorAndTheRecipesSlope) {
  nlohmann::json family = {{"schema", "rbcal.surrogate_family/1"},
                           {"prior", {{"mean", 0.652}, {"sd", 0.04}}},
                           {"provenance", {{"recipe", {{"mapping", {{"offset", 0.652}, {"offset_slope", 1.1}}}}}}}};
  const auto f = recorded_offset(family);
  ASSERT_TRUE(f.has_value());
  EXPECT_DOUBLE_EQ(f->at(8), 0.652);
  EXPECT_NEAR(f->at(12), 0.652 + 1.1 * (1.0 / 12.0 - 1.0 / 8.0), 1e-15);  // 0.606
  family["provenance"] = nlohmann::json::object();
  EXPECT_DOUBLE_EQ(recorded_offset(family)->at(12), 0.652);  // no recipe: slope 0
  const nlohmann::json surrogate = {{"schema", "rbcal.surrogate/1"},
                                    {"provenance", {{"recipe", {{"mapping", {{"offset", 0.75}}}}}}}};
  EXPECT_DOUBLE_EQ(recorded_offset(surrogate)->at(6), 0.75);
  EXPECT_FALSE(recorded_offset(nlohmann::json{{"schema", "rbcal.surrogate/1"}}).has_value());
}

}  // namespace
}  // namespace rbcal::surrogate
