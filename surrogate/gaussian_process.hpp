#pragma once
// Gaussian-process regression with an explicit linear mean ("universal kriging"):
//   y_i = h(x_i)^T beta + f(x_i) + eps_i,  f ~ GP(0, k) (Matern-5/2, matern52_kernel.hpp),
//   eps_i ~ N(0, noise_i + nugget + jitter)  (heteroscedastic, known noise_i per point),
// with beta given a vague (flat) prior and integrated out, i.e. estimated by generalised
// least squares and its uncertainty carried into the predictive variance (Rasmussen &
// Williams 2006, "Gaussian Processes for Machine Learning", section 2.7, eqs. 2.41-2.43).
// Generic in the input dimension d and the number m of mean basis functions; the caller
// evaluates the basis h(x) (and its Jacobian, for derivatives). Notation of the comments:
// K = k(X, X) + diag(noise), A = H^T K^-1 H (m x m), P = K^-1 - K^-1 H A^-1 H^T K^-1.
#include <Eigen/Cholesky>
#include <Eigen/Core>

#include "surrogate/joint_covariance.hpp"
#include "surrogate/matern52_kernel.hpp"

namespace rbcal::surrogate {

// The low-rank form of the latent covariance (latent_covariance_factor) leaves out less than
// this variance of ln eta_re at any point (sd 1e-4: a hundredth of a per cent of eta_re, against
// measurement errors of a per cent or more), with at most kLowRankMaxColumns columns.
inline constexpr double kLowRankTolerance = 1e-8;
inline constexpr Eigen::Index kLowRankMaxColumns = 600;

// Fixed jitter added to every diagonal element of K (variance units of y), so that K stays
// numerically positive definite even for noise-free points; sd 1e-5 in y = ln eta_re.
inline constexpr double kGaussianProcessJitterVariance = 1e-10;

// Log-parametrised hyper-parameters; packed order: [ln s2, ln l_1 .. ln l_d, ln nugget].
struct GaussianProcessHyperparameters {
  double log_signal_variance = 0.0;
  Eigen::VectorXd log_length_scales;
  double log_nugget_variance = -20.0;  // extra noise variance on every point (model misfit)

  Eigen::VectorXd packed() const;
  static GaussianProcessHyperparameters unpacked(const Eigen::VectorXd& packed);
  Matern52Kernel kernel() const;
};

struct GaussianProcessData {
  Eigen::MatrixXd inputs;           // n x d, one training point per row
  Eigen::VectorXd targets;          // n
  Eigen::VectorXd noise_variances;  // n, known observation noise (>= 0)
  Eigen::MatrixXd basis;            // n x m, row i = h(x_i)^T
};

struct GaussianProcessPrediction {
  double mean = 0.0;               // of the latent h^T beta + f at x (eq. 2.41 with beta integrated out)
  double variance = 0.0;           // of the latent value (no observation noise, no nugget), eq. 2.42
  Eigen::VectorXd mean_gradient;   // d mean / d x
};

// The same at q points at once (row i: point i): the kernel evaluated vectorised and the
// solves as matrix operations, for the many points of a calibration's likelihood.
struct GaussianProcessPredictions {
  Eigen::VectorXd mean;             // q
  Eigen::VectorXd variance;         // q
  Eigen::MatrixXd kernel_gradient;  // q x d: the gradient of the kernel part k*^T alpha (add h'(x)^T beta)
  JointCovariance covariance;       // of the latent values, where asked (see LatentCovariance)
};

// Which joint covariance predict_many adds: none, latent_covariance's exact matrix (full), or
// latent_covariance_factor's diagonal and factor.
enum class LatentCovariance { none, exact, low_rank };

// Closed-form leave-one-out predictions of each y_i from all other points, beta
// re-estimated each time (R&W eqs. 5.10-5.12 with K^-1 replaced by P):
//   mean_i = y_i - [P y]_i / P_ii,   variance_i = 1 / P_ii (of y_i, noise included).
struct LeaveOneOutPredictions {
  Eigen::VectorXd mean;
  Eigen::VectorXd variance;
};

class GaussianProcess {
 public:
  // Factorises K; throws std::runtime_error if K or A is not positive definite (e.g. a
  // basis that is rank deficient on the training inputs).
  GaussianProcess(GaussianProcessData data, GaussianProcessHyperparameters hyperparameters);

  // h_at_x: basis h(x) (m); h_jacobian: d h / d x (m x d).
  GaussianProcessPrediction predict(const Eigen::VectorXd& x, const Eigen::VectorXd& h_at_x,
                                    const Eigen::MatrixXd& h_jacobian) const;
  double latent_variance(const Eigen::VectorXd& x, const Eigen::VectorXd& h_at_x) const;
  // predict at every row of x_rows (h_rows: the basis there), the numbers of predict, and their
  // joint covariance in the form asked (the kernel and the solves shared).
  GaussianProcessPredictions predict_many(const Eigen::MatrixXd& x_rows, const Eigen::MatrixXd& h_rows,
                                          LatentCovariance covariance = LatentCovariance::none) const;
  // Joint covariance of the latent values at several points (row i of x_rows: a point, of
  // h_rows: its basis), eq. 2.42 for every pair: k(x_i, x_j) - k_i^T K^-1 k_j + R_i^T A^-1 R_j.
  // Its diagonal is latent_variance (not clipped at 0 here: the matrix is kept whole).
  Eigen::MatrixXd latent_covariance(const Eigen::MatrixXd& x_rows, const Eigen::MatrixXd& h_rows) const;
  // The same for many points as a diagonal plus a low-rank factor: the pivoted Cholesky
  // factorisation of that matrix, stopped where no point's variance left unexplained exceeds
  // kLowRankTolerance, which stays on the diagonal (exact there; off the diagonal each
  // neglected covariance is below that tolerance). Its rank is set by how many length scales
  // the points span, not by how many points there are.
  JointCovariance latent_covariance_factor(const Eigen::MatrixXd& x_rows, const Eigen::MatrixXd& h_rows) const;

  // GLS estimate beta = A^-1 H^T K^-1 y (eq. 2.42's beta-bar) and its covariance A^-1.
  const Eigen::VectorXd& mean_coefficients() const { return beta_; }
  Eigen::MatrixXd mean_coefficient_covariance() const;

  // log p(y | X, theta) with beta integrated out under a flat prior (eq. 2.43 in the
  // vague limit, i.e. the restricted likelihood):
  //   -1/2 y^T P y - 1/2 ln|K| - 1/2 ln|A| - (n - m)/2 ln 2 pi.
  double log_marginal_likelihood() const;
  // Its gradient in the packed hyper-parameters (eq. 5.9 with P for K^-1):
  //   d/d theta_j = 1/2 tr((alpha alpha^T - P) dK/d theta_j),  alpha = P y.
  Eigen::VectorXd log_marginal_likelihood_gradient() const;

  LeaveOneOutPredictions leave_one_out() const;

  const GaussianProcessData& data() const { return data_; }
  const GaussianProcessHyperparameters& hyperparameters() const { return hyperparameters_; }
  // Total diagonal noise variance of point i (noise_i + nugget + jitter).
  double total_noise_variance(Eigen::Index i) const;

 private:
  Eigen::MatrixXd projection() const;  // P
  Eigen::VectorXd cross_covariance(const Eigen::VectorXd& x) const;
  double variance_given(const Eigen::VectorXd& k_star, const Eigen::VectorXd& h_at_x) const;

  GaussianProcessData data_;
  GaussianProcessHyperparameters hyperparameters_;
  Matern52Kernel kernel_;
  // Training inputs by column (d x n), scaled by the length scales: each point contiguous,
  // so predictions loop over them without temporaries (the MCMC calls predict millions of times).
  Eigen::MatrixXd scaled_points_;
  Eigen::MatrixXd scaled_points_by_dimension_;  // the same, n x d: each coordinate contiguous, for batches
  Eigen::LLT<Eigen::MatrixXd> k_cholesky_;  // K = L L^T
  Eigen::MatrixXd k_inverse_basis_;         // K^-1 H (n x m)
  Eigen::LLT<Eigen::MatrixXd> a_cholesky_;  // A = H^T K^-1 H
  Eigen::VectorXd beta_;
  Eigen::VectorXd alpha_;                   // P y = K^-1 (y - H beta)
};

}  // namespace rbcal::surrogate
