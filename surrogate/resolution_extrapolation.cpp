#include "surrogate/resolution_extrapolation.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <tuple>

#include "formats/json_file.hpp"
#include "surrogate/training_case.hpp"
#include "surrogate/viscosity_surrogate.hpp"

namespace rbcal::surrogate {

namespace {

int common_resolution(const SimulationLibrary& lib) {
  if (lib.cases.empty()) throw std::invalid_argument(lib.root.string() + ": no cases");
  const int n = lib.cases.front().nodes_per_radius;
  for (const LibraryCase& c : lib.cases)
    if (c.nodes_per_radius != n)
      throw std::invalid_argument(lib.root.string() + ": cases at N_a " + std::to_string(n) + " and " +
                                  std::to_string(c.nodes_per_radius) + " (" + c.id + ")");
  return n;
}

using Key = std::tuple<double, double, double>;
Key key_of(const LibraryCase& c) { return {c.phi, c.capillary_number, c.viscosity_ratio}; }

double richardson(double fine, double coarse, double ratio, double order) {
  return fine + (fine - coarse) / (std::pow(ratio, order) - 1.0);
}

}  // namespace

double error_with_scatter_floor(const LibraryCase& c, const ExtrapolationOptions& options) {
  const double span = options.scatter_phi_high - options.scatter_phi_low;
  const double weight = span > 0.0 ? std::clamp((c.phi - options.scatter_phi_low) / span, 0.0, 1.0)
                                   : (c.phi >= options.scatter_phi_high ? 1.0 : 0.0);
  return std::hypot(c.eta_re_sem, weight * options.scatter_floor * c.eta_re);
}

std::vector<ExtrapolatedCase> extrapolate_to_continuum(const SimulationLibrary& coarse, const SimulationLibrary& fine,
                                                       const ExtrapolationOptions& options) {
  const int n_c = common_resolution(coarse), n_f = common_resolution(fine);
  if (n_f <= n_c)
    throw std::invalid_argument(fine.root.string() + " (N_a " + std::to_string(n_f) + ") is not finer than " +
                                coarse.root.string() + " (N_a " + std::to_string(n_c) + ")");
  if (!(options.order > 0.0 && options.order_low > 0.0))
    throw std::invalid_argument("extrapolation orders must be positive");
  if (!(options.scatter_floor >= 0.0)) throw std::invalid_argument("the scatter floor must not be negative");
  const double ratio = static_cast<double>(n_f) / n_c;
  std::map<Key, const LibraryCase*> fine_at;
  for (const LibraryCase& f : fine.cases) fine_at[key_of(f)] = &f;

  std::vector<ExtrapolatedCase> out;
  std::vector<TrainingCase> corrections;
  for (const LibraryCase& c : coarse.cases) {
    ExtrapolatedCase e;
    e.coarse = c;
    const double sem_c = error_with_scatter_floor(c, options);  // the raw cases keep their own
    const auto it = fine_at.find(key_of(c));
    if (it != fine_at.end()) {
      const LibraryCase& f = *it->second;
      const double sem_f = error_with_scatter_floor(f, options);
      fine_at.erase(it);
      e.paired = true;
      e.fine = f;
      const double g = 1.0 / (std::pow(ratio, options.order) - 1.0);
      e.eta_re = richardson(f.eta_re, c.eta_re, ratio, options.order);
      const double order_spread = 0.5 * (richardson(f.eta_re, c.eta_re, ratio, options.order_low) - e.eta_re);
      e.eta_re_sd = std::sqrt(std::pow((1.0 + g) * sem_f, 2) + std::pow(g * sem_c, 2) +
                              order_spread * order_spread);
      if (!(e.eta_re > 0.0))
        throw std::invalid_argument("case " + c.id + ": Richardson gives eta_re " + std::to_string(e.eta_re) +
                                    " (N_a " + std::to_string(n_c) + ": " + std::to_string(c.eta_re) + ", N_a " +
                                    std::to_string(n_f) + ": " + std::to_string(f.eta_re) + ")");
      e.log_correction = std::log(e.eta_re / c.eta_re);
      const double relative_c = sem_c / c.eta_re;
      e.log_correction_sd = std::sqrt(std::pow(e.eta_re_sd / e.eta_re, 2) + relative_c * relative_c);
      TrainingCase t = training_case(c);
      t.ln_eta_re = e.log_correction;
      t.noise_variance = e.log_correction_sd * e.log_correction_sd;
      corrections.push_back(t);
    }
    out.push_back(e);
  }
  if (!fine_at.empty())
    throw std::invalid_argument(fine.root.string() + ": case " + fine_at.begin()->second->id + " has no twin in " +
                                coarse.root.string());
  const bool some_unpaired = corrections.size() < out.size();
  if (some_unpaired && corrections.size() < 3)
    throw std::invalid_argument(std::to_string(corrections.size()) +
                                " paired points: too few to model the correction at the other " +
                                std::to_string(out.size() - corrections.size()));
  if (some_unpaired) {
    // The correction model: the surrogate's process on c instead of ln eta_re.
    const ViscositySurrogate model = ViscositySurrogate::fit(corrections, fine.root.string());
    for (ExtrapolatedCase& e : out) {
      if (e.paired) continue;
      const LibraryCase& c = e.coarse;
      const double ln_correction = std::log(model.predict(c.phi_actual, c.capillary_number, c.viscosity_ratio).eta_re);
      const double sd = model.log_viscosity_sd(c.phi_actual, c.capillary_number, c.viscosity_ratio);
      e.log_correction = ln_correction;
      e.log_correction_sd = sd;
      e.eta_re = c.eta_re * std::exp(ln_correction);
      e.eta_re_sd = e.eta_re * std::hypot(sd, error_with_scatter_floor(c, options) / c.eta_re);
    }
  }
  return out;
}

nlohmann::json extrapolated_case_json(const ExtrapolatedCase& c, const ExtrapolationOptions& options) {
  nlohmann::json j = formats::read_json_file(c.coarse.source);
  j["result"]["eta_re"] = c.eta_re;
  j["result"]["eta_re_sem"] = c.eta_re_sd;
  nlohmann::json raw = nlohmann::json::array();
  raw.push_back({{"N_a", c.coarse.nodes_per_radius}, {"eta_re", c.coarse.eta_re}, {"eta_re_sem", c.coarse.eta_re_sem}});
  if (c.paired)
    raw.push_back({{"N_a", c.fine.nodes_per_radius}, {"eta_re", c.fine.eta_re}, {"eta_re_sem", c.fine.eta_re_sem}});
  j["extrapolation"] = {{"method", c.method()},
                        {"order", options.order},
                        {"order_low", options.order_low},
                        {"scatter_floor", options.scatter_floor},
                        {"scatter_phi", {options.scatter_phi_low, options.scatter_phi_high}},
                        {"raw", raw},
                        {"log_correction", c.log_correction},
                        {"log_correction_sd", c.log_correction_sd}};
  return j;
}

}  // namespace rbcal::surrogate
