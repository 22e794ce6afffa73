#pragma once
// The Gaussian-process surrogate of the suspension's relative viscosity (docs/reference.md,
// "Model files"), implementing ViscosityModel for the calibration stage.
//
// Model: universal kriging (gaussian_process.hpp) of y = ln eta_re over
// x = (phi, ln Ca, ln lambda), phi being the cases' actual volume fraction, with
//   mean m(x) = phi (b0 + b1 ln Ca + b2 ln lambda)   (the seed study's eta_re = exp(alpha phi),
//                                                      alpha linear in ln Ca and ln lambda),
// b by generalised least squares with its uncertainty in the predictive variance; a term
// whose input is constant over the library (e.g. a single lambda) is left out of the mean
// and its length scale held at 1. Anisotropic Matern-5/2 kernel; heteroscedastic noise
// (eta_re_sem / eta_re)^2 per case, plus a fitted nugget and a fixed jitter of 1e-10.
//
// Prediction: eta_re = exp(E[y]) (the median of the log-normal predictive, not its mean),
// sd = eta_re * s * sd(y) (delta method; sd(y) is the latent sd, without observation noise or
// nugget), derivatives eta_re * dE[y]/dx (analytic). s, the predictive sd scale, is the RMS
// of the held-out residuals (held_out_rms) when that exceeds 1, else 1: a process whose held-out
// errors are s times its stated sd on average. Multiplying the whole covariance (kernel,
// nugget and noise) by s^2 leaves the mean unchanged and scales every variance by s^2, so s is
// that one overall scale fitted by cross-validation (docs/library.md, "The runs' offset sd,
// and a predictive sd scale"). inside_hull is false outside the
// bounding box of the library's (phi_actual, Ca, lambda), its phi edges widened by 1 % of
// the largest phi for the scatter of phi_actual about the planned phi: libraries are grids,
// so the box is their convex hull (a library with holes or a non-grid design is not
// checked point by point).
#include <string>
#include <vector>

#include "surrogate/gaussian_process.hpp"
#include "surrogate/leave_one_out_report.hpp"
#include "surrogate/training_case.hpp"
#include "surrogate/viscosity_model.hpp"

namespace rbcal::surrogate {

// How the hyper-parameters were fitted (informational; kept in the surrogate file).
struct SurrogateFitInfo {
  double log_marginal_likelihood = 0.0;
  int starts_tried = 0;
  int starts_converged = 0;
};

class ViscositySurrogate final : public ViscosityModel {
 public:
  // Fits the hyper-parameters by maximum marginal likelihood (hyperparameter_fit.hpp).
  static ViscositySurrogate fit(std::vector<TrainingCase> cases, std::string source_library = "");
  // Takes the hyper-parameters of another surrogate instead of fitting them, its own sd scale
  // from its held-out runs as fit() does. Members of a surrogate family (the same runs mapped at
  // other offsets) built this way differ only by the mapping: fitted one by one, their processes
  // differed by more than the offset moves them where runs are sparse.
  static ViscositySurrogate with_hyperparameters_of(std::vector<TrainingCase> cases, const ViscositySurrogate& reference,
                                                    std::string source_library = "");

  // Uses the given hyper-parameters and sd scale as they are (no fit): a loaded surrogate, or
  // tests. Throws std::invalid_argument unless predictive_sd_scale >= 1 and finite.
  ViscositySurrogate(std::vector<TrainingCase> cases, GaussianProcessHyperparameters hyperparameters,
                     std::string source_library = "", SurrogateFitInfo fit_info = {},
                     double predictive_sd_scale = 1.0);

  ParameterRange range() const override { return range_; }

  // Latent predictive sd of ln eta_re (= relative sd of eta_re), the sd scale applied.
  double log_viscosity_sd(double phi, double capillary_number, double viscosity_ratio) const;
  bool inside_hull(double phi, double capillary_number, double viscosity_ratio) const;

  // Of the process as fitted (before the sd scale).
  LeaveOneOutReport leave_one_out() const;
  // The RMS of the leave-one-out residuals, each divided by what a new run at that point would
  // scatter by about the prediction: the held-out latent variance, the nugget and the run's own
  // noise (run_noise_variance; a case's noise_variance may also carry a systematic share, such
  // as the offset's, that a new run does not add). Equals the leave-one-out RMS standardised
  // residual when every case's run noise is its noise.
  double held_out_rms() const;
  double predictive_sd_scale() const { return predictive_sd_scale_; }

  // Mean basis: names of the terms used ("phi", "phi ln Ca", "phi ln lambda"), GLS
  // coefficients and their standard deviations.
  const std::vector<std::string>& mean_terms() const { return mean_terms_; }
  Eigen::VectorXd mean_coefficients() const { return process_.mean_coefficients(); }
  Eigen::VectorXd mean_coefficient_sds() const;

  const std::vector<TrainingCase>& training_cases() const { return cases_; }
  const GaussianProcess& process() const { return process_; }
  const std::string& source_library() const { return source_library_; }
  const SurrogateFitInfo& fit_info() const { return fit_info_; }

  // Input vector x and mean basis h(x) with its Jacobian, as the process sees them.
  Eigen::VectorXd input(double phi, double capillary_number, double viscosity_ratio) const;
  Eigen::VectorXd basis(const Eigen::VectorXd& x) const;
  Eigen::MatrixXd basis_jacobian(const Eigen::VectorXd& x) const;

 private:
  // Covariance from the process's joint latent covariance of ln eta_re, carried to eta_re by the
  // delta method as each point's sd is: cov(eta_i, eta_j) = eta_i eta_j cov(y_i, y_j). One point
  // without covariance takes the process's single-point path.
  JointViscosityPrediction joint_prediction(const std::vector<ParameterPoint>& queries, const NuisanceValues& nuisances,
                                            CovarianceForm form) const override;
  ViscosityPrediction predict_one(double phi, double capillary_number, double viscosity_ratio) const;
  struct Terms {
    bool ca = false, lambda = false;  // which of phi ln Ca, phi ln lambda are in the mean
  };
  static Terms terms_for(const std::vector<TrainingCase>& cases);
  static GaussianProcessData process_data(const std::vector<TrainingCase>& cases, Terms terms);
  static Eigen::VectorXd basis_of(const Eigen::VectorXd& x, Terms terms);
  // The prediction of eta_re from the process's ln eta_re at a point (mean, latent variance, gradient).
  ViscosityPrediction prediction_from(double mean, double variance, const Eigen::VectorXd& mean_gradient, double phi,
                                      double capillary_number, double viscosity_ratio) const;
  // predict_many, and the process's joint covariance of ln eta_re in the form asked.
  std::vector<ViscosityPrediction> predict_rows(const std::vector<ParameterPoint>& queries, LatentCovariance form,
                                                JointCovariance* covariance) const;

  std::vector<TrainingCase> cases_;
  std::string source_library_;
  SurrogateFitInfo fit_info_;
  double predictive_sd_scale_ = 1.0;
  Terms terms_;
  std::vector<std::string> mean_terms_;
  ParameterRange range_;
  Eigen::Vector3d lower_, upper_;  // bounding box in (phi, ln Ca, ln lambda)
  GaussianProcess process_;
};

}  // namespace rbcal::surrogate
