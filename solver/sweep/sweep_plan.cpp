#include "solver/sweep/sweep_plan.hpp"

#include <algorithm>
#include <filesystem>
#include <set>

#include "formats/field_reader.hpp"
#include "formats/json_file.hpp"
#include "formats/library_schema.hpp"
#include "formats/plan_grid.hpp"
#include "solver/lattice_units.hpp"

namespace rbcal::solver {

SweepPlan read_sweep_plan(const std::string& path) { return sweep_plan_from_json(formats::read_json_file(path), path); }

namespace {

// A plan of case files: each a case file as `rbcal simulate` reads it, its id the file's stem.
SweepPlan case_file_plan(const nlohmann::json& j, const std::string& path) {
  const formats::FieldReader r(j, path);
  r.expect_schema(formats::kPlanSchema);
  r.only_known_keys("", {"schema", "description", "case_files"});
  SweepPlan plan;
  plan.source = path;
  plan.document = j;
  plan.description = r.text_or("description", "");
  const nlohmann::json& list = r.require("case_files");
  if (!list.is_array() || list.empty()) r.fail("case_files", "must be a non-empty array of case files");
  const std::filesystem::path folder = std::filesystem::path(path).parent_path();
  std::set<std::string> ids;
  for (std::size_t i = 0; i < list.size(); ++i) {
    const std::string at = "case_files." + std::to_string(i);
    const std::filesystem::path file = folder / r.text(at);
    if (!std::filesystem::is_regular_file(file)) r.fail(at, "no such case file: " + file.string());
    const std::string id = file.stem().string();
    if (!ids.insert(id).second) r.fail(at, "a second case named " + id + " (ids are the files' stems)");
    plan.cases.push_back({id, read_case(file.string())});
  }
  return plan;
}

}  // namespace

SweepPlan sweep_plan_from_json(const nlohmann::json& j, const std::string& path) {
  if (formats::names_case_files(j)) return case_file_plan(j, path);
  const formats::ParameterGrid grid = formats::plan_grid_from_json(j, path);  // checks the schema too
  const formats::FieldReader r(j, path);
  SweepPlan plan;
  plan.source = path;
  plan.document = j;
  plan.description = r.text_or("description", "");
  plan.phi = grid.phi;
  plan.capillary_numbers = grid.capillary_number;
  plan.viscosity_ratios = grid.viscosity_ratio;
  if (!r.require("base").is_object()) r.fail("base", "must be an object (a case without params)");
  nlohmann::json base = j["base"];
  if (r.find("base.cells.placements"))
    r.fail("base.cells.placements", "a sweep seeds its cells for each phi; remove the placements");
  base["schema"] = formats::kCaseSchema;
  // 0: every case keeps the base Reynolds number.
  const double max_modulus =
      r.find("max_shear_modulus_lattice") ? r.positive("max_shear_modulus_lattice") : 0.0;
  for (const formats::ParameterPoint& point : grid.points()) {
    const double phi = point.phi, ca = point.capillary_number, lambda = point.viscosity_ratio;
    nlohmann::json c = base;
    c["params"]["phi"] = phi;
    c["params"]["Ca"] = ca;
    c["params"]["lambda"] = lambda;
    // Field errors from the case reader are reported as fields of base.
    SimulationCase spec = case_from_json(c, path + " (base)");
    if (max_modulus > 0.0) {
      // G_s in lattice units is proportional to Re at fixed Ca, N_a and tau_out.
      const double modulus = max_modulus * std::min(1.0, 0.5 * (1.0 + lambda));
      const double re_cap =
          spec.flow.reynolds_number * modulus / derive_lattice_units(spec.flow, spec.resolution).shear_modulus;
      if (re_cap < spec.flow.reynolds_number) {
        c["numerics"]["Re"] = re_cap;
        spec = case_from_json(c, path + " (base)");
      }
    }
    plan.cases.push_back({formats::case_id(phi, ca, lambda), std::move(spec)});
  }
  return plan;
}

}  // namespace rbcal::solver
