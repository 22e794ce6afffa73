#include "surrogate/effective_volume_fraction.hpp"

#include <cmath>
#include <stdexcept>

#include "formats/json_file.hpp"
#include "formats/library_schema.hpp"

namespace rbcal::surrogate {

namespace {

nlohmann::json without_resolution(nlohmann::json signature) {
  signature.erase("numerics.N_a");
  return signature;
}

}  // namespace

MappedLibrary map_to_effective_volume_fraction(const std::vector<SimulationLibrary>& tiers,
                                               const VolumeRatio& volume_ratio,
                                               const EffectiveVolumeFractionOptions& options) {
  if (!(options.offset >= 0.0 && options.offset_sd >= 0.0))
    throw std::invalid_argument("the offset and its sd must not be negative");
  if (!(options.phi_max > 0.0 && options.phi_max < 1.0))
    throw std::invalid_argument("phi_max (--phi-max) must lie strictly between 0 and 1");
  MappedLibrary out;
  const LibraryCase* first = nullptr;
  for (const SimulationLibrary& tier : tiers)
    for (const LibraryCase& c : tier.cases) {
      if (!first) first = &c;
      if (!c.extrapolation_method.empty())
        throw std::invalid_argument(c.source.string() + ": already " + c.extrapolation_method +
                                    " (extrapolation.method): give the runs as simulated");
      if (const auto field = formats::first_signature_difference(without_resolution(first->numerics_signature),
                                                                 without_resolution(c.numerics_signature)))
        throw std::invalid_argument(c.source.string() + ": field " + *field + " is " +
                                    c.numerics_signature.value(*field, nlohmann::json()).dump() + ", " +
                                    first->numerics_signature.value(*field, nlohmann::json()).dump() + " in " +
                                    first->source.string() + " (runs may differ in N_a only)");
      const double h = 1.0 / c.nodes_per_radius;  // a lattice spacing in cell radii
      MappedCase m;
      m.raw = c;
      const double offset = options.offset_at(c.nodes_per_radius);
      if (!(offset >= 0.0))
        throw std::invalid_argument("the offset at N_a " + std::to_string(c.nodes_per_radius) + " (" +
                                    std::to_string(offset) + ") is negative: lower --offset-slope");
      m.volume_ratio = volume_ratio(offset * h);
      m.volume_ratio_sd = 0.5 * std::abs(volume_ratio((offset + options.offset_sd) * h) -
                                         volume_ratio(std::max(0.0, offset - options.offset_sd) * h));
      m.phi = m.volume_ratio * c.phi;
      m.phi_actual = m.volume_ratio * c.phi_actual;
      if (m.phi_actual > options.phi_max) {
        out.left_out.push_back(c);
        continue;
      }
      const double from_offset = c.eta_re * std::abs(std::log(c.eta_re)) * m.volume_ratio_sd / m.volume_ratio;
      m.run_sd = error_with_scatter_floor(c, options.scatter);
      m.eta_re_sd = std::hypot(m.run_sd, from_offset);
      out.cases.push_back(m);
    }
  return out;
}

std::string mapped_case_id(const MappedCase& c) { return c.raw.id + "_n" + std::to_string(c.raw.nodes_per_radius); }

nlohmann::json mapped_case_json(const MappedCase& c, const EffectiveVolumeFractionOptions& options) {
  nlohmann::json j = formats::read_json_file(c.raw.source);
  j["params"]["phi"] = c.phi;
  j["result"]["phi_actual"] = c.phi_actual;
  j["result"]["eta_re_sem"] = c.eta_re_sd;
  j["extrapolation"] = {
      {"method", formats::kEffectiveVolumeFraction},
      {"offset_lattice_spacings", options.offset},
      {"offset_slope", options.offset_slope},
      {"offset_sd", options.offset_sd},
      {"offset_at_this_resolution", options.offset_at(c.raw.nodes_per_radius)},
      {"volume_ratio", c.volume_ratio},
      {"volume_ratio_sd", c.volume_ratio_sd},
      {"run_sd", c.run_sd},
      {"phi_raw", c.raw.phi},
      {"phi_actual_raw", c.raw.phi_actual},
      {"scatter_floor", options.scatter.scatter_floor},
      {"scatter_phi", {options.scatter.scatter_phi_low, options.scatter.scatter_phi_high}},
      {"raw", nlohmann::json::array({{{"N_a", c.raw.nodes_per_radius},
                                      {"eta_re", c.raw.eta_re},
                                      {"eta_re_sem", c.raw.eta_re_sem}}})}};
  return j;
}

}  // namespace rbcal::surrogate
