#pragma once
// The Gaussian likelihood of a sample's points with the model's errors correlated between them:
//   eta_re ~ N(m, Sigma),  Sigma = diag(measurement sd_i^2 + (sigma_d m_i)^2) + C,
// where m and C are the model's predictions and their joint covariance at the points
// (surrogate/viscosity_model.hpp, predict_joint). The measurement errors are independent; the
// model's are not: neighbouring points draw on the same runs, and an error common to every run
// (the box correction) moves them all together. Shared by the posterior (its log likelihood) and
// the direct fit (its whitened residuals), so that both answer the same question.
#include <vector>

#include <Eigen/Dense>

#include "calibration/calibration_input.hpp"
#include "calibration/viscosity_observation.hpp"
#include "surrogate/joint_covariance.hpp"

namespace rbcal::calibration {

struct JointResiduals {
  Eigen::VectorXd residual;               // measured eta_re - predicted
  surrogate::JointCovariance covariance;  // Sigma
};

// at: eta0 and the model's nuisance values; relative_discrepancy: sigma_d (0 without it).
JointResiduals joint_residuals(const ViscosityObservation& at, const std::vector<RelativeViscosityPoint>& points,
                               double shear_modulus, double lambda, bool plasma_viscosity_is_parameter,
                               double relative_discrepancy = 0.0);

// One sample's share of a likelihood over several samples: its points at its own G_s, lambda
// and eta0.
struct SampleTerms {
  const std::vector<RelativeViscosityPoint>* points = nullptr;
  double shear_modulus = 0.0;      // [N/m]
  double lambda = 0.0;
  double plasma_viscosity = 0.0;   // eta0 [Pa s]
  bool plasma_viscosity_is_parameter = false;
};

// The samples' points in one vector (sample by sample) with the model's joint covariance over
// all of them: the model's errors at two samples' points are as correlated as at one sample's
// (the same runs, the same box correction, the same nuisance values).
JointResiduals joint_residuals(const surrogate::ViscosityModel& model, const surrogate::NuisanceValues& nuisance,
                               double cell_radius, const std::vector<SampleTerms>& samples,
                               double relative_discrepancy = 0.0);

struct WhitenedResiduals {
  bool ok = false;                // false: Sigma is not finite and positive definite
  // W r with W Sigma W^T = I: independent, unit variance. W = L^-1 (Sigma = L L^T) where Sigma
  // is dense; Sigma^-1/2 where it is a diagonal plus a low-rank factor.
  Eigen::VectorXd whitened;
  double log_determinant = 0.0;   // ln det Sigma
  // -1/2 (|whitened|^2 + ln det Sigma + n ln 2 pi); -inf when not ok.
  double log_likelihood() const;
};

// Where Sigma is singular (points with zero stated sd at which the model is certain) it gets a
// jitter of 1e-12 of its mean diagonal. With a low-rank factor of rank r < n, D + F F^T is
// whitened in O(n r^2) by the Woodbury identity and the matrix determinant lemma in their
// symmetric form: with W = D^-1/2 F and W^T W = V S^2 V^T,
//   Sigma^-1/2 = (I + W V g(S) V^T W^T) D^-1/2,  g(s) = ((1 + s^2)^-1/2 - 1) / s^2,
//   ln det Sigma = sum ln D_i + sum ln(1 + s_k^2).
WhitenedResiduals whiten(const JointResiduals& joint);

// The same log likelihood as whiten(joint).log_likelihood(), without the whitened residuals:
// for a low-rank factor through the Cholesky factor of the r x r capacitance C = I + W^T W,
//   r^T Sigma^-1 r = |y|^2 - |L_C^-1 W^T y|^2,  ln det Sigma = sum ln D_i + 2 sum ln (L_C)_kk,
// (y = D^-1/2 r), a fraction of the cost of whitening; what the MCMC asks for at every step.
double joint_log_likelihood(const JointResiduals& joint);

}  // namespace rbcal::calibration
