#include "calibration/model_reach.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

#include "formats/short_number.hpp"

namespace rbcal::calibration {

namespace {

constexpr int kCaSamples = 48, kLambdaSamples = 9;

std::string number(double v) { return formats::short_number(v, 3); }

std::string percent(double gap) { return formats::short_number(std::abs(100.0 * gap), 2) + " %"; }

// Smallest and largest model eta_re (with the sd at each) at phi over the scanned range.
struct Extremes {
  double min = 0.0, min_sd = 0.0, max = 0.0, max_sd = 0.0;
};

Extremes model_extremes(double phi, const surrogate::ViscosityModel& model, const ModelSetup& setup) {
  const surrogate::ParameterRange r = model.range();
  std::vector<double> lambdas;
  if (setup.fit_lambda) {
    for (int k = 0; k < kLambdaSamples; ++k)
      lambdas.push_back(r.lambda_min * std::pow(r.lambda_max / r.lambda_min, k / (kLambdaSamples - 1.0)));
  } else {
    lambdas.push_back(setup.lambda);
  }
  // A model's nuisance parameters (the offset) move it too: every
  // combination of their prior's min, mean and max is tried, so that no point is dropped that
  // another value of them could reach.
  std::vector<surrogate::NuisanceValues> settings{{}};
  for (const surrogate::ModelNuisance& n : model.nuisances()) {
    std::vector<surrogate::NuisanceValues> next;
    for (const auto& s : settings)
      for (double v : {n.min, n.mean, n.max}) {
        next.push_back(s);
        next.back().set(n.name, v);
      }
    settings = std::move(next);
  }
  Extremes e{1e300, 0.0, -1e300, 0.0};
  for (const auto& values : settings)
    for (double lambda : lambdas)
      for (int k = 0; k < kCaSamples; ++k) {
        const double ca = r.ca_min * std::pow(r.ca_max / r.ca_min, k / (kCaSamples - 1.0));
        const surrogate::ViscosityPrediction p =
            model.predict(phi, ca, lambda, values);
        if (p.eta_re < e.min) e = {p.eta_re, p.sd, e.max, e.max_sd};
        if (p.eta_re > e.max) e = {e.min, e.min_sd, p.eta_re, p.sd};
      }
  return e;
}

}  // namespace

std::string to_string(Reach reach) {
  switch (reach) {
    case Reach::reachable: return "reachable";
    case Reach::phi_outside_model: return "phi outside the model";
    case Reach::below_model: return "below the model";
    case Reach::above_model: return "above the model";
  }
  return "";
}

std::string PointReach::reason() const {
  std::ostringstream s;
  switch (reach) {
    case Reach::reachable: return "reachable";
    case Reach::phi_outside_model: s << "phi " << point.phi << " outside the model's phi range"; break;
    case Reach::below_model:
      s << "eta_re " << number(point.eta_re) << " is " << percent(relative_gap) << " below the model's lowest value "
        << number(model_min) << " at phi " << point.phi << " (any G_s)";
      break;
    case Reach::above_model:
      s << "eta_re " << number(point.eta_re) << " is " << percent(relative_gap) << " above the model's highest value "
        << number(model_max) << " at phi " << point.phi << " (any G_s)";
      break;
  }
  return s.str();
}

std::string ReachGroup::line(const surrogate::ParameterRange& range, const ModelSetup& setup) const {
  std::ostringstream s;
  s << "phi " << phi << ": " << points << (points == 1 ? " point" : " points");
  if (reach == Reach::phi_outside_model) {
    s << " outside the model's phi range " << number(range.phi_min) << " to " << number(range.phi_max)
      << " (not fitted)";
    return s.str();
  }
  const std::string where = setup.fit_lambda ? "lambda " + number(range.lambda_min) + " to " + number(range.lambda_max)
                                             : "lambda " + number(setup.lambda);
  s << (reach == Reach::below_model ? " below" : " above") << " the model at any G_s: measured eta_re "
    << number(measured_min) << " to " << number(measured_max) << ", model " << number(model_min) << " to "
    << number(model_max) << " over Ca " << number(range.ca_min) << " to " << number(range.ca_max) << " (" << where
    << "), off by " << percent(gap_min) << (gap_min == gap_max ? "" : " to " + percent(gap_max)) << " (not fitted)";
  return s.str();
}

int ReachDiagnosis::reachable_count() const {
  return static_cast<int>(std::count_if(points.begin(), points.end(), [](const PointReach& p) { return p.reachable(); }));
}

ReachDiagnosis diagnose_reach(const std::vector<RelativeViscosityPoint>& points,
                              const surrogate::ViscosityModel& model, const ModelSetup& setup) {
  const surrogate::ParameterRange range = model.range();
  ReachDiagnosis d;
  std::map<double, Extremes> at_phi;  // the scan depends on phi only
  for (const RelativeViscosityPoint& p : points) {
    PointReach r;
    r.point = p;
    if (!range.contains_phi(p.phi)) {
      r.reach = Reach::phi_outside_model;
    } else {
      auto it = at_phi.find(p.phi);
      if (it == at_phi.end()) it = at_phi.emplace(p.phi, model_extremes(p.phi, model, setup)).first;
      const Extremes& e = it->second;
      r.model_min = e.min;
      r.model_max = e.max;
      if (p.eta_re < e.min - 2.0 * std::hypot(p.eta_re_sd, e.min_sd)) {
        r.reach = Reach::below_model;
        r.relative_gap = p.eta_re / e.min - 1.0;
      } else if (p.eta_re > e.max + 2.0 * std::hypot(p.eta_re_sd, e.max_sd)) {
        r.reach = Reach::above_model;
        r.relative_gap = p.eta_re / e.max - 1.0;
      }
    }
    d.points.push_back(r);
  }
  // Groups by (phi, verdict), phi ascending.
  std::map<std::pair<double, int>, ReachGroup> groups;
  for (const PointReach& r : d.points) {
    if (r.reachable()) continue;
    ReachGroup& g = groups[{r.point.phi, static_cast<int>(r.reach)}];
    const bool first = g.points++ == 0;
    g.phi = r.point.phi;
    g.reach = r.reach;
    g.model_min = r.model_min;
    g.model_max = r.model_max;
    g.measured_min = first ? r.point.eta_re : std::min(g.measured_min, r.point.eta_re);
    g.measured_max = first ? r.point.eta_re : std::max(g.measured_max, r.point.eta_re);
    const double gap = std::abs(r.relative_gap);
    g.gap_min = first ? r.relative_gap : (gap < std::abs(g.gap_min) ? r.relative_gap : g.gap_min);
    g.gap_max = first ? r.relative_gap : (gap > std::abs(g.gap_max) ? r.relative_gap : g.gap_max);
  }
  for (auto& [key, g] : groups) d.unreachable_groups.push_back(g);
  return d;
}

}  // namespace rbcal::calibration
