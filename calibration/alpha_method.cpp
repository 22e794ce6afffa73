#include "calibration/alpha_method.hpp"

#include "calibration/detail/curve_interpolation.hpp"
#include "calibration/sample_mean.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

namespace rbcal::calibration {

namespace {

ShearModulusSummary summarise(const std::vector<AlphaMatch>& matches) {
  std::vector<double> matched;
  for (const auto& m : matches)
    if (m.matched) matched.push_back(m.shear_modulus);
  const SampleMean g = sample_mean(matched);
  return {g.mean, g.sd, g.standard_error, g.count};
}

// Picks the crossing and writes the message; false if there is none.
bool pick_crossing(const std::vector<double>& crossings, const std::string& what, double* x, std::string* message) {
  if (crossings.empty()) {
    *message = what;
    return false;
  }
  *x = crossings.front();
  if (crossings.size() > 1)
    *message = std::to_string(crossings.size()) + " crossings of alpha (alpha not monotone); the first is used";
  return true;
}

}  // namespace

std::vector<double> level_crossings(const std::vector<double>& x, const std::vector<double>& y, double target) {
  std::vector<double> result;
  for (std::size_t i = 0; i + 1 < x.size(); ++i) {
    const double a = y[i] - target, b = y[i + 1] - target;
    if (a == 0.0) {
      result.push_back(x[i]);
    } else if (a * b < 0.0) {
      result.push_back(x[i] + (x[i + 1] - x[i]) * a / (a - b));
    }
  }
  if (!x.empty() && y.back() == target) result.push_back(x.back());
  return result;
}

AlphaMethodResult estimate_by_alpha_matching(const SampleData& sample, const surrogate::ViscosityModel& model,
                                             const AlphaMethodOptions& options) {
  AlphaMethodResult result;
  const double eta0 = sample.plasma.eta0;
  result.plasma_viscosity = eta0;

  // Measured alpha per shear rate (shear rates equal to 1e-9 relative are one group).
  std::vector<RelativeViscosityPoint> points;
  for (const auto& p : sample.points)
    if (p.phi >= options.phi_min && p.phi <= options.phi_max) points.push_back(p);
  std::sort(points.begin(), points.end(),
            [](const auto& a, const auto& b) { return a.shear_rate < b.shear_rate; });
  std::vector<std::pair<double, std::pair<std::vector<double>, std::vector<double>>>> groups;  // rate, (phi, eta_re)
  for (std::size_t begin = 0; begin < points.size();) {
    std::size_t end = begin;
    std::vector<double> phi, eta_re;
    while (end < points.size() && points[end].shear_rate <= points[begin].shear_rate * (1.0 + 1e-9)) {
      phi.push_back(points[end].phi);
      eta_re.push_back(points[end].eta_re);
      ++end;
    }
    groups.push_back({points[begin].shear_rate, {phi, eta_re}});
    begin = end;
  }
  // Curves measured at their own shear rates (digitised figures) share none: then every curve is
  // read at the shear rates of the hematocrit with the most points (log-log, inside each curve's
  // measured range, curve_interpolation.hpp), and the alphas are fitted there.
  const bool shared = std::any_of(groups.begin(), groups.end(), [&](const auto& g) {
    return static_cast<int>(g.second.first.size()) >= options.min_points_per_shear_rate;
  });
  if (!shared && !points.empty()) {
    std::map<double, std::vector<RelativeViscosityPoint>> curves;
    for (const auto& p : points) curves[p.phi].push_back(p);
    const auto reference = std::max_element(curves.begin(), curves.end(), [](const auto& a, const auto& b) {
      return a.second.size() < b.second.size();
    });
    groups.clear();
    std::vector<std::pair<double, SortedCurve>> sorted;  // each curve sorted once, read at every rate
    for (const auto& [curve_phi, curve] : curves) sorted.emplace_back(curve_phi, SortedCurve(curve));
    for (const auto& r : reference->second) {
      std::vector<double> phi, eta_re;
      for (const auto& [curve_phi, curve] : sorted)
        if (const auto v = curve.at(r.shear_rate)) {
          phi.push_back(curve_phi);
          eta_re.push_back(*v);
        }
      groups.push_back({r.shear_rate, {phi, eta_re}});
    }
    std::ostringstream m;
    m << "no shear rate is shared by " << options.min_points_per_shear_rate
      << " hematocrits: every curve read at the shear rates of phi " << reference->first
      << " (log-log interpolation, no extrapolation)";
    result.messages.push_back(m.str());
    result.curves_interpolated = true;
  }
  for (const auto& [rate, data] : groups) {
    const auto& [phi, eta_re] = data;
    if (static_cast<int>(phi.size()) >= options.min_points_per_shear_rate) {
      result.measured.push_back({rate, fit_exponential_alpha(phi, eta_re, options.fit_space)});
    } else {
      std::ostringstream m;
      m << "shear rate " << rate << " 1/s skipped: " << phi.size()
        << " volume fraction(s) within the cut-offs, need " << options.min_points_per_shear_rate;
      result.messages.push_back(m.str());
    }
  }

  // Model alpha per Ca on a ln-uniform grid, fitted to the model at a phi grid.
  const surrogate::ParameterRange range = model.range();
  const double phi_lo = std::max(range.phi_min, options.phi_min);
  const double phi_hi = std::min(range.phi_max, options.phi_max);
  // The model's alpha is fitted where the sample's is: at its hematocrits (those inside the
  // model's range). ln eta_re is not exactly linear in phi, so an alpha over another phi window
  // would not be comparable. A sample with fewer than two such hematocrits uses a uniform grid.
  std::vector<double> model_phi;
  for (const auto& p : points)
    if (p.phi >= phi_lo && p.phi <= phi_hi && std::find(model_phi.begin(), model_phi.end(), p.phi) == model_phi.end())
      model_phi.push_back(p.phi);
  std::sort(model_phi.begin(), model_phi.end());
  if (model_phi.size() < 2 || !options.model_at_sample_hematocrits) {
    model_phi.clear();
    for (int i = 0; i < options.model_phi_points; ++i)
      model_phi.push_back(phi_lo + (phi_hi - phi_lo) * i / std::max(1, options.model_phi_points - 1));
  }
  auto model_alpha = [&](double ca) {
    std::vector<double> eta_re;
    for (double phi : model_phi) eta_re.push_back(model.predict(phi, ca, options.setup.lambda).eta_re);
    return fit_exponential_alpha(model_phi, eta_re, options.fit_space);
  };
  std::vector<double> ln_ca, alpha_of_ln_ca;
  for (int i = 0; i < options.model_ca_points; ++i) {
    const double x = std::log(range.ca_min) +
                     (std::log(range.ca_max) - std::log(range.ca_min)) * i / std::max(1, options.model_ca_points - 1);
    const double ca = std::exp(x);
    result.model.push_back({ca, model_alpha(ca)});
    ln_ca.push_back(x);
    alpha_of_ln_ca.push_back(result.model.back().fit.alpha);
  }

  // Measured shear rate -> Ca with the same model alpha (linear in ln Ca) -> G_s.
  for (const auto& m : result.measured) {
    AlphaMatch match;
    match.shear_rate = m.shear_rate;
    match.alpha = m.fit.alpha;
    double x = 0.0;
    std::ostringstream why;
    why << "alpha " << m.fit.alpha << " is outside the model's alpha over Ca in [" << range.ca_min << ", "
        << range.ca_max << "]";
    if (pick_crossing(level_crossings(ln_ca, alpha_of_ln_ca, m.fit.alpha), why.str(), &x, &match.message)) {
      match.matched = true;
      match.capillary_number = std::exp(x);
      match.shear_modulus =
          shear_modulus_from_capillary_number(eta0, m.shear_rate, options.setup.cell_radius, match.capillary_number);
    }
    result.per_shear_rate.push_back(match);
  }

  // The seed study's direction: model Ca -> shear rate with the same measured alpha (linear in ln gamma_dot).
  std::vector<double> ln_rate, measured_alpha;
  for (const auto& m : result.measured) {
    ln_rate.push_back(std::log(m.shear_rate));
    measured_alpha.push_back(m.fit.alpha);
  }
  for (double ca : options.capillary_numbers) {
    AlphaMatch match;
    match.capillary_number = ca;
    if (!range.contains_ca(ca)) {
      std::ostringstream m;
      m << "Ca " << ca << " is outside the model's range [" << range.ca_min << ", " << range.ca_max << "]";
      match.message = m.str();
      result.per_capillary_number.push_back(match);
      continue;
    }
    match.alpha = model_alpha(ca).alpha;
    double x = 0.0;
    std::ostringstream why;
    why << "model alpha " << match.alpha << " at Ca " << ca << " is outside the measured alphas";
    if (pick_crossing(level_crossings(ln_rate, measured_alpha, match.alpha), why.str(), &x, &match.message)) {
      match.matched = true;
      match.shear_rate = std::exp(x);
      match.shear_modulus = shear_modulus_from_capillary_number(eta0, match.shear_rate, options.setup.cell_radius, ca);
    }
    result.per_capillary_number.push_back(match);
  }
  result.shear_modulus = summarise(result.per_shear_rate);
  result.shear_modulus_per_ca = summarise(result.per_capillary_number);
  if (result.shear_modulus.count == 0)
    result.messages.push_back("no measured shear rate could be matched to a Ca of the model");
  return result;
}

}  // namespace rbcal::calibration
