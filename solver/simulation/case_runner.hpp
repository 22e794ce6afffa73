#pragma once
// Runs one simulation case to its end strain and writes its outputs into a folder:
//   result.json  the case, the derived lattice values, the results (docs/reference.md)
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
// A folder that already holds a run (a checkpoint, a series or a result) is refused unless
// the run resumes it or overwrite is set, and a run holds a lock on its folder
// (OUT/.run.lock, flock: released by the kernel however the run ends), so that two runs
// never write one folder.
#include <iosfwd>
#include <nlohmann/json.hpp>
#include <string>

#include "solver/device/device_stepper.hpp"
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
  bool overwrite = false;  // start afresh in a folder that holds a run, discarding it
  Backend backend = Backend::Cpu;  // Device: every step on the device path (a GPU in a CUDA build)
  // The fluid update's prefetch distance (FluidConfig::prefetch_distance; the results are
  // the same at any). Negative: the fastest on this host and lattice, timed at the start of
  // the run (40 samples of at least 10 ms, the state untouched), so that a run resumed on
  // another host gets that host's best; lattices under
  // ShearFlowSimulation::kPrefetchTimingNodes keep the default untimed.
  int prefetch_distance = -1;
};

// Returns the result JSON (also written to result.json), or, when max_steps or a signal
// stopped the run early, {"status": "interrupted", "strain": ..., "checkpoint": ..., "signal":
// N} with the checkpoint written (signal 0: max_steps). Throws std::runtime_error for a
// folder that holds a run (see above) or that another run holds.
nlohmann::json run_case(const SimulationCase& c, const RunOptions& options);

}  // namespace rbcal::solver
