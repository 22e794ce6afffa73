#pragma once
// Runs the cases of a sweep plan into a library folder (docs/reference.md, "Library folder"):
//   LIB/plan.json         the plan (a library belongs to one plan: checked on every start)
//   LIB/cases/ID.json     finished case: the solver's result JSON, published last by rename
//   LIB/cases/ID.csv      its time series
//   LIB/work/ID/          a case in progress: outputs and checkpoint.bin (resumed)
//   LIB/work/ID.lock      the claim of the worker running it (see case_claim.hpp)
//   LIB/failed/ID.txt     a case the solver stopped (guard), with the message
// Any number of workers (threads of `--jobs`, MPI ranks, array jobs) may run the same
// plan on the same folder at once: each takes the next unclaimed, unfinished case. A
// worker killed at any moment leaves its case in work/, and the next worker to claim it
// resumes from its checkpoint, so every case is finished exactly once and no finished
// file is ever half-written.
#include <iosfwd>
#include <string>

#include "solver/device/device_stepper.hpp"

#include "solver/sweep/sweep_plan.hpp"

namespace rbcal::solver {

struct SweepOptions {
  std::string library_dir;
  int case_index = -1;                // >= 0: only this case (scheduler array index)
  std::string worker = "worker";      // name in progress lines
  int workers = 1;                    // how many run at once (for the ETA)
  bool retry_failed = false;          // run cases recorded in failed/ again
  std::ostream* progress = nullptr;   // per-case lines and the solver's progress
  double progress_seconds = 60.0;     // between the solver's progress lines
  Backend backend = Backend::Cpu;     // Device: each case on the device path (a GPU host)
};

struct SweepSummary {
  int total = 0;            // cases in the plan (or 1 with case_index)
  int already_done = 0;     // finished before this worker started
  int finished = 0;         // finished by this worker
  int failed = 0;           // stopped by a solver guard (this worker, or recorded before)
  int claimed_elsewhere = 0;  // running in another worker
  bool interrupted = false;   // SIGINT / SIGTERM: stopped with a checkpoint
};

SweepSummary run_sweep(const SweepPlan& plan, const SweepOptions& options);

}  // namespace rbcal::solver
