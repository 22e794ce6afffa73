// The shipped default surrogate is what `rbcal surrogate build data/library/default` makes
// from the shipped library: it reproduces the shipped surrogate. Built with
// -march=native, a rebuild on another CPU may round differently inside the Ceres fit, so
// hyper-parameters and predictions are compared to a relative 1e-5, far below the
// surrogate's own predictive sd (about 1 %), not bit for bit.
#include <gtest/gtest.h>

#include <cmath>

#include <Eigen/Cholesky>

#include "surrogate/offset_family_file.hpp"
#include "surrogate/surrogate_file.hpp"
#include "surrogate/trend_check.hpp"

namespace rbcal::surrogate {
namespace {

const std::filesystem::path kLibrary = RBCAL_DEFAULT_LIBRARY;

TEST(ShippedSurrogate, IsRebuiltFromTheShippedLibrary) {
  const ViscositySurrogate shipped = load_surrogate(kLibrary / "surrogate.json");
  const ViscositySurrogate rebuilt = build_surrogate(kLibrary);

  ASSERT_EQ(rebuilt.training_cases().size(), shipped.training_cases().size());
  const Eigen::VectorXd a = shipped.process().hyperparameters().packed();
  const Eigen::VectorXd b = rebuilt.process().hyperparameters().packed();
  ASSERT_EQ(a.size(), b.size());
  // Packed hyper-parameters are logarithms: an absolute difference is a relative one.
  for (Eigen::Index i = 0; i < a.size(); ++i) EXPECT_NEAR(a[i], b[i], 1e-5) << "hyper-parameter " << i;

  // Predictions on a grid inside the library, including points between the training cases.
  for (double phi : {0.05, 0.15, 0.3, 0.41})
    for (double ca : {0.01, 0.03, 0.2, 0.8})
      for (double lambda : {0.1, 2.0, 10.0}) {
        const ViscosityPrediction p = shipped.predict(phi, ca, lambda);
        const ViscosityPrediction q = rebuilt.predict(phi, ca, lambda);
        EXPECT_NEAR(q.eta_re / p.eta_re, 1.0, 1e-5) << phi << " " << ca << " " << lambda;
        EXPECT_NEAR(q.sd / p.sd, 1.0, 1e-4) << phi << " " << ca << " " << lambda;
      }
}

// The physical trends asked of the default library (library v2 at its effective volume
// fractions), on the probe grid of `rbcal surrogate check` (phi 0.05-0.55, Ca 0.01-3.2, lambda
// 0.1-10): eta_re rises with phi everywhere, and falls with Ca at phi 0.41 for every lambda.
// Elsewhere at phi >= 0.21 a step along Ca may be flat but must not rise by a resolvable
// amount. At phi 0.41, Ca 0.8, lambda 5 it lies within 25 % of blood at high shear (Pries et
// al. 1992, surrogate/trend_check.hpp; docs/library.md).
TEST(ShippedSurrogate, ShowsThePhysicalTrends) {
  const ViscositySurrogate model = load_surrogate(kLibrary / "surrogate.json");
  const TrendCheck check = check_trends(model);
  EXPECT_GT(check.phi_steps, 600);
  EXPECT_LE(check.phi.front(), 0.05 + 1e-12) << "the probe grid must start at phi 0.05";
  EXPECT_LE(check.phi.back(), 0.55 + 1e-12);
  EXPECT_GE(check.phi.back(), 0.55 - 1e-12) << "the probe grid must reach phi 0.55";
  EXPECT_TRUE(check.not_rising_with_phi.empty()) << check.report();
  EXPECT_EQ(check.high_shear_phi, 0.41);
  EXPECT_EQ(check.high_shear_ca, 0.8);
  EXPECT_EQ(check.high_shear_lambda, 5.0);
  EXPECT_TRUE(check.high_shear_ok()) << check.report();
  for (const TrendViolation& v : check.not_falling_with_ca) {
    const double sd = model.predict(v.phi, v.capillary_number, v.viscosity_ratio).sd;
    EXPECT_LT(v.eta_re_next - v.eta_re_here, 0.05 * sd)
        << "phi " << v.phi << " Ca " << v.capillary_number << " lambda " << v.viscosity_ratio;
    EXPECT_NE(v.phi, 0.41);
  }
  for (double lambda : check.viscosity_ratio) {
    double previous = model.predict(0.41, check.capillary_number.front(), lambda).eta_re;
    for (std::size_t i = 1; i < check.capillary_number.size(); ++i) {
      const double here = model.predict(0.41, check.capillary_number[i], lambda).eta_re;
      EXPECT_LT(here, previous) << "phi 0.41, lambda " << lambda << ", Ca " << check.capillary_number[i];
      previous = here;
    }
  }
}

// The shipped surrogate family (the calibration's default model) holds the shipped surrogate as
// its member at the prior mean, c = 0.75 +- 0.05 lattice spacings (docs/library.md, "The effective
// volume fraction"), and its members move as a larger offset must: each run lands at a denser
// phi_eff, so eta_re at a given phi falls with c (at the acceptance point phi 0.41, Ca 0.8,
// lambda 5, and on a grid of the dense end).
TEST(ShippedSurrogateFamily, HoldsTheShippedSurrogateAndFallsWithTheOffset) {
  const OffsetFamilyModel family = load_surrogate_family(kLibrary / "surrogate_family.json");
  const ViscositySurrogate shipped = load_surrogate(kLibrary / "surrogate.json");
  const ModelNuisance& prior = family.offset_prior();
  EXPECT_DOUBLE_EQ(prior.mean, 0.75);
  EXPECT_DOUBLE_EQ(prior.sd, 0.05);
  EXPECT_LE(prior.min, prior.mean - 2.0 * prior.sd + 1e-12);
  EXPECT_GE(prior.max, prior.mean + 2.0 * prior.sd - 1e-12);
  for (double phi : {0.1, 0.3, 0.5})
    for (double ca : {0.01, 0.8, 3.2}) {
      EXPECT_NEAR(family.predict_at_offset(phi, ca, 5.0, 0.75).eta_re / shipped.predict(phi, ca, 5.0).eta_re, 1.0, 1e-12)
          << phi << " " << ca;  // the interpolation's weights at a member are exact to rounding
      double previous = 1e300;
      for (const auto& m : family.members()) {
        if (phi < 0.3) continue;
        const double eta = m.model->predict(phi, ca, 5.0).eta_re;
        EXPECT_LT(eta, previous) << "phi " << phi << ", Ca " << ca << ", offset " << m.offset;
        previous = eta;
      }
    }
}

// The likelihood of a 300-point sample (four hematocrits, shear rates 40-1000 1/s) under the
// shipped family's low-rank covariance against its exact one, with 3 % measurement errors:
// the same to 0.01 in ln L (a likelihood ratio within 1 %) at offsets in and between members.
TEST(ShippedSurrogateFamily, LowRankLikelihoodIsTheExactOne) {
  const OffsetFamilyModel family = load_surrogate_family(kLibrary / "surrogate_family.json");
  const auto log_likelihood = [](const Eigen::MatrixXd& sigma, const Eigen::VectorXd& r) {
    const Eigen::LLT<Eigen::MatrixXd> llt(sigma);
    return -0.5 * (llt.matrixL().solve(r).squaredNorm() + 2.0 * llt.matrixLLT().diagonal().array().log().sum());
  };
  const auto sample = [](int per_line) {
    std::vector<ParameterPoint> queries;
    for (const double phi : {0.25, 0.35, 0.45, 0.55})
      for (int i = 0; i < per_line; ++i) {
        const double shear_rate = 40.0 * std::pow(25.0, i / (per_line - 1.0));
        queries.push_back({phi, 1.2e-3 * shear_rate * 4e-6 / 1.3e-6, 5.0});  // Ca at G_s 1.3 uN/m
      }
    return queries;
  };
  for (const double offset : {0.75, 0.62}) {
    const std::vector<ParameterPoint> queries = sample(75);
    const JointViscosityPrediction exact = family.predict_joint(queries, {{"offset_c", offset}}, CovarianceForm::exact);
    const JointViscosityPrediction low = family.predict_joint(queries, {{"offset_c", offset}}, CovarianceForm::low_rank);
    ASSERT_TRUE(exact.covariance.dense_is_cheaper());
    ASSERT_FALSE(low.covariance.dense_is_cheaper());
    const auto n = static_cast<Eigen::Index>(queries.size());
    Eigen::VectorXd noise(n), r(n);
    for (Eigen::Index i = 0; i < n; ++i) {
      const double eta = exact.points[static_cast<std::size_t>(i)].eta_re;
      noise(i) = std::pow(0.03 * eta, 2);
      r(i) = 0.04 * eta * std::sin(0.7 * static_cast<double>(i));  // a residual pattern of the data's size
    }
    const Eigen::MatrixXd e = exact.covariance.dense() + Eigen::MatrixXd(noise.asDiagonal());
    const Eigen::MatrixXd l = low.covariance.dense() + Eigen::MatrixXd(noise.asDiagonal());
    EXPECT_NEAR(log_likelihood(l, r), log_likelihood(e, r), 0.01) << "offset " << offset;
    // Its rank is set by the span of the points in length scales: twice the points, hardly more.
    const Eigen::Index rank_twice = family.predict_joint(sample(150), {{"offset_c", offset}}, CovarianceForm::low_rank).covariance.rank();
    EXPECT_LE(rank_twice, low.covariance.rank() + low.covariance.rank() / 10) << "offset " << offset;
  }
}

}  // namespace
}  // namespace rbcal::surrogate
