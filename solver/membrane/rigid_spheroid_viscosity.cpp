#include "solver/membrane/rigid_spheroid_viscosity.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <stdexcept>
#include <utility>

namespace rbcal::solver {

namespace {

// Adaptive Simpson on [lo, hi] to an absolute tolerance.
double simpson(const std::function<double(double)>& f, double lo, double hi, double flo, double fmid, double fhi,
               double whole, double tol, int depth) {
  const double mid = 0.5 * (lo + hi), lm = 0.5 * (lo + mid), rm = 0.5 * (mid + hi);
  const double flm = f(lm), frm = f(rm);
  const double left = (mid - lo) / 6.0 * (flo + 4.0 * flm + fmid), right = (hi - mid) / 6.0 * (fmid + 4.0 * frm + fhi);
  if (depth <= 0 || std::abs(left + right - whole) <= 15.0 * tol) return left + right + (left + right - whole) / 15.0;
  return simpson(f, lo, mid, flo, flm, fmid, left, 0.5 * tol, depth - 1) +
         simpson(f, mid, hi, fmid, frm, fhi, right, 0.5 * tol, depth - 1);
}

}  // namespace

double jeffery_equatorial_integral(double polar, double equatorial) {
  const double a = polar, b = equatorial;
  if (!(a > 0.0 && b > 0.0 && std::isfinite(a) && std::isfinite(b)))
    throw std::invalid_argument("Jeffery integral: semi-axes must be positive and finite");
  // x + a^2 = a^2 / t^2 maps [0, inf) onto t in (0, 1], where the integrand
  // 2 a t^4 / (a^2 + (b^2 - a^2) t^2)^3 is smooth (its denominator is at least min(a, b)^6).
  const double k2 = b * b - a * a;
  const std::function<double(double)> f = [&](double t) {
    const double d = a * a + k2 * t * t;
    return 2.0 * a * t * t * t * t / (d * d * d);
  };
  // A thin body's integrand peaks near t = a / b: split there so that Simpson sees it.
  const double split = std::min(0.5, a / b);
  const double scale = 1.0 / (a * std::pow(b, 4));  // J' lies between 0.4 b^-5 and (3 pi / 8) of this
  double sum = 0.0;
  for (const auto& [lo, hi] : {std::pair{0.0, split}, std::pair{split, 1.0}}) {
    const double flo = f(lo), fhi = f(hi), fmid = f(0.5 * (lo + hi));
    sum += simpson(f, lo, hi, flo, fmid, fhi, (hi - lo) / 6.0 * (flo + 4.0 * fmid + fhi), 1e-13 * scale, 40);
  }
  return sum;
}

double rolling_spheroid_intrinsic_viscosity(double aspect_ratio) {
  if (!(aspect_ratio > 0.0)) throw std::invalid_argument("rolling spheroid: aspect ratio must be positive");
  return 1.0 / (aspect_ratio * jeffery_equatorial_integral(aspect_ratio, 1.0));
}

}  // namespace rbcal::solver
