#include "surrogate/trend_check.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <sstream>

#include "formats/short_number.hpp"

namespace rbcal::surrogate {

namespace {

// n values from lo to hi (log-spaced if log), clipped to [min, max], duplicates dropped.
std::vector<double> probe(double lo, double hi, int n, bool log, double min, double max) {
  std::set<double> values;
  for (int i = 0; i < n; ++i) {
    const double t = n == 1 ? 0.0 : static_cast<double>(i) / (n - 1);
    const double v = log ? lo * std::pow(hi / lo, t) : lo + (hi - lo) * t;
    values.insert(std::clamp(v, min, max));
  }
  return {values.begin(), values.end()};
}

std::string number(double v) { return formats::short_number(v, 3); }

std::string worst(const std::vector<TrendViolation>& v, const char* axis) {
  if (v.empty()) return "";
  // The largest drop against the trend, relative.
  const auto w = std::max_element(v.begin(), v.end(), [](const TrendViolation& a, const TrendViolation& b) {
    return std::abs(a.eta_re_next / a.eta_re_here - 1.0) < std::abs(b.eta_re_next / b.eta_re_here - 1.0);
  });
  return "; worst at phi " + number(w->phi) + ", Ca " + number(w->capillary_number) + ", lambda " +
         number(w->viscosity_ratio) + ": " + number(w->eta_re_here) + " -> " + number(w->eta_re_next) + " at the next " +
         axis;
}

}  // namespace

double pries_1992_relative_viscosity(double hematocrit) {
  const double c = -0.8;
  return 1.0 + 2.2 * (std::pow(1.0 - hematocrit, c) - 1.0) / (std::pow(0.55, c) - 1.0);
}

bool TrendCheck::high_shear_ok() const { return std::abs(high_shear_eta_re / high_shear_pries - 1.0) <= 0.25; }

TrendCheck check_trends(const ViscosityModel& model) {
  const ParameterRange r = model.range();
  TrendCheck t;
  t.phi = probe(0.05, 0.55, 11, false, r.phi_min, r.phi_max);
  t.capillary_number = probe(0.01, 3.2, 11, true, r.ca_min, r.ca_max);
  for (double lambda : {0.1, 0.3, 1.0, 3.0, 5.0, 10.0}) t.viscosity_ratio.push_back(std::clamp(lambda, r.lambda_min, r.lambda_max));
  t.viscosity_ratio.erase(std::unique(t.viscosity_ratio.begin(), t.viscosity_ratio.end()), t.viscosity_ratio.end());
  auto eta = [&](double phi, double ca, double lambda) { return model.predict(phi, ca, lambda).eta_re; };
  for (double lambda : t.viscosity_ratio)
    for (double ca : t.capillary_number)
      for (std::size_t i = 0; i + 1 < t.phi.size(); ++i) {
        ++t.phi_steps;
        const double a = eta(t.phi[i], ca, lambda), b = eta(t.phi[i + 1], ca, lambda);
        if (!(b > a)) t.not_rising_with_phi.push_back({{t.phi[i], ca, lambda}, a, b});
      }
  for (double lambda : t.viscosity_ratio)
    for (double phi : t.phi) {
      if (phi < 0.21 - 1e-12) continue;
      for (std::size_t i = 0; i + 1 < t.capillary_number.size(); ++i) {
        ++t.ca_steps;
        const ViscosityPrediction here = model.predict(phi, t.capillary_number[i], lambda);
        const double b = eta(phi, t.capillary_number[i + 1], lambda);
        if (!(b < here.eta_re)) t.not_falling_with_ca.push_back({{phi, t.capillary_number[i], lambda}, here.eta_re, b, here.sd});
      }
    }
  t.high_shear_phi = std::clamp(0.41, r.phi_min, r.phi_max);
  t.high_shear_ca = std::clamp(0.8, r.ca_min, r.ca_max);
  t.high_shear_lambda = std::clamp(5.0, r.lambda_min, r.lambda_max);
  t.high_shear_eta_re = eta(t.high_shear_phi, t.high_shear_ca, t.high_shear_lambda);
  t.high_shear_pries = pries_1992_relative_viscosity(t.high_shear_phi);
  const double phi0 = t.phi.front();
  t.intrinsic_low_ca = (eta(phi0, t.capillary_number.front(), t.high_shear_lambda) - 1.0) / phi0;
  t.intrinsic_high_ca = (eta(phi0, t.capillary_number.back(), t.high_shear_lambda) - 1.0) / phi0;
  return t;
}

std::string TrendCheck::report() const {
  std::ostringstream o;
  o << "probe grid: " << phi.size() << " phi (" << number(phi.front()) << " to " << number(phi.back()) << ") x "
    << capillary_number.size() << " Ca (" << number(capillary_number.front()) << " to "
    << number(capillary_number.back()) << ") x " << viscosity_ratio.size() << " lambda\n";
  o << "  rises with phi:        " << (not_rising_with_phi.empty() ? "PASS" : "FAIL") << " ("
    << not_rising_with_phi.size() << " of " << phi_steps << " steps not rising"
    << worst(not_rising_with_phi, "phi") << ")\n";
  o << "  falls with Ca (phi >= 0.21): " << (not_falling_with_ca.empty() ? "PASS" : "FAIL") << " ("
    << not_falling_with_ca.size() << " of " << ca_steps << " steps not falling" << worst(not_falling_with_ca, "Ca")
    << ")\n";
  if (!not_falling_with_ca.empty()) {
    // Where they are, and whether the model resolves them (a step far below its sd is flat).
    std::map<double, int> per_phi;
    double largest = 0.0;
    for (const TrendViolation& v : not_falling_with_ca) {
      ++per_phi[v.phi];
      largest = std::max(largest, v.size_in_sd());
    }
    o << "    not falling, per phi (of " << (capillary_number.size() - 1) * viscosity_ratio.size() << " steps):";
    for (const auto& [p, n] : per_phi) o << " " << number(p) << ": " << n << ";";
    o << " the largest rise is " << number(largest) << " sd of the model\n";
  }
  o << "  high shear (phi " << number(high_shear_phi) << ", Ca " << number(high_shear_ca) << ", lambda "
    << number(high_shear_lambda) << "): " << (high_shear_ok() ? "PASS" : "FAIL") << " (eta_re "
    << number(high_shear_eta_re) << " against " << number(high_shear_pries) << " from Pries et al. 1992, ratio "
    << number(high_shear_eta_re / high_shear_pries) << "; within 25 % passes)\n";
  o << "  dilute end: (eta_re - 1) / phi at phi " << number(phi.front()) << " = " << number(intrinsic_low_ca)
    << " at Ca " << number(capillary_number.front()) << ", " << number(intrinsic_high_ca) << " at Ca "
    << number(capillary_number.back()) << " (lambda " << number(high_shear_lambda) << ")\n";
  return o.str();
}

}  // namespace rbcal::surrogate
