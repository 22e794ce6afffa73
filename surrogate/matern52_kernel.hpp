#pragma once
// Anisotropic Matern-5/2 covariance (Rasmussen & Williams 2006, eq. 4.17 with nu = 5/2,
// one length scale per input dimension, "automatic relevance determination"):
//   k(a, b) = s2 (1 + sqrt5 r + 5 r^2 / 3) exp(-sqrt5 r),  r^2 = sum_d ((a_d - b_d) / l_d)^2.
// Chosen over the squared exponential because sample paths are twice (not infinitely)
// differentiable, which is less over-confident between library points, while the mean
// and its first derivatives stay smooth (the derivatives below are continuous at r = 0).
#include <Eigen/Core>
#include <cmath>

namespace rbcal::surrogate {

struct Matern52Kernel {
  double signal_variance = 1.0;   // s2
  Eigen::VectorXd length_scales;  // l_d > 0

  // k and the derivatives' common factor in terms of u = sqrt5 r and e = exp(-u): one formula
  // for single values (double) and for whole columns of them (Eigen arrays).
  template <typename T>
  T value_from(const T& u, const T& e) const {
    return signal_variance * (1.0 + u + u * u / 3.0) * e;
  }
  template <typename T>
  T derivative_factor_from(const T& u, const T& e) const {
    return signal_variance * (5.0 / 3.0) * (1.0 + u) * e;
  }

  // s2 (5/3)(1 + sqrt5 r) exp(-sqrt5 r): the common factor of the derivatives below.
  double derivative_factor(double r) const {
    const double u = std::sqrt(5.0) * r;
    return derivative_factor_from(u, std::exp(-u));
  }

  double scaled_distance(const Eigen::Ref<const Eigen::VectorXd>& a, const Eigen::Ref<const Eigen::VectorXd>& b) const {
    return ((a - b).cwiseQuotient(length_scales)).norm();
  }

  double operator()(const Eigen::Ref<const Eigen::VectorXd>& a, const Eigen::Ref<const Eigen::VectorXd>& b) const {
    return of_scaled_distance(scaled_distance(a, b));
  }

  // k as a function of the scaled distance r.
  double of_scaled_distance(double r) const {
    const double u = std::sqrt(5.0) * r;
    return value_from(u, std::exp(-u));
  }

  // d k(a, b) / d ln l_d = s2 (5/3)(1 + sqrt5 r) exp(-sqrt5 r) ((a_d - b_d) / l_d)^2.
  Eigen::VectorXd log_length_scale_derivatives(const Eigen::Ref<const Eigen::VectorXd>& a,
                                               const Eigen::Ref<const Eigen::VectorXd>& b) const {
    const Eigen::VectorXd scaled = (a - b).cwiseQuotient(length_scales);
    return derivative_factor(scaled.norm()) * scaled.cwiseAbs2();
  }
};

}  // namespace rbcal::surrogate
