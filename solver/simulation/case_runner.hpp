#pragma once
// Runs one simulation case to its end strain and writes its outputs into a folder:
//   result.json  the case, the derived lattice values, the results (DESIGN.md section 4)
//                and provenance; written atomically (temporary file + rename)
//   series.csv   one row per record interval: strain, eta_re (stresslet and wall), shape
//                of the first cell, volume error, node Mach number
//   vtk/         membranes (.vtp) and fluid (.vti) snapshots with a .pvd index
//   checkpoint.bin  the latest checkpoint (every run.checkpoint_interval of strain)
// Progress with an ETA goes to a stream. Stops with a message naming the quantity, the
// cell and the step if the state turns non-finite or the Mach number exceeds 0.3, after
// writing checkpoint_failed.bin. With resume, a run continues from checkpoint.bin: the
// series is cut back to the checkpoint and the averages rebuilt from it, so a run killed
// at any moment loses at most the work since its last checkpoint. SIGINT and SIGTERM
// (Ctrl-C, a scheduler's warning) stop the run after the current step with a checkpoint.
#include <iosfwd>
#include <nlohmann/json.hpp>
#include <string>

#include "solver/simulation/simulation_case.hpp"

namespace rbcal::solver {

struct RunOptions {
  std::string output_dir;
  std::ostream* progress = nullptr;  // null: silent
  double progress_seconds = 5.0;     // between progress lines
  bool resume = false;               // continue from output_dir/checkpoint.bin if present
  std::int64_t max_steps = 0;        // stop after this many steps, with a checkpoint (0: run to the end)
  // > 0: advance the membrane every this many fluid steps instead of the case's
  // numerics.coupling_interval, and resume from a checkpoint written under another interval
  // (e.g. 1 after a late instability at 2). Each change is kept in
  // coupling_interval_changes.json and reported in result.json; the case block keeps the
  // case's own value.
  int coupling_interval = 0;
};

// Returns the result JSON (also written to result.json), or, when max_steps or a signal
// stopped the run early, {"status": "interrupted", "strain": ...} with the checkpoint written.
nlohmann::json run_case(const SimulationCase& c, const RunOptions& options);

}  // namespace rbcal::solver
