#include "calibration/consistency_check.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "calibration/calibration_report.hpp"
#include "formats/units.hpp"

namespace rbcal::calibration {

namespace {

constexpr double kZ95 = 1.959963984540054;

std::string format(const char* pattern, double a, double b = 0.0, double c = 0.0, double d = 0.0) {
  char buffer[256];
  std::snprintf(buffer, sizeof buffer, pattern, a, b, c, d);
  return buffer;
}

// The sd of ln G_s that a 95 % interval implies, or 0 when it has no positive lower end.
double log_sd(const Interval& i) {
  if (!(i.lower > 0.0 && i.upper > i.lower)) return 0.0;
  return std::log(i.upper / i.lower) / (2.0 * kZ95);
}

struct MethodValue {
  std::string name;
  double value = 0.0;
  Interval interval;
};

std::vector<MethodValue> shear_modulus_by_method(const SampleReport& r) {
  std::vector<MethodValue> out;
  if (r.alpha && r.alpha->shear_modulus.count > 1) {
    const auto& g = r.alpha->shear_modulus;
    // The interval the report prints for the alpha method (mean +- 1.96 se).
    out.push_back({"alpha", g.mean, {g.mean - 1.96 * g.standard_error, g.mean + 1.96 * g.standard_error, 0.95}});
  }
  if (r.direct && r.direct->has_interval_estimate())
    out.push_back({"direct", r.direct->shear_modulus, r.direct->shear_modulus_interval});
  if (r.mcmc) out.push_back({"mcmc", r.mcmc->mcmc.converged ? r.mcmc->shear_modulus_median : 0.0, r.mcmc->shear_modulus_interval});
  out.erase(std::remove_if(out.begin(), out.end(), [](const MethodValue& m) { return !(m.value > 0.0); }), out.end());
  return out;
}

void check_bounds(const std::string& method, const std::string& parameter, double value, const Interval& interval,
                  double lo, double hi, bool log_scale, std::vector<ParameterAtBound>& out) {
  if (!(hi > lo) || !std::isfinite(value) || (log_scale && !(lo > 0.0 && value > 0.0))) return;
  ParameterAtBound near_lower{parameter, method, value, interval, lo, hi, false, log_scale};
  ParameterAtBound near_upper = near_lower;
  near_upper.upper = true;
  if (near_lower.distance_share() <= kBoundShare) out.push_back(near_lower);
  else if (near_upper.distance_share() <= kBoundShare) out.push_back(near_upper);
}

}  // namespace

double ParameterAtBound::distance_share() const {
  const auto t = [&](double x) { return log_scale ? std::log(x) : x; };
  return (upper ? t(range_max) - t(value) : t(value) - t(range_min)) / (t(range_max) - t(range_min));
}

std::string ParameterAtBound::line() const {
  return parameter + " (" + method + ") " + format("%.4g, 95 %% [%.4g, %.4g]", value, interval.lower, interval.upper) +
         " sits at the " + (upper ? "upper" : "lower") + " end of its range " + format("%.4g .. %.4g", range_min, range_max) +
         format(" (%.0f %% of the range from the bound): the data push it against the model's range, and G_s's "
                "interval lacks what the bound cuts off",
                100.0 * distance_share());
}

std::string MethodComparison::line() const {
  return "methods disagree: G_s " + first + format(" %.4g [%.4g, %.4g]", kMicro * first_value, kMicro * first_interval.lower,
                                                   kMicro * first_interval.upper) +
         " and " + second +
         format(" %.4g [%.4g, %.4g] uN/m", kMicro * second_value, kMicro * second_interval.lower,
                kMicro * second_interval.upper) +
         format(": the 95 %% intervals do not overlap (%.2g combined sd of ln G_s apart)", z);
}

bool ConsistencyCheck::consistent() const {
  return at_bounds.empty() && std::all_of(comparisons.begin(), comparisons.end(), [](const auto& c) { return c.overlap; });
}

std::vector<std::string> ConsistencyCheck::lines() const {
  std::vector<std::string> out;
  for (const auto& b : at_bounds) out.push_back(b.line());
  for (const auto& c : comparisons)
    if (!c.overlap) out.push_back(c.line());
  return out;
}

nlohmann::json ConsistencyCheck::to_json() const {
  nlohmann::json j;
  j["consistent"] = consistent();
  j["bound_share"] = kBoundShare;
  j["at_bounds"] = nlohmann::json::array();
  for (const auto& b : at_bounds)
    j["at_bounds"].push_back({{"parameter", b.parameter},
                              {"method", b.method},
                              {"value", b.value},
                              {"interval", {b.interval.lower, b.interval.upper}},
                              {"range", {b.range_min, b.range_max}},
                              {"bound", b.upper ? "upper" : "lower"},
                              {"distance_share", b.distance_share()}});
  j["method_comparisons"] = nlohmann::json::array();
  for (const auto& c : comparisons)
    j["method_comparisons"].push_back({{"methods", {c.first, c.second}},
                                       {"G_s_uN_per_m", {kMicro * c.first_value, kMicro * c.second_value}},
                                       {"intervals_uN_per_m",
                                        {{kMicro * c.first_interval.lower, kMicro * c.first_interval.upper},
                                         {kMicro * c.second_interval.lower, kMicro * c.second_interval.upper}}},
                                       {"z", c.z},
                                       {"overlap", c.overlap}});
  return j;
}

ConsistencyCheck check_consistency(const SampleReport& r, const surrogate::ParameterRange& range) {
  ConsistencyCheck out;
  if (r.direct) {
    for (const auto& n : r.direct->nuisances)
      check_bounds("direct", n.prior.name, n.value, n.interval, n.prior.min, n.prior.max, false, out.at_bounds);
    if (r.direct->index_of("ln_lambda") >= 0)
      check_bounds("direct", "lambda", r.direct->lambda, r.direct->lambda_interval, range.lambda_min, range.lambda_max,
                   true, out.at_bounds);
  }
  if (r.mcmc) {
    for (const auto& n : r.mcmc->nuisances)
      check_bounds("mcmc", n.prior.name, n.value, n.interval, n.prior.min, n.prior.max, false, out.at_bounds);
    if (r.mcmc->lambda_interval.upper > r.mcmc->lambda_interval.lower)
      check_bounds("mcmc", "lambda", r.mcmc->lambda_median, r.mcmc->lambda_interval, range.lambda_min, range.lambda_max,
                   true, out.at_bounds);
  }
  const auto methods = shear_modulus_by_method(r);
  for (std::size_t i = 0; i < methods.size(); ++i)
    for (std::size_t k = i + 1; k < methods.size(); ++k) {
      const MethodValue &a = methods[i], &b = methods[k];
      MethodComparison c{a.name, b.name, a.value, b.value, a.interval, b.interval};
      const double sd = std::hypot(log_sd(a.interval), log_sd(b.interval));
      c.z = sd > 0.0 ? std::abs(std::log(a.value / b.value)) / sd : 0.0;
      c.overlap = a.interval.overlaps(b.interval);
      out.comparisons.push_back(c);
    }
  return out;
}

}  // namespace rbcal::calibration
