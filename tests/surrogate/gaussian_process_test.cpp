// The universal-kriging Gaussian process: analytic gradients against finite differences,
// closed-form leave-one-out against refits, and recovery of known length scales.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <random>

#include "surrogate/gaussian_process.hpp"
#include "surrogate/detail/hyperparameter_fit.hpp"

namespace rbcal::surrogate {
namespace {

// Random inputs in [0, 1]^3, basis (x0, x0 x1), smooth targets, heteroscedastic noise.
GaussianProcessData random_data(int n, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  GaussianProcessData d;
  d.inputs.resize(n, 3);
  d.targets.resize(n);
  d.noise_variances.resize(n);
  d.basis.resize(n, 2);
  for (int i = 0; i < n; ++i) {
    for (int k = 0; k < 3; ++k) d.inputs(i, k) = u(rng);
    const double x0 = d.inputs(i, 0), x1 = d.inputs(i, 1), x2 = d.inputs(i, 2);
    d.targets(i) = 2.0 * x0 + 0.5 * x0 * x1 + 0.3 * std::sin(3.0 * x2) + 0.1 * x1 * x1;
    d.noise_variances(i) = 1e-4 * (1.0 + u(rng));
    d.basis.row(i) << x0, x0 * x1;
  }
  return d;
}

GaussianProcessHyperparameters some_hyperparameters() {
  GaussianProcessHyperparameters hp;
  hp.log_signal_variance = std::log(0.2);
  hp.log_length_scales = Eigen::Vector3d(std::log(0.4), std::log(0.7), std::log(0.3));
  hp.log_nugget_variance = std::log(3e-5);
  return hp;
}

TEST(GaussianProcess, MarginalLikelihoodGradientMatchesFiniteDifferences) {
  const GaussianProcessData data = random_data(30, 7);
  const Eigen::VectorXd p = some_hyperparameters().packed();
  const Eigen::VectorXd analytic = GaussianProcess(data, GaussianProcessHyperparameters::unpacked(p)).log_marginal_likelihood_gradient();
  for (Eigen::Index j = 0; j < p.size(); ++j) {
    const double h = 1e-5;
    Eigen::VectorXd plus = p, minus = p;
    plus(j) += h, minus(j) -= h;
    const double numeric = (GaussianProcess(data, GaussianProcessHyperparameters::unpacked(plus)).log_marginal_likelihood() -
                            GaussianProcess(data, GaussianProcessHyperparameters::unpacked(minus)).log_marginal_likelihood()) /
                           (2.0 * h);
    EXPECT_NEAR(analytic(j), numeric, 1e-5 * (1.0 + std::abs(numeric))) << "parameter " << j;
  }
}

TEST(GaussianProcess, MeanGradientMatchesFiniteDifferences) {
  const GaussianProcessData data = random_data(30, 8);
  const GaussianProcess gp(data, some_hyperparameters());
  auto basis = [](const Eigen::VectorXd& x) { return Eigen::Vector2d(x(0), x(0) * x(1)); };
  auto jacobian = [](const Eigen::VectorXd& x) {
    Eigen::MatrixXd j = Eigen::MatrixXd::Zero(2, 3);
    j(0, 0) = 1.0, j(1, 0) = x(1), j(1, 1) = x(0);
    return j;
  };
  for (const Eigen::Vector3d& x : {Eigen::Vector3d(0.3, 0.6, 0.2), Eigen::Vector3d(0.81, 0.12, 0.55)}) {
    const Eigen::VectorXd gradient = gp.predict(x, basis(x), jacobian(x)).mean_gradient;
    for (int k = 0; k < 3; ++k) {
      const double h = 1e-6;
      Eigen::VectorXd plus = x, minus = x;
      plus(k) += h, minus(k) -= h;
      const double numeric =
          (gp.predict(plus, basis(plus), jacobian(plus)).mean - gp.predict(minus, basis(minus), jacobian(minus)).mean) /
          (2.0 * h);
      EXPECT_NEAR(gradient(k), numeric, 1e-6 * (1.0 + std::abs(numeric))) << "dimension " << k;
    }
  }
}

TEST(GaussianProcess, ClosedFormLeaveOneOutEqualsRefitsWithoutEachPoint) {
  const GaussianProcessData data = random_data(25, 9);
  const GaussianProcessHyperparameters hp = some_hyperparameters();
  const GaussianProcess full(data, hp);
  const LeaveOneOutPredictions loo = full.leave_one_out();
  const Eigen::Index n = data.targets.size();
  for (Eigen::Index i = 0; i < n; ++i) {
    GaussianProcessData rest;
    rest.inputs.resize(n - 1, 3);
    rest.targets.resize(n - 1);
    rest.noise_variances.resize(n - 1);
    rest.basis.resize(n - 1, 2);
    for (Eigen::Index r = 0, k = 0; r < n; ++r) {
      if (r == i) continue;
      rest.inputs.row(k) = data.inputs.row(r);
      rest.targets(k) = data.targets(r);
      rest.noise_variances(k) = data.noise_variances(r);
      rest.basis.row(k) = data.basis.row(r);
      ++k;
    }
    const GaussianProcess refit(rest, hp);
    const Eigen::VectorXd x = data.inputs.row(i).transpose(), h = data.basis.row(i).transpose();
    const GaussianProcessPrediction p = refit.predict(x, h, Eigen::MatrixXd::Zero(2, 3));
    // Predictive distribution of the noisy y_i: latent variance plus the point's noise.
    const double variance = p.variance + full.total_noise_variance(i);
    EXPECT_NEAR(loo.mean(i), p.mean, 1e-8 * (1.0 + std::abs(p.mean))) << "point " << i;
    EXPECT_NEAR(loo.variance(i), variance, 1e-7 * variance) << "point " << i;
  }
}

TEST(GaussianProcess, PredictiveVarianceIncludesMeanCoefficientUncertainty) {
  // Far from all data the latent variance tends to s2 + h^T A^-1 h (eq. 2.42), more than s2.
  const GaussianProcessData data = random_data(20, 10);
  const GaussianProcess gp(data, some_hyperparameters());
  const Eigen::Vector3d far(40.0, 50.0, 60.0);
  const Eigen::Vector2d h(far(0), far(0) * far(1));
  const double expected = std::exp(some_hyperparameters().log_signal_variance) + h.dot(gp.mean_coefficient_covariance() * h);
  EXPECT_NEAR(gp.latent_variance(far, h), expected, 1e-9 * expected);
}

// The joint latent covariance against the conditioning rule it must obey: observing y at x_j with
// total noise v_j lowers the latent variance at x_i by cov(i, j)^2 / (var(j) + v_j). The refit with
// the extra point is an independent computation (a new factorisation, beta re-estimated).
TEST(GaussianProcess, JointLatentCovarianceObeysTheConditioningRule) {
  const GaussianProcessData data = random_data(20, 11);
  const GaussianProcessHyperparameters hp = some_hyperparameters();
  const GaussianProcess gp(data, hp);
  Eigen::MatrixXd x(3, 3), h(3, 2);
  x << 0.2, 0.3, 0.4, 0.25, 0.35, 0.5, 0.9, 0.1, 0.8;
  for (int i = 0; i < 3; ++i) h.row(i) << x(i, 0), x(i, 0) * x(i, 1);
  const Eigen::MatrixXd cov = gp.latent_covariance(x, h);
  EXPECT_NEAR((cov - cov.transpose()).norm(), 0.0, 1e-15);
  for (int i = 0; i < 3; ++i)
    EXPECT_NEAR(cov(i, i), gp.latent_variance(x.row(i).transpose(), h.row(i).transpose()), 1e-12);
  EXPECT_GT(cov(0, 1), 0.1 * std::sqrt(cov(0, 0) * cov(1, 1)));  // neighbours are correlated
  for (int j = 0; j < 3; ++j) {
    GaussianProcessData more = data;
    const Eigen::Index n = data.targets.size();
    more.inputs.conservativeResize(n + 1, 3);
    more.targets.conservativeResize(n + 1);
    more.noise_variances.conservativeResize(n + 1);
    more.basis.conservativeResize(n + 1, 2);
    more.inputs.row(n) = x.row(j);
    more.targets(n) = 1.0;  // the value does not enter variances
    more.noise_variances(n) = 2e-4;
    more.basis.row(n) = h.row(j);
    const GaussianProcess conditioned(more, hp);
    const double v_j = conditioned.total_noise_variance(n);
    for (int i = 0; i < 3; ++i) {
      const double expected = cov(i, i) - cov(i, j) * cov(i, j) / (cov(j, j) + v_j);
      EXPECT_NEAR(conditioned.latent_variance(x.row(i).transpose(), h.row(i).transpose()), expected,
                  1e-8 * cov(i, i))
          << i << " given " << j;
    }
  }
}

// The batched predictions are predict's numbers at every point.
TEST(GaussianProcess, BatchedPredictionsArePointByPointPredictions) {
  const GaussianProcessData data = random_data(25, 12);
  const GaussianProcess gp(data, some_hyperparameters());
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-0.2, 1.2);
  Eigen::MatrixXd x(40, 3), h(40, 2);
  for (int i = 0; i < 40; ++i) {
    for (int k = 0; k < 3; ++k) x(i, k) = u(rng);
    h.row(i) << x(i, 0), x(i, 0) * x(i, 1);
  }
  const GaussianProcessPredictions many = gp.predict_many(x, h);
  for (int i = 0; i < 40; ++i) {
    Eigen::MatrixXd jacobian = Eigen::MatrixXd::Zero(2, 3);  // of h = (x0, x0 x1)
    jacobian(0, 0) = 1.0, jacobian(1, 0) = x(i, 1), jacobian(1, 1) = x(i, 0);
    const GaussianProcessPrediction one = gp.predict(x.row(i).transpose(), h.row(i).transpose(), jacobian);
    EXPECT_NEAR(many.mean(i), one.mean, 1e-12 * (1.0 + std::abs(one.mean)));
    EXPECT_NEAR(many.variance(i), one.variance, 1e-12 + 1e-10 * one.variance);
    const Eigen::VectorXd gradient = many.kernel_gradient.row(i).transpose() + jacobian.transpose() * gp.mean_coefficients();
    EXPECT_NEAR((gradient - one.mean_gradient).norm(), 0.0, 1e-10 * (1.0 + one.mean_gradient.norm()));
  }
}

// The low-rank form against the exact matrix at many points spread over a few length scales:
// the diagonal exact, every entry within the stated tolerance, and a rank well below the
// number of points (it is set by the span in length scales, not by the count).
TEST(GaussianProcess, LowRankLatentCovarianceIsTheExactMatrixWithinItsTolerance) {
  const GaussianProcessData data = random_data(30, 13);
  const GaussianProcess gp(data, some_hyperparameters());
  const auto lines = [](int per_line) {  // four lines of points, as a sample's hematocrits
    Eigen::MatrixXd x(4 * per_line, 3), h(4 * per_line, 2);
    for (int i = 0; i < 4 * per_line; ++i) {
      x.row(i) << 0.2 + 0.2 * (i / per_line), (i % per_line) / (per_line - 1.0), 0.5;
      h.row(i) << x(i, 0), x(i, 0) * x(i, 1);
    }
    return std::pair{x, h};
  };
  const auto [x, h] = lines(100);
  const Eigen::MatrixXd exact = gp.latent_covariance(x, h);
  const JointCovariance low = gp.latent_covariance_factor(x, h);
  const Eigen::MatrixXd approximate = low.dense();
  const auto [x2, h2] = lines(200);  // twice the points on the same lines: hardly more columns
  const Eigen::Index rank_twice = gp.latent_covariance_factor(x2, h2).rank();
  EXPECT_LT(low.rank(), 200);
  EXPECT_LE(rank_twice, low.rank() + low.rank() / 10);
  EXPECT_NEAR((approximate.diagonal() - exact.diagonal().cwiseMax(0.0)).cwiseAbs().maxCoeff(), 0.0,
              1e-12 * exact.diagonal().maxCoeff());
  EXPECT_LE((approximate - exact).cwiseAbs().maxCoeff(), kLowRankTolerance);
  EXPECT_GT(exact.cwiseAbs().maxCoeff(), 1e4 * kLowRankTolerance);  // the tolerance is not the whole matrix
  const GaussianProcessPredictions both = gp.predict_many(x, h, LatentCovariance::low_rank);
  EXPECT_EQ(both.covariance.factor, low.factor);
}

TEST(HyperparameterFit, RecoversKnownLengthScalesOfASampledProcess) {
  // Draw one sample of a zero-mean-plus-constant GP with known hyper-parameters at 250
  // random points in [0, 1]^3, then fit; ML estimates scatter, so the tolerance is a
  // factor 1.35 on each length scale and 2 on the signal variance.
  const int n = 250;
  std::mt19937_64 rng(2024);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::normal_distribution<double> normal(0.0, 1.0);
  GaussianProcessData data;
  data.inputs.resize(n, 3);
  for (int i = 0; i < n; ++i)
    for (int k = 0; k < 3; ++k) data.inputs(i, k) = u(rng);
  const Eigen::Vector3d true_lengths(0.15, 0.3, 0.6);
  const double true_signal_variance = 0.5, noise_variance = 1e-4;
  const Matern52Kernel kernel{true_signal_variance, true_lengths};
  Eigen::MatrixXd k(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      k(i, j) = kernel(data.inputs.row(i).transpose(), data.inputs.row(j).transpose()) + (i == j ? noise_variance : 0.0);
  Eigen::VectorXd z(n);
  for (int i = 0; i < n; ++i) z(i) = normal(rng);
  data.targets = Eigen::MatrixXd(k.llt().matrixL()) * z + Eigen::VectorXd::Constant(n, 1.5);
  data.noise_variances = Eigen::VectorXd::Constant(n, noise_variance);
  data.basis = Eigen::MatrixXd::Ones(n, 1);

  const HyperparameterFitResult fit =
      fit_hyperparameters(data, default_hyperparameter_fit_options(Eigen::Vector3d::Ones(), 0.3));
  EXPECT_GE(fit.starts_converged, 1) << fit.summary;
  const Eigen::VectorXd lengths = fit.hyperparameters.log_length_scales.array().exp();
  std::cout << "fitted length scales " << lengths.transpose() << " (true " << true_lengths.transpose() << "), signal variance "
            << std::exp(fit.hyperparameters.log_signal_variance) << " (true " << true_signal_variance << ")\n";
  for (int d = 0; d < 3; ++d)
    EXPECT_LT(std::abs(std::log(lengths(d) / true_lengths(d))), std::log(1.35))
        << "dimension " << d << ": fitted " << lengths(d) << ", true " << true_lengths(d);
  EXPECT_LT(std::abs(fit.hyperparameters.log_signal_variance - std::log(true_signal_variance)), std::log(2.0));
  // The optimum is a maximum: no start ends higher, and the true parameters score lower.
  GaussianProcessHyperparameters truth{std::log(true_signal_variance), true_lengths.array().log(), std::log(1e-12)};
  EXPECT_GE(fit.log_marginal_likelihood, GaussianProcess(data, truth).log_marginal_likelihood());
}

}  // namespace
}  // namespace rbcal::surrogate
