#include "surrogate/box_twins.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "formats/printf_string.hpp"

namespace rbcal::surrogate {

using formats::printf_string;

namespace {

bool same_point(const LibraryCase& a, const LibraryCase& b) {
  auto close = [](double x, double y) { return std::abs(x - y) <= 1e-9 * std::max(std::abs(x), std::abs(y)); };
  return close(a.phi, b.phi) && close(a.capillary_number, b.capillary_number) &&
         close(a.viscosity_ratio, b.viscosity_ratio);
}

}  // namespace

BetaSpread spread_of(const std::vector<double>& beta, const std::vector<double>& beta_se) {
  BetaSpread out;
  const double n = static_cast<double>(beta.size());
  if (beta.empty()) return out;
  double sum = 0.0, se2 = 0.0;
  for (std::size_t i = 0; i < beta.size(); ++i) sum += beta[i], se2 += beta_se[i] * beta_se[i];
  out.mean = sum / n;
  double ss = 0.0;
  for (double b : beta) ss += (b - out.mean) * (b - out.mean);
  out.scatter = beta.size() > 1 ? std::sqrt(ss / (n - 1.0)) : 0.0;
  out.mean_se = std::sqrt(se2) / n;
  return out;
}

BulkPrior bulk_prior(const BetaSpread& step, double twins_mean_beta) {
  const double beyond = 0.5 * twins_mean_beta;
  return {step.mean + beyond, std::sqrt(step.scatter * step.scatter + beyond * beyond + step.mean_se * step.mean_se)};
}

BoxTwinPrior box_twin_prior(const std::vector<BoxTwinFiles>& pairs) {
  if (pairs.empty()) throw std::invalid_argument("box correction: no twin pairs given");
  BoxTwinPrior p;
  for (const BoxTwinFiles& f : pairs) {
    BoxTwin t{read_library_case(f.library_box), read_library_case(f.bigger_box)};
    if (!same_point(t.library_box, t.bigger_box))
      throw std::invalid_argument(f.bigger_box.string() + ": not the same point (phi, Ca, lambda) as its twin " +
                                  f.library_box.string());
    const double e8 = t.library_box.eta_re, s8 = t.library_box.eta_re_sem;
    const double e16 = t.bigger_box.eta_re, s16 = t.bigger_box.eta_re_sem;
    if (!(e8 > 1.0)) throw std::invalid_argument(f.library_box.string() + ": eta_re must exceed 1 for a twin");
    const double ln8 = std::log(e8);
    t.beta = std::log(e16 / e8) / ln8;
    // d beta / d e16 = 1 / (e16 ln e8); d beta / d e8 = -(1 + beta) / (e8 ln e8)
    t.beta_se = std::hypot(s16 / (e16 * ln8), (1.0 + t.beta) * s8 / (e8 * ln8));
    p.twins.push_back(std::move(t));
  }
  std::vector<double> beta, se;
  for (const BoxTwin& t : p.twins) beta.push_back(t.beta), se.push_back(t.beta_se);
  const BetaSpread spread = spread_of(beta, se);
  p.mean_beta = spread.mean, p.scatter = spread.scatter, p.mean_se = spread.mean_se;
  const BulkPrior bulk = bulk_prior(spread, spread.mean);  // the twins are their own step: 1.5 m
  p.mean = bulk.mean, p.sd = bulk.sd;
  return p;
}

std::string describe_box_twins(const BoxTwinPrior& p) {
  std::string s = printf_string("  %-34s %10s %14s %14s %6s %15s\n", "twin", "phi_actual", "eta_re", "eta_re 2x box",
                         "ratio", "beta");
  for (const BoxTwin& t : p.twins)
    s += printf_string("  %-34s %10.4g %7.3f +- %4.2f %7.3f +- %4.2f %6.3f %+7.3f +- %5.3f\n", t.library_box.id.c_str(),
                t.library_box.phi_actual, t.library_box.eta_re, t.library_box.eta_re_sem, t.bigger_box.eta_re,
                t.bigger_box.eta_re_sem, t.bigger_box.eta_re / t.library_box.eta_re, t.beta, t.beta_se);
  s += printf_string("  %zu twins: mean beta %+.3f, scatter %.3f, standard error of the mean %.3f\n", p.twins.size(),
              p.mean_beta, p.scatter, p.mean_se);
  s += printf_string("  prior for the bulk: mean %.4f, sd %.4f (1.5 m +- sqrt(s^2 + (0.5 m)^2 + se_m^2))\n", p.mean,
                     p.sd);
  return s;
}

}  // namespace rbcal::surrogate
