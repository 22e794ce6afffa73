#pragma once
// The parameter grid of a library's plan (LIB/plan.json, schema "rbcal.plan/1"):
//   {"schema": "rbcal.plan/1", "grid": {"phi": [...], "Ca": [...], "lambda": [...]}, ...}
// or, for a space-filling design, the points themselves (exactly one of the two):
//   {"schema": "rbcal.plan/1", "points": [[phi, Ca, lambda], ...], ...}
// The other keys (description, base case, max_shear_modulus_lattice) belong to the
// sweep that runs the plan (solver/sweep/sweep_plan.hpp). Each axis is a non-empty array
// of distinct numbers within the bounds below, the same bounds a case file's params obey.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "formats/parameter_point.hpp"

namespace rbcal::formats {

struct AxisBounds {
  double lo, hi;  // closed
};
inline constexpr AxisBounds kPhiBounds{1e-4, 0.7};               // volume fraction
inline constexpr AxisBounds kCapillaryNumberBounds{1e-6, 1e3};   // Ca
inline constexpr AxisBounds kViscosityRatioBounds{1e-3, 1e3};    // lambda

struct ParameterGrid {
  std::vector<double> phi;               // volume fractions
  std::vector<double> capillary_number;  // Ca
  std::vector<double> viscosity_ratio;   // lambda
  // A listed design ("points"): its points, in the file's order; the axes above then hold
  // the distinct values that occur. Empty for a grid.
  std::vector<ParameterPoint> listed;
  bool is_listed() const { return !listed.empty(); }
  std::size_t size() const {
    return is_listed() ? listed.size() : phi.size() * capillary_number.size() * viscosity_ratio.size();
  }
  // The plan's points: the listed ones, or the grid lambda-major, then Ca, then phi.
  std::vector<ParameterPoint> points() const;
};

// Checks the top level (an object of schema "rbcal.plan/1") and the grid; FormatError
// names the source and the field.
ParameterGrid plan_grid_from_json(const nlohmann::json& plan, const std::string& source);
// A plan may instead name case files ("case_files": [...], solver/sweep/sweep_plan.hpp): it
// has no grid, and its cases' own values span the library.
inline bool names_case_files(const nlohmann::json& plan) { return plan.is_object() && plan.contains("case_files"); }

}  // namespace rbcal::formats
