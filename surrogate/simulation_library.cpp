#include "surrogate/simulation_library.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "formats/format_error.hpp"
#include "formats/json_file.hpp"
#include "formats/plan_grid.hpp"
#include "formats/library_schema.hpp"

namespace rbcal::surrogate {

namespace {

bool same_value(double a, double b) { return std::abs(a - b) <= 1e-9 * std::max(std::abs(a), std::abs(b)); }

bool same_parameters(const LibraryCase& a, const LibraryCase& b) {
  return same_value(a.phi, b.phi) && same_value(a.capillary_number, b.capillary_number) &&
         same_value(a.viscosity_ratio, b.viscosity_ratio);
}

std::string shown(const nlohmann::json& signature, const std::string& field) {
  const auto it = signature.find(field);
  return it == signature.end() ? "(absent)" : it->dump();
}

}  // namespace

void check_library_consistency(const std::vector<LibraryCase>& cases) {
  if (cases.empty()) return;
  const LibraryCase& first = cases.front();
  for (const LibraryCase& c : cases) {
    if (const auto field = formats::first_signature_difference(first.numerics_signature, c.numerics_signature))
      throw formats::FormatError(c.source.string(), *field,
                                 shown(c.numerics_signature, *field) + " differs from " +
                                     shown(first.numerics_signature, *field) + " in " + first.source.string() +
                                     " (all cases of a library must share their numerics)");
  }
  for (std::size_t i = 0; i < cases.size(); ++i)
    for (std::size_t k = 0; k < i; ++k)
      if (same_parameters(cases[i], cases[k]))
        throw std::invalid_argument(cases[i].source.string() + ": same (phi, Ca, lambda) = (" +
                                    std::to_string(cases[i].phi) + ", " + std::to_string(cases[i].capillary_number) +
                                    ", " + std::to_string(cases[i].viscosity_ratio) + ") as " +
                                    cases[k].source.string());
}

SimulationLibrary read_library(const std::filesystem::path& root) {
  namespace fs = std::filesystem;
  if (!fs::is_directory(root)) throw std::invalid_argument(root.string() + ": not a folder");
  const fs::path case_dir = formats::library_layout::cases(root);
  if (!fs::is_directory(case_dir))
    throw std::invalid_argument(case_dir.string() + ": missing (a library keeps its finished cases there)");
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(case_dir))
    if (entry.is_regular_file() && entry.path().extension() == ".json") files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  if (files.empty()) throw std::invalid_argument(case_dir.string() + ": no finished cases (*.json)");

  SimulationLibrary lib;
  lib.root = root;
  for (const fs::path& f : files) lib.cases.push_back(read_library_case(f));
  check_library_consistency(lib.cases);
  const fs::path plan = formats::library_layout::plan(root);
  if (fs::exists(plan)) {
    const nlohmann::json document = formats::read_json_file(plan);
    if (!formats::names_case_files(document))
      lib.plan = formats::plan_grid_from_json(document, plan.string());
  }
  return lib;
}

}  // namespace rbcal::surrogate
