#include "surrogate/simulation_library.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace rbcal::surrogate {

namespace {

bool same_value(double a, double b) { return std::abs(a - b) <= 1e-9 * std::max(std::abs(a), std::abs(b)); }

bool same_parameters(const LibraryCase& a, const LibraryCase& b) {
  return same_value(a.phi, b.phi) && same_value(a.capillary_number, b.capillary_number) &&
         same_value(a.viscosity_ratio, b.viscosity_ratio);
}

std::string shown(const nlohmann::json* v) { return v ? v->dump() : "(absent)"; }

}  // namespace

void check_library_consistency(const std::vector<LibraryCase>& cases) {
  if (cases.empty()) return;
  const LibraryCase& first = cases.front();
  for (const LibraryCase& c : cases) {
    for (const char* const* f = library_numerics_fields(); *f; ++f) {
      const auto a = first.numerics_signature.find(*f);
      const auto b = c.numerics_signature.find(*f);
      const nlohmann::json* va = a == first.numerics_signature.end() ? nullptr : &*a;
      const nlohmann::json* vb = b == c.numerics_signature.end() ? nullptr : &*b;
      const bool equal = (!va && !vb) || (va && vb && *va == *vb);
      if (!equal)
        throw std::invalid_argument(c.source.string() + ": field " + *f + ": " + shown(vb) + " differs from " +
                                    shown(va) + " in " + first.source.string() +
                                    " (all cases of a library must share their numerics)");
    }
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
  const fs::path case_dir = root / "cases";
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
  if (fs::exists(root / "plan.json")) lib.plan = read_plan_grid(root / "plan.json");
  return lib;
}

}  // namespace rbcal::surrogate
