#pragma once
// A sweep plan: one base case and a grid (or a list) of (phi, Ca, lambda); each point is one
// library case. File format (schema "rbcal.plan/1"):
//   {"schema": "rbcal.plan/1", "description": "...",
//    "grid": {"phi": [...], "Ca": [...], "lambda": [...]}   (or "points": [[phi, Ca, lambda], ...]),
//    "base": {cells, numerics, run, params.kb_hat: as in a case file (rbcal.case/1)},
//    "max_shear_modulus_lattice": G (optional)}
// With max_shear_modulus_lattice, each case's Reynolds number is lowered from the base
// value where needed so that G_s in lattice units, Re nu^2 / (N_a Ca), stays at or below
// G min(1, (1 + lambda) / 2): the explicit membrane coupling is unstable for stiff
// membranes, the more so the less viscous the cell's interior, which damps the membrane
// together with the plasma (docs/library.md). This keeps the time step small only for
// the low-Ca cases that need it.
// Cases are ordered lambda-major, then Ca, then phi (a listed plan: in the file's order),
// so the index of a case (for scheduler array jobs) is fixed by the plan.
// A plan may instead name case files, each run as `rbcal simulate` would run it (its id the
// file's stem), for cases no grid describes, e.g. the dense anchors:
//   {"schema": "rbcal.plan/1", "description": "...", "case_files": ["cases/a.json", ...]}
// (paths relative to the plan file; no base, grid or points then).
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "solver/simulation/simulation_case.hpp"

namespace rbcal::solver {

struct PlannedCase {
  std::string id;  // file-name-safe, e.g. "phi0.21_Ca0.1_lambda5"
  SimulationCase spec;
};

struct SweepPlan {
  std::string source;        // the plan file
  nlohmann::json document;   // its contents, as recorded in the library
  std::string description;
  std::vector<double> phi, capillary_numbers, viscosity_ratios;
  std::vector<PlannedCase> cases;
};

// Parses and checks a plan; errors name the file and the field. Every case is checked
// as a case file would be.
SweepPlan read_sweep_plan(const std::string& path);
// The same for a parsed plan; source names it in errors and in SweepPlan::source.
SweepPlan sweep_plan_from_json(const nlohmann::json& plan, const std::string& source);

}  // namespace rbcal::solver
