#include "solver/sweep/sweep_plan.hpp"

#include <algorithm>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>

#include "solver/io/json_file.hpp"
#include "solver/lattice_units.hpp"

namespace rbcal::solver {

namespace {

std::string short_number(double v) {
  std::ostringstream s;
  s.precision(6);
  s << v;
  return s.str();
}

std::vector<double> grid_axis(const nlohmann::json& plan, const std::string& name, double lo, double hi,
                              const std::string& path) {
  const std::string field = "grid." + name;
  auto fail = [&](const std::string& what) { throw std::invalid_argument(path + ": field " + field + ": " + what); };
  if (!plan.contains("grid") || !plan["grid"].is_object()) throw std::invalid_argument(path + ": field grid: is missing");
  const auto it = plan["grid"].find(name);
  if (it == plan["grid"].end()) fail("is missing");
  if (!it->is_array() || it->empty()) fail("must be a non-empty array of numbers");
  std::vector<double> out;
  std::set<double> seen;
  for (const auto& v : *it) {
    if (!v.is_number()) fail("must be a non-empty array of numbers");
    const double x = v.get<double>();
    if (!(x >= lo && x <= hi)) fail("values must lie in [" + short_number(lo) + ", " + short_number(hi) + "], got " + short_number(x));
    if (!seen.insert(x).second) fail("value " + short_number(x) + " appears twice");
    out.push_back(x);
  }
  return out;
}

}  // namespace

std::string case_id(double phi, double capillary_number, double viscosity_ratio) {
  return "phi" + short_number(phi) + "_Ca" + short_number(capillary_number) + "_lambda" + short_number(viscosity_ratio);
}

SweepPlan read_sweep_plan(const std::string& path) {
  const nlohmann::json j = read_json_file(path, "plan file");
  if (!j.is_object()) throw std::invalid_argument(path + ": field (top level): must be a JSON object");
  if (j.value("schema", std::string()) != "rbcal.plan/1")
    throw std::invalid_argument(path + ": field schema: must be \"rbcal.plan/1\"");
  SweepPlan plan;
  plan.source = path;
  plan.document = j;
  if (j.contains("description")) {
    if (!j["description"].is_string()) throw std::invalid_argument(path + ": field description: must be a string");
    plan.description = j["description"].get<std::string>();
  }
  plan.phi = grid_axis(j, "phi", 1e-4, 0.7, path);
  plan.capillary_numbers = grid_axis(j, "Ca", 1e-6, 1e3, path);
  plan.viscosity_ratios = grid_axis(j, "lambda", 1e-3, 1e3, path);
  if (!j.contains("base") || !j["base"].is_object()) throw std::invalid_argument(path + ": field base: must be an object (a case without params)");
  nlohmann::json base = j["base"];
  if (base.contains("cells") && base["cells"].contains("placements"))
    throw std::invalid_argument(path + ": field base.cells.placements: a sweep seeds its cells for each phi; remove the placements");
  base["schema"] = "rbcal.case/1";
  double max_modulus = 0.0;  // 0: every case keeps the base Reynolds number
  if (j.contains("max_shear_modulus_lattice")) {
    const auto& g = j["max_shear_modulus_lattice"];
    if (!g.is_number() || !(g.get<double>() > 0.0))
      throw std::invalid_argument(path + ": field max_shear_modulus_lattice: must be a positive number");
    max_modulus = g.get<double>();
  }
  for (double lambda : plan.viscosity_ratios)
    for (double ca : plan.capillary_numbers)
      for (double phi : plan.phi) {
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
        plan.cases.push_back({case_id(phi, ca, lambda), std::move(spec)});
      }
  return plan;
}

}  // namespace rbcal::solver
