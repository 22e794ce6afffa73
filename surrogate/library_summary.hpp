#pragma once
// What `rbcal library show` prints: how many cases, their parameter ranges, cost, typical
// statistical error, and which points of the grid (the plan's, or else the one spanned by
// the cases' own parameter values) are present or missing.
#include <string>
#include <vector>

#include "surrogate/simulation_library.hpp"
#include "surrogate/viscosity_model.hpp"

namespace rbcal::surrogate {

struct GridPoint : ParameterPoint {
  bool present = false;  // a finished case has these nominal parameters
  double eta_re = 0.0;   // its result, when present
};

struct LibrarySummary {
  std::string root;
  std::size_t case_count = 0;
  ParameterRange nominal_range;        // of params.{phi, Ca, lambda}
  double phi_actual_min = 0.0, phi_actual_max = 0.0;
  double eta_re_min = 0.0, eta_re_max = 0.0;
  double total_wall_seconds = 0.0;
  double median_eta_re_sem = 0.0;           // absolute
  double median_relative_eta_re_sem = 0.0;  // eta_re_sem / eta_re
  bool grid_from_plan = false;              // false: grid spanned by the cases' own values
  bool listed_design = false;               // the plan lists its points, or (without a plan) the cases do
                                            // not fill a grid: grid_points are those points
  ParameterGrid grid;
  std::vector<GridPoint> grid_points;       // phi slowest, lambda fastest
  std::size_t missing_count = 0;
  std::size_t off_grid_count = 0;           // cases whose parameters are not on the plan's grid
  // An extrapolated library (`rbcal library extrapolate`): every case with its raw values.
  std::vector<LibraryCase> extrapolated;
};

LibrarySummary summarise(const SimulationLibrary& library);

// Human-readable report: totals, ranges, then one block per lambda with a phi x Ca table
// marking present ('x') and missing ('.') points, or with values: each present point's
// eta_re (to read the trends in phi, Ca and lambda).
std::string format_summary(const LibrarySummary& summary, bool values = false);

}  // namespace rbcal::surrogate
