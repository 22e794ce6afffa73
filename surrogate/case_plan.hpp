#pragma once
// The parameter grid of a library's plan (LIB/plan.json, schema "rbcal.plan/1"):
// {"schema": "rbcal.plan/1", "grid": {"phi": [...], "Ca": [...], "lambda": [...]}, ...}.
// Other keys of the plan (base case, numerics) belong to `library generate`; only the
// grid is read here.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <vector>

namespace rbcal::surrogate {

struct ParameterGrid {
  std::vector<double> phi;               // volume fractions, each in (0, 1)
  std::vector<double> capillary_number;  // Ca, each > 0
  std::vector<double> viscosity_ratio;   // lambda, each > 0
  std::size_t size() const { return phi.size() * capillary_number.size() * viscosity_ratio.size(); }
};

ParameterGrid plan_grid_from_json(const nlohmann::json& j, const std::string& source);
ParameterGrid read_plan_grid(const std::filesystem::path& plan_file);

// The grid with the midpoint inserted between neighbouring values of each axis (phi
// linearly, Ca and lambda geometrically); axes are sorted and de-duplicated first.
ParameterGrid refined(const ParameterGrid& grid);

}  // namespace rbcal::surrogate
