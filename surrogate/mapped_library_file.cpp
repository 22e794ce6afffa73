#include "surrogate/mapped_library_file.hpp"

#include <cstdio>
#include <map>
#include <stdexcept>

#include "formats/json_file.hpp"
#include "formats/library_schema.hpp"
#include "formats/printf_string.hpp"

namespace rbcal::surrogate {

using formats::printf_string;

void write_mapped_library(const MappedLibrary& mapped, const EffectiveVolumeFractionOptions& options,
                          const std::filesystem::path& out) {
  namespace fs = std::filesystem;
  std::map<std::string, const MappedCase*> by_id;
  for (const auto& c : mapped.cases) {
    const auto [at, inserted] = by_id.emplace(mapped_case_id(c), &c);
    if (!inserted)
      throw std::invalid_argument(c.raw.source.string() + ": a second run " + at->first + " (the first: " +
                                  at->second->raw.source.string() +
                                  "; the same point at the same N_a in two libraries)");
  }
  const fs::path cases_dir = formats::library_layout::cases(out);
  fs::create_directories(cases_dir);
  for (const auto& c : mapped.cases) {
    const std::string id = mapped_case_id(c);
    formats::write_json_atomically(cases_dir / (id + ".json"), mapped_case_json(c, options));
    const fs::path series = c.raw.source.parent_path() / (c.raw.id + ".csv");
    if (fs::exists(series)) fs::copy_file(series, cases_dir / (id + ".csv"), fs::copy_options::overwrite_existing);
  }
}

std::string describe_mapped_library(const MappedLibrary& mapped, std::size_t libraries,
                                    const std::filesystem::path& out, const VolumeRatio& volume_ratio,
                                    const EffectiveVolumeFractionOptions& options) {
  std::string s = printf_string("rbcal library effective-phi: %zu runs from %zu librar%s -> %s\n",
                         mapped.cases.size() + mapped.left_out.size(), libraries, libraries == 1 ? "y" : "ies",
                         out.string().c_str());
  s += printf_string(
      "  offset %g +- %g lattice spacings at N_a 8, slope %g per unit of 1 / N_a; phi_eff = g phi_actual with g:",
      options.offset, options.offset_sd, options.offset_slope);
  for (int n : {6, 8, 10, 12, 16}) s += printf_string(" %.3f (N_a %d)", volume_ratio(options.offset_at(n) / n), n);
  s += printf_string("\n  %-34s %8s %10s %8s %7s %10s %16s\n", "run", "phi", "phi_actual", "phi_eff", "g", "eta_re",
                     "sd");
  for (const auto& c : mapped.cases)
    s += printf_string("  %-34s %8.4g %10.4g %8.4g %7.4f %10.4g %7.2g (sem %.2g)\n", mapped_case_id(c).c_str(),
                       c.raw.phi, c.raw.phi_actual, c.phi_actual, c.volume_ratio, c.raw.eta_re, c.eta_re_sd,
                       c.raw.eta_re_sem);
  for (const auto& c : mapped.left_out)
    s += printf_string("  left out (g phi_actual above %g): %s at N_a %d\n", options.phi_max, c.id.c_str(),
                       c.nodes_per_radius);
  return s;
}

}  // namespace rbcal::surrogate
