#include "surrogate/box_anchors.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "formats/printf_string.hpp"

namespace rbcal::surrogate {

using formats::printf_string;

BoxAnchorPrior box_anchor_prior(const std::vector<std::filesystem::path>& anchors, const ViscosityModel& model,
                                const EffectivePhi& phi_eff, const std::vector<int>& library_resolutions,
                                const BoxTwinPrior& twins) {
  if (anchors.empty()) throw std::invalid_argument("box correction: no anchor runs given");
  if (library_resolutions.empty()) throw std::invalid_argument("box correction: no library resolutions given");
  const int coarsest = *std::min_element(library_resolutions.begin(), library_resolutions.end());
  BoxAnchorPrior p;
  const ParameterRange range = model.range();
  for (const std::filesystem::path& file : anchors) {
    BoxAnchor a{read_library_case(file)};
    const LibraryCase& r = a.run;
    if (r.nodes_per_radius < coarsest)
      throw std::invalid_argument(file.string() + ": N_a " + std::to_string(r.nodes_per_radius) +
                                  " is coarser than the library's runs (N_a " + std::to_string(coarsest) +
                                  " and finer): an anchor reads the model at its own resolution or a finer one");
    a.phi_eff = phi_eff(r);
    if (!range.contains(a.phi_eff, r.capillary_number, r.viscosity_ratio))
      throw std::invalid_argument(file.string() + printf_string(": phi_eff %.4g, Ca %g, lambda %g lies outside the "
                                                                "model's range",
                                                                a.phi_eff, r.capillary_number, r.viscosity_ratio));
    a.model_eta_re = model.predict(a.phi_eff, r.capillary_number, r.viscosity_ratio).eta_re;
    if (!(r.eta_re > 1.0 && a.model_eta_re > 1.0))
      throw std::invalid_argument(file.string() + ": eta_re of the run and of the model must exceed 1 for an anchor");
    const double ln_model = std::log(a.model_eta_re);
    a.beta = std::log(r.eta_re) / ln_model - 1.0;
    a.beta_se = r.eta_re_sem / (r.eta_re * ln_model);
    p.anchors.push_back(std::move(a));
  }
  std::vector<double> beta, se;
  for (const BoxAnchor& a : p.anchors) beta.push_back(a.beta), se.push_back(a.beta_se);
  const BetaSpread spread = spread_of(beta, se);
  std::vector<int> resolutions;
  for (const BoxAnchor& a : p.anchors) resolutions.push_back(a.run.nodes_per_radius);
  std::sort(resolutions.begin(), resolutions.end());
  resolutions.erase(std::unique(resolutions.begin(), resolutions.end()), resolutions.end());
  for (const int n_a : resolutions) {
    std::vector<double> tier_beta, tier_se;
    for (const BoxAnchor& a : p.anchors)
      if (a.run.nodes_per_radius == n_a) tier_beta.push_back(a.beta), tier_se.push_back(a.beta_se);
    p.by_resolution.push_back({n_a, tier_beta.size(), spread_of(tier_beta, tier_se)});
  }
  p.mean_beta = spread.mean, p.scatter = spread.scatter, p.mean_se = spread.mean_se;
  p.twins_mean_beta = twins.mean_beta;
  const BulkPrior bulk = bulk_prior(spread, twins.mean_beta);
  p.mean = bulk.mean, p.sd = bulk.sd;
  return p;
}

std::string describe_box_anchors(const BoxAnchorPrior& p) {
  std::string s = printf_string("  %-34s %4s %10s %8s %16s %9s %15s\n", "anchor", "N_a", "phi_actual", "phi_eff",
                                "eta_re", "model", "beta");
  for (const BoxAnchor& a : p.anchors)
    s += printf_string("  %-34s %4d %10.4g %8.4f %8.3f +- %4.2f %9.3f %+7.3f +- %5.3f\n", a.run.id.c_str(),
                       a.run.nodes_per_radius, a.run.phi_actual, a.phi_eff, a.run.eta_re, a.run.eta_re_sem,
                       a.model_eta_re, a.beta, a.beta_se);
  s += printf_string("  %zu anchors: mean beta %+.3f, scatter %.3f, standard error of the mean %.3f\n",
                     p.anchors.size(), p.mean_beta, p.scatter, p.mean_se);
  if (p.by_resolution.size() > 1)
    for (const ResolutionStep& r : p.by_resolution)
      s += printf_string("    at N_a %d: %zu anchors, mean beta %+.3f, scatter %.3f\n", r.nodes_per_radius, r.count,
                         r.spread.mean, r.spread.scatter);
  s += printf_string("  prior for the bulk: mean %.4f, sd %.4f (n + 0.5 m +- sqrt(s^2 + (0.5 m)^2 + se_n^2), "
                     "m %+.3f from the twins)\n",
                     p.mean, p.sd, p.twins_mean_beta);
  return s;
}

}  // namespace rbcal::surrogate
