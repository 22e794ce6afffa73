#include "formats/plan_grid.hpp"

#include <algorithm>
#include <set>
#include <tuple>

#include "formats/field_reader.hpp"
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

double bounded(const FieldReader& r, const std::string& field, const nlohmann::json& v, AxisBounds bounds,
               const char* name) {
  if (!v.is_number()) r.fail(field, std::string(name) + " must be a number");
  const double x = v.get<double>();
  if (!(x >= bounds.lo && x <= bounds.hi))
    r.fail(field, std::string(name) + " must lie in [" + short_number(bounds.lo) + ", " + short_number(bounds.hi) +
                      "], got " + short_number(x));
  return x;
}

std::vector<double> distinct_sorted(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
  return v;
}

// "points": [[phi, Ca, lambda], ...], each within the axis bounds, none twice.
ParameterGrid listed_points(const FieldReader& r) {
  const nlohmann::json& a = r.require("points");
  if (!a.is_array() || a.empty()) r.fail("points", "must be a non-empty array of [phi, Ca, lambda]");
  ParameterGrid g;
  std::set<std::tuple<double, double, double>> seen;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const std::string field = "points." + std::to_string(i);
    if (!a[i].is_array() || a[i].size() != 3) r.fail(field, "must be [phi, Ca, lambda]");
    const ParameterPoint p{bounded(r, field, a[i][0], kPhiBounds, "phi"), bounded(r, field, a[i][1], kCapillaryNumberBounds, "Ca"),
                      bounded(r, field, a[i][2], kViscosityRatioBounds, "lambda")};
    if (!seen.insert({p.phi, p.capillary_number, p.viscosity_ratio}).second) r.fail(field, "appears twice");
    g.listed.push_back(p);
    g.phi.push_back(p.phi);
    g.capillary_number.push_back(p.capillary_number);
    g.viscosity_ratio.push_back(p.viscosity_ratio);
  }
  g.phi = distinct_sorted(g.phi);
  g.capillary_number = distinct_sorted(g.capillary_number);
  g.viscosity_ratio = distinct_sorted(g.viscosity_ratio);
  return g;
}

}  // namespace

std::vector<ParameterPoint> ParameterGrid::points() const {
  if (is_listed()) return listed;
  std::vector<ParameterPoint> out;
  for (double lambda : viscosity_ratio)
    for (double ca : capillary_number)
      for (double p : phi) out.push_back({p, ca, lambda});
  return out;
}

ParameterGrid plan_grid_from_json(const nlohmann::json& plan, const std::string& source) {
  FieldReader r(plan, source);
  r.expect_schema(kPlanSchema);
  const bool has_grid = r.find("grid") != nullptr, has_points = r.find("points") != nullptr;
  if (has_grid && has_points) r.fail("points", "a plan has a grid or points, not both");
  if (has_points) return listed_points(r);
  if (!r.require("grid").is_object()) r.fail("grid", "must be an object with arrays phi, Ca, lambda (or give points)");
  ParameterGrid g;
  g.phi = axis(r, "grid.phi", kPhiBounds);
  g.capillary_number = axis(r, "grid.Ca", kCapillaryNumberBounds);
  g.viscosity_ratio = axis(r, "grid.lambda", kViscosityRatioBounds);
  return g;
}

}  // namespace rbcal::formats
