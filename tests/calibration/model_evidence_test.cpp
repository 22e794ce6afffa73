// The evidence on a conjugate Gaussian model, where it is known exactly: theta ~ N(0, tau^2 I)
// in d dimensions, y_i ~ N(A_i theta, sigma^2), so that y ~ N(0, sigma^2 I + tau^2 A A^T).
// Laplace is exact for this Gaussian posterior; importance sampling must agree within its
// Monte Carlo error.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "calibration/mcmc_sampling.hpp"
#include "calibration/model_evidence.hpp"

using namespace rbcal::calibration;

namespace {

// theta ~ N(0, tau^2 I) in d = 3 dimensions, 12 observations y = A theta + N(0, sigma^2).
struct ConjugateGaussianModel {
  static constexpr int d = 3, m = 12;
  double tau = 2.0, sigma = 0.3;
  Eigen::MatrixXd A;
  Eigen::VectorXd y;
  Eigen::VectorXd mu;     // posterior mean
  Eigen::MatrixXd Sigma;  // posterior covariance
  double exact = 0.0;     // ln Z

  ConjugateGaussianModel() {
    std::mt19937_64 rng(5);
    std::normal_distribution<double> normal;
    A.resize(m, d);
    for (int i = 0; i < m; ++i)
      for (int j = 0; j < d; ++j) A(i, j) = normal(rng);
    Eigen::VectorXd truth(d);
    truth << 0.5, -1.0, 1.5;
    y = A * truth;
    for (int i = 0; i < m; ++i) y(i) += sigma * normal(rng);
    // Exact: ln N(y; 0, sigma^2 I + tau^2 A A^T).
    const Eigen::MatrixXd C = sigma * sigma * Eigen::MatrixXd::Identity(m, m) + tau * tau * A * A.transpose();
    const Eigen::LLT<Eigen::MatrixXd> llt(C);
    const Eigen::MatrixXd L = llt.matrixL();
    exact = -0.5 * y.dot(llt.solve(y)) - L.diagonal().array().log().sum() - 0.5 * m * std::log(2.0 * std::numbers::pi);
    const Eigen::MatrixXd precision = A.transpose() * A / (sigma * sigma) + Eigen::MatrixXd::Identity(d, d) / (tau * tau);
    Sigma = precision.inverse();
    mu = Sigma * A.transpose() * y / (sigma * sigma);
  }

  double log_density(const Eigen::VectorXd& theta) const {
    const double ln_2pi = std::log(2.0 * std::numbers::pi);
    const double prior = -0.5 * theta.squaredNorm() / (tau * tau) - d * std::log(tau) - 0.5 * d * ln_2pi;
    const double like = -0.5 * (y - A * theta).squaredNorm() / (sigma * sigma) - m * std::log(sigma) - 0.5 * m * ln_2pi;
    return prior + like;
  }

  // Posterior draws (what an MCMC would give): N(mu, Sigma).
  Eigen::MatrixXd draws(int count) const {
    std::mt19937_64 rng(11);
    std::normal_distribution<double> normal;
    const Eigen::MatrixXd S = Sigma.llt().matrixL();
    Eigen::MatrixXd out(count, d);
    for (int k = 0; k < count; ++k) {
      Eigen::VectorXd z(d);
      for (int j = 0; j < d; ++j) z(j) = normal(rng);
      out.row(k) = (mu + S * z).transpose();
    }
    return out;
  }
};

}  // namespace

TEST(ModelEvidence, ExactOnAConjugateGaussianModel) {
  const ConjugateGaussianModel model;
  const LogDensityFunction log_density = [&](const Eigen::VectorXd& theta) { return model.log_density(theta); };
  const int d = ConjugateGaussianModel::d;
  const Eigen::MatrixXd draws = model.draws(4000);
  const ModelEvidence e = model_evidence(log_density, draws);
  ASSERT_TRUE(e.laplace_ok);
  EXPECT_NEAR(e.laplace, model.exact, 1e-5) << e.line();
  EXPECT_NEAR(e.importance, model.exact, std::max(4.0 * e.importance_error, 1e-3)) << e.line();
  // Drawn in batches of 500 until the Monte Carlo error is below the target (0.03).
  EXPECT_LT(e.importance_error, 0.03);
  EXPECT_LT(e.samples, 4000);
  EXPECT_EQ(e.samples % 500, 0);
  // A model that explains the data worse (a prior far off the truth) has a smaller evidence.
  const LogDensityFunction shifted = [&](const Eigen::VectorXd& theta) {
    return log_density(theta) - 0.5 * (theta - Eigen::VectorXd::Constant(d, 5.0)).squaredNorm() +
           0.5 * theta.squaredNorm() / (model.tau * model.tau) + d * std::log(model.tau);
  };
  EXPECT_LT(model_evidence(shifted, draws).laplace, e.laplace);
}

TEST(ModelEvidence, TargetZeroDrawsTheWholeImportanceSample) {
  const ConjugateGaussianModel model;
  ModelEvidenceOptions all;
  all.importance_target_error = 0.0;
  all.threads = 2;
  const ModelEvidence e =
      model_evidence([&](const Eigen::VectorXd& theta) { return model.log_density(theta); }, model.draws(4000), all);
  EXPECT_EQ(e.samples, 4000);
  EXPECT_GT(e.effective_samples, 1000.0);
  EXPECT_NEAR(e.importance, model.exact, std::max(4.0 * e.importance_error, 1e-3)) << e.line();
  ModelEvidenceOptions one_thread = all;
  one_thread.threads = 1;
  EXPECT_EQ(model_evidence([&](const Eigen::VectorXd& theta) { return model.log_density(theta); }, model.draws(4000),
                           one_thread)
                .importance,
            e.importance);  // the same draws for any number of threads
}

// The independence sampler's proposals are an importance sample of the evidence: from them,
// with the draws' own log densities for the mode, no evaluation beyond the Laplace refinement.
TEST(ModelEvidence, FromTheIndependenceSamplersProposals) {
  const ConjugateGaussianModel model;
  const LogDensityFunction log_density = [&](const Eigen::VectorXd& theta) { return model.log_density(theta); };
  McmcOptions o;
  o.sampler = SamplerKind::Independence;
  o.seed = 17;
  const McmcResult r = sample_posterior(log_density, {"a", "b", "c"},
                                        {model.mu, model.Sigma.diagonal().cwiseSqrt(), model.Sigma}, o);
  ASSERT_TRUE(r.converged) << r.stop_reason;
  ASSERT_FALSE(r.proposal_log_weights.empty());
  long long evaluations = 0;
  const LogDensityFunction counted = [&](const Eigen::VectorXd& theta) {
#pragma omp atomic
    ++evaluations;
    return model.log_density(theta);
  };
  const ModelEvidence e =
      model_evidence(counted, r.draws(), {}, {r.draw_log_densities(), r.proposal_log_weights, "the proposals"});
  EXPECT_EQ(e.samples, static_cast<int>(r.proposal_log_weights.size()));
  EXPECT_NEAR(e.importance, model.exact, 4.0 * e.importance_error) << e.line();
  EXPECT_LT(e.importance_error, 0.03);
  EXPECT_NEAR(e.laplace, model.exact, 1e-5) << e.line();
  EXPECT_LT(evaluations, 200);  // Newton steps and Hessians only
  EXPECT_NE(e.line().find("the proposals"), std::string::npos);
}
