#include "formats/plan_grid.hpp"

#include <set>

#include "formats/field_reader.hpp"
#include "formats/json_file.hpp"
#include "formats/library_schema.hpp"
#include "formats/short_number.hpp"

namespace rbcal::formats {

namespace {

std::vector<double> axis(const FieldReader& r, const std::string& field, AxisBounds bounds) {
  const nlohmann::json& a = r.require(field);
  const std::string what = "must be a non-empty array of numbers";
  if (!a.is_array() || a.empty()) r.fail(field, what);
  std::vector<double> out;
  std::set<double> seen;
  for (const auto& v : a) {
    if (!v.is_number()) r.fail(field, what);
    const double x = v.get<double>();
    if (!(x >= bounds.lo && x <= bounds.hi))
      r.fail(field, "values must lie in [" + short_number(bounds.lo) + ", " + short_number(bounds.hi) + "], got " + short_number(x));
    if (!seen.insert(x).second) r.fail(field, "value " + short_number(x) + " appears twice");
    out.push_back(x);
  }
  return out;
}

}  // namespace

ParameterGrid plan_grid_from_json(const nlohmann::json& plan, const std::string& source) {
  FieldReader r(plan, source);
  if (!plan.is_object()) r.fail("(top level)", "must be a JSON object");
  const std::string schema = r.text("schema");
  if (schema != kPlanSchema) r.fail("schema", std::string("must be \"") + kPlanSchema + "\", got \"" + schema + "\"");
  if (!r.require("grid").is_object()) r.fail("grid", "must be an object with arrays phi, Ca, lambda");
  ParameterGrid g;
  g.phi = axis(r, "grid.phi", kPhiBounds);
  g.capillary_number = axis(r, "grid.Ca", kCapillaryNumberBounds);
  g.viscosity_ratio = axis(r, "grid.lambda", kViscosityRatioBounds);
  return g;
}

ParameterGrid read_plan_grid(const std::filesystem::path& plan_file) {
  return plan_grid_from_json(read_json_file(plan_file), plan_file.string());
}

}  // namespace rbcal::formats
