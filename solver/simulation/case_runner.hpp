#pragma once
// Runs one simulation case to its end strain and writes its outputs into a folder:
//   result.json  the case, the derived lattice values, the results (DESIGN.md section 4)
//                and provenance; written atomically (temporary file + rename)
//   series.csv   one row per record interval: strain, eta_re (stresslet and wall), shape
//                of the first cell, volume error, node Mach number
//   vtk/         membranes (.vtp) and fluid (.vti) snapshots with a .pvd index
// Progress with an ETA goes to a stream. Stops with a message naming the quantity, the
// cell and the step if the state turns non-finite or the Mach number exceeds 0.3.
#include <iosfwd>
#include <nlohmann/json.hpp>
#include <string>

#include "solver/simulation/simulation_case.hpp"

namespace rbcal::solver {

struct RunOptions {
  std::string output_dir;
  std::ostream* progress = nullptr;  // null: silent
  double progress_seconds = 5.0;     // between progress lines
};

nlohmann::json run_case(const SimulationCase& c, const RunOptions& options);

// Writes text to path via a temporary file and a rename, so that readers never see a
// half-written file.
void write_file_atomically(const std::string& path, const std::string& text);

}  // namespace rbcal::solver
