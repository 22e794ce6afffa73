#pragma once
// One finished solver case of a simulation library, as read from LIB/cases/<id>.json
// (schema "rbcal.case/1", written by `rbcal simulate` / `rbcal library generate`).
// Only what the surrogate needs is kept; the case file itself stays the interface
// between solver/ and surrogate/ (docs/reference.md). All quantities dimensionless.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace rbcal::surrogate {

// A case's result at one resolution, kept by an extrapolated library (resolution_extrapolation.hpp).
struct ResolutionResult {
  int nodes_per_radius = 0;
  double eta_re = 0.0;
  double eta_re_sem = 0.0;
};

struct LibraryCase {
  std::string id;                  // file stem, e.g. "phi0.20_Ca0.10_lam5"
  std::filesystem::path source;    // the case file it was read from
  // Nominal parameters (params.*); phi falls back to result.phi_actual when the case
  // places its cells explicitly and has no params.phi.
  double phi = 0.0;
  double capillary_number = 0.0;   // Ca = eta0 gamma_dot a / G_s
  double viscosity_ratio = 0.0;    // lambda = eta1 / eta0
  // Results (result.*).
  double phi_actual = 0.0;         // volume fraction of the seeded cells: the surrogate's input
  double eta_re = 0.0;             // relative viscosity from the stresslet
  double eta_re_sem = 0.0;         // its standard error (autocorrelation-aware)
  double eta_re_wall = 0.0;        // relative viscosity from the wall shear stress
  double eta_re_wall_sem = 0.0;
  long long n_cells = 0;
  long long steps = 0;
  double wall_seconds = 0.0;
  int nodes_per_radius = 0;        // numerics.N_a
  // Cases of an extrapolated library (key "extrapolation"): how eta_re was obtained
  // ("richardson" or "correction model") and the raw results it came from; empty otherwise.
  std::string extrapolation_method;
  std::vector<ResolutionResult> raw_results;
  // Cases moved to their effective volume fraction: the phi they were run at (0 otherwise), and
  // the run's own error (standard error and seed scatter, without the offset's share that
  // eta_re_sem carries there; 0: not given, eta_re_sem is the run's own).
  double phi_as_run = 0.0;
  double run_sd = 0.0;
  // The numerics every case of one library must share (formats::numerics_signature).
  nlohmann::json numerics_signature;
};

// Schema-checks a parsed case; errors read "SOURCE: field result.eta_re_sem: must be ...".
LibraryCase library_case_from_json(const nlohmann::json& j, const std::filesystem::path& source);

// Reads and checks one case file; malformed JSON is reported with the file and position.
LibraryCase read_library_case(const std::filesystem::path& file);

}  // namespace rbcal::surrogate
