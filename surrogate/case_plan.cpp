#include "surrogate/case_plan.hpp"

#include <algorithm>
#include <cmath>

#include "surrogate/field_reader.hpp"
#include "surrogate/json_file.hpp"

namespace rbcal::surrogate {

namespace {

std::vector<double> axis(const FieldReader& r, const std::string& field, double lo, double hi) {
  std::vector<double> v = r.numbers(field, 1);
  for (double x : v)
    if (!(x > lo && x < hi)) r.fail(field, "values must be in (" + std::to_string(lo) + ", " + std::to_string(hi) + ")");
  return v;
}

std::vector<double> sorted_unique(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
  return v;
}

std::vector<double> with_midpoints(const std::vector<double>& axis_values, bool geometric) {
  const std::vector<double> v = sorted_unique(axis_values);
  std::vector<double> out;
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (i > 0) out.push_back(geometric ? std::sqrt(v[i - 1] * v[i]) : 0.5 * (v[i - 1] + v[i]));
    out.push_back(v[i]);
  }
  return out;
}

}  // namespace

ParameterGrid plan_grid_from_json(const nlohmann::json& j, const std::string& source) {
  FieldReader r(j, source);
  if (!j.is_object()) r.fail("(top level)", "must be a JSON object");
  const std::string schema = r.text("schema");
  if (schema != "rbcal.plan/1") r.fail("schema", "must be \"rbcal.plan/1\", got \"" + schema + "\"");
  ParameterGrid g;
  g.phi = axis(r, "grid.phi", 0.0, 1.0);
  g.capillary_number = axis(r, "grid.Ca", 0.0, HUGE_VAL);
  g.viscosity_ratio = axis(r, "grid.lambda", 0.0, HUGE_VAL);
  return g;
}

ParameterGrid read_plan_grid(const std::filesystem::path& plan_file) {
  return plan_grid_from_json(read_json_file(plan_file), plan_file.string());
}

ParameterGrid refined(const ParameterGrid& grid) {
  return {with_midpoints(grid.phi, false), with_midpoints(grid.capillary_number, true),
          with_midpoints(grid.viscosity_ratio, true)};
}

}  // namespace rbcal::surrogate
