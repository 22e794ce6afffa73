#include "solver/sweep/sweep_runner.hpp"

#include "formats/write_error.hpp"

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <ostream>
#include <sstream>
#include <stdexcept>

#include "formats/json_file.hpp"
#include "formats/library_schema.hpp"
#include "formats/write_error.hpp"
#include "solver/io/detail/format_duration.hpp"
#include "solver/simulation/case_runner.hpp"
#include "solver/simulation/window_drift.hpp"
#include "solver/sweep/detail/case_claim.hpp"

namespace rbcal::solver {

namespace fs = std::filesystem;

namespace {

// "window drifts +9.4 % (3.3 sd); " where the finished case's window is not stationary.
std::string drift_note(const nlohmann::json& result) {
  const WindowDrift d = drift_of_result(result);
  if (!drifts(d)) return "";
  std::ostringstream s;
  s << std::showpos << std::fixed << std::setprecision(1) << "window drifts " << 100.0 * d.drift << " % ("
    << std::noshowpos << std::abs(d.z()) << " sd); ";
  return s.str();
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + p.string());
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// The library remembers its plan; a different plan on the same folder is refused,
// since its cases would not belong together.
void record_plan(const SweepPlan& plan, const fs::path& lib) {
  const fs::path stored = formats::library_layout::plan(lib);
  if (fs::exists(stored)) {
    nlohmann::json old;
    try {
      old = formats::read_json_file(stored);
    } catch (const std::invalid_argument& e) {
      throw std::runtime_error(std::string(e.what()) + "; remove it to adopt " + plan.source);
    }
    if (old != plan.document)
      throw std::runtime_error(plan.source + " differs from the plan of the library " + stored.string() +
                               "; use another library folder");
    return;
  }
  formats::write_json_atomically(stored, plan.document);
}

bool finished(const fs::path& lib, const std::string& id) {
  return fs::exists(formats::library_layout::case_result(lib, id));
}

// Runs (or resumes) one case. A run that the node guard stopped at a coupling interval above 1
// continues at interval 1 from its last checkpoint, as `rbcal simulate --resume
// --coupling-interval 1` does (equivalent numerics: docs/library.md), and stays at 1 when
// resumed later (its coupling_interval_changes.json says it switched).
nlohmann::json run_with_interval_fallback(const PlannedCase& pc, RunOptions ro, const SweepOptions& opt) {
  const fs::path work = ro.output_dir;
  if (fs::exists(work / "coupling_interval_changes.json")) ro.coupling_interval = 1;
  try {
    return run_case(pc.spec, ro);
  } catch (const formats::WriteError&) {
    throw;
  } catch (const std::runtime_error& e) {
    const bool unstable_above_1 = ro.coupling_interval != 1 && pc.spec.coupling_interval > 1 &&
                                  fs::exists(work / "checkpoint.bin") && fs::exists(work / "checkpoint_failed.bin");
    if (!unstable_above_1) throw;
    if (opt.progress)
      *opt.progress << "[" << opt.worker << "] " << pc.id << ": unstable at coupling interval "
                    << pc.spec.coupling_interval << " (" << e.what()
                    << "); continuing at 1 from the last checkpoint" << std::endl;
    ro.coupling_interval = 1;
    return run_case(pc.spec, ro);
  }
}

}  // namespace

SweepSummary run_sweep(const SweepPlan& plan, const SweepOptions& opt) {
  const fs::path lib(opt.library_dir);
  namespace layout = formats::library_layout;
  for (const fs::path& sub : {layout::cases(lib), layout::work(lib), layout::failed(lib)}) fs::create_directories(sub);
  record_plan(plan, lib);

  std::vector<std::size_t> order;
  if (opt.case_index >= 0) {
    if (static_cast<std::size_t>(opt.case_index) >= plan.cases.size())
      throw std::invalid_argument("case index " + std::to_string(opt.case_index) + " is outside the plan's " +
                                  std::to_string(plan.cases.size()) + " cases (0-based)");
    order.push_back(static_cast<std::size_t>(opt.case_index));
  } else {
    for (std::size_t i = 0; i < plan.cases.size(); ++i) order.push_back(i);
  }

  SweepSummary sum;
  sum.total = static_cast<int>(order.size());
  for (std::size_t i : order)
    if (finished(lib, plan.cases[i].id)) ++sum.already_done;
  if (opt.progress)
    *opt.progress << "[" << opt.worker << "] " << sum.already_done << " of " << sum.total << " cases already finished in "
                  << lib.string() << "\n";

  double seconds_spent = 0.0;
  for (std::size_t i : order) {
    const PlannedCase& pc = plan.cases[i];
    if (finished(lib, pc.id)) {
      // A worker killed right after publishing leaves its work folder and lock behind.
      const fs::path lock = formats::library_layout::work(lib) / (pc.id + ".lock");
      if (fs::exists(lock) || fs::exists(formats::library_layout::work(lib) / pc.id)) {
        CaseClaim claim(lock.string());
        if (claim.held()) {
          fs::remove_all(formats::library_layout::work(lib) / pc.id);
          fs::remove(lock);
        }
      }
      continue;
    }
    const fs::path failed = formats::library_layout::failed(lib) / (pc.id + ".txt");
    if (fs::exists(failed) && !opt.retry_failed) {
      ++sum.failed;
      continue;
    }
    CaseClaim claim((formats::library_layout::work(lib) / (pc.id + ".lock")).string());
    if (!claim.held()) {
      ++sum.claimed_elsewhere;
      continue;
    }
    if (finished(lib, pc.id)) continue;  // finished between the check and the claim
    const fs::path work = formats::library_layout::work(lib) / pc.id;
    const bool resuming = fs::exists(work / "checkpoint.bin");
    if (opt.progress)
      *opt.progress << "[" << opt.worker << "] case " << i << " " << pc.id << (resuming ? ": resuming" : ": starting")
                    << std::endl;
    RunOptions ro;
    ro.output_dir = work.string();
    ro.resume = true;
    ro.progress = opt.progress;
    ro.progress_seconds = opt.progress_seconds;
    ro.backend = opt.backend;
    const auto t0 = std::chrono::steady_clock::now();
    nlohmann::json result;
    try {
      result = run_with_interval_fallback(pc, ro, opt);
    } catch (const formats::WriteError&) {
      throw;  // the machine's failure, not the case's: the sweep stops, and the case runs again later
    } catch (const std::exception& e) {
      formats::write_file_atomically(failed, std::string(e.what()) + "\n");
      ++sum.failed;
      if (opt.progress) *opt.progress << "[" << opt.worker << "] case " << pc.id << " FAILED: " << e.what() << std::endl;
      continue;
    }
    if (!result.contains("result")) {
      sum.interrupted = true;
      if (opt.progress) *opt.progress << "[" << opt.worker << "] stopped; " << pc.id << " resumes from its checkpoint\n";
      return sum;
    }
    // Publish: the series first, the result JSON last (its presence means finished).
    formats::write_file_atomically(formats::library_layout::case_series(lib, pc.id), slurp(work / "series.csv"));
    fs::rename(work / "result.json", formats::library_layout::case_result(lib, pc.id));
    fs::remove(failed);
    fs::remove_all(work);
    fs::remove(formats::library_layout::work(lib) / (pc.id + ".lock"));
    ++sum.finished;
    seconds_spent += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (opt.progress) {
      int left = 0;
      for (std::size_t k : order) left += finished(lib, plan.cases[k].id) ? 0 : 1;
      const double eta = seconds_spent / sum.finished * left / std::max(1, opt.workers);
      const auto& r = result["result"];
      *opt.progress << "[" << opt.worker << "] finished " << pc.id << ": eta_re = " << r["eta_re"].get<double>() << " +- "
                    << r["eta_re_sem"].get<double>() << " (" << format_duration(r["wall_seconds"].get<double>()) << "); "
                    << drift_note(r) << left << " cases left, sweep ETA " << format_duration(eta) << std::endl;
    }
  }
  return sum;
}

}  // namespace rbcal::solver
