#include "solver/simulation/case_runner.hpp"

#include <array>
#include <chrono>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <cmath>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <memory>
#include <new>
#include <numbers>
#include <ostream>
#include <sstream>
#include <stdexcept>

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include "formats/json_file.hpp"
#include "formats/write_error.hpp"
#include "formats/provenance.hpp"
#include "solver/io/detail/format_duration.hpp"
#include "solver/io/detail/vtk_writer.hpp"
#include "solver/simulation/detail/block_average.hpp"
#include "solver/simulation/window_drift.hpp"
#include "solver/membrane/mesh_health.hpp"
#include "solver/simulation/cell_overlap.hpp"
#include "solver/simulation/detail/coupling_stability.hpp"
#include "solver/simulation/detail/memory_estimate.hpp"
#include "solver/simulation/shear_flow_simulation.hpp"
#include "solver/simulation/state_guards.hpp"

namespace rbcal::solver {

namespace fs = std::filesystem;

namespace {

// Set by SIGINT / SIGTERM to the signal's number: the run stops at the next step with a checkpoint.
volatile std::sig_atomic_t stop_requested = 0;
extern "C" void request_stop(int signal_number) { stop_requested = signal_number; }

// What of an earlier run a folder holds (empty: nothing).
std::string earlier_run_in(const fs::path& folder) {
  for (const char* name : {"checkpoint.bin", "result.json", "series.csv"})
    if (fs::exists(folder / name)) return (folder / name).string();
  return "";
}

// An exclusive lock on OUT/.run.lock for the run's lifetime; the kernel drops it when the
// process ends, however it ends.
class FolderLock {
 public:
  explicit FolderLock(const fs::path& folder) {
    const fs::path path = folder / ".run.lock";
    fd_ = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd_ < 0) throw std::runtime_error("cannot open " + path.string() + ": " + std::strerror(errno));
    if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
      const int err = errno;
      ::close(fd_);
      if (err == EWOULDBLOCK)
        throw std::runtime_error(folder.string() + " is in use by another run (it holds " + path.string() +
                                 "); give each run its own output folder");
      throw std::runtime_error("cannot lock " + path.string() + ": " + std::strerror(err));
    }
  }
  ~FolderLock() { ::close(fd_); }
  FolderLock(const FolderLock&) = delete;
  FolderLock& operator=(const FolderLock&) = delete;

 private:
  int fd_ = -1;
};

// Creates the folder and takes its lock, after refusing to start afresh over a run.
std::unique_ptr<FolderLock> claim_output_folder(const RunOptions& opt) {
  if (opt.output_dir.empty()) throw std::invalid_argument("run_case: no output folder");
  fs::create_directories(opt.output_dir);
  auto lock = std::make_unique<FolderLock>(opt.output_dir);
  const std::string earlier = earlier_run_in(opt.output_dir);
  if (!earlier.empty() && !opt.resume && !opt.overwrite)
    throw std::runtime_error(opt.output_dir + " holds a run (" + earlier +
                             "): give --resume to continue it, --overwrite to discard it, or another output folder");
  if (opt.overwrite && !opt.resume)
    for (const char* name : {"checkpoint.bin", "checkpoint_failed.bin", "result.json", "series.csv"})
      fs::remove(fs::path(opt.output_dir) / name);
  return lock;
}

// SIGINT and SIGTERM request a stop while a run is in progress; the previous handlers
// come back when it ends, however it ends.
class StopOnSignals {
 public:
  StopOnSignals() : int_(std::signal(SIGINT, request_stop)), term_(std::signal(SIGTERM, request_stop)) {
    stop_requested = 0;
  }
  ~StopOnSignals() {
    std::signal(SIGINT, int_);
    std::signal(SIGTERM, term_);
  }
  StopOnSignals(const StopOnSignals&) = delete;
  StopOnSignals& operator=(const StopOnSignals&) = delete;

 private:
  void (*int_)(int);
  void (*term_)(int);
};

// The samples inside the averaging window, per observable.
struct WindowSamples {
  std::array<double, 2> window;
  std::vector<double> stresslet, wall, deformation, angle;
  void keep(double strain, double eta_s, double eta_w, double d, double a) {
    if (strain < window[0] - 1e-9 || strain > window[1] + 1e-9) return;
    stresslet.push_back(eta_s);
    wall.push_back(eta_w);
    deformation.push_back(d);
    angle.push_back(a);
  }
};

SimulationCase with_coupling_interval(SimulationCase c, int interval) {
  if (interval > 0) c.coupling_interval = interval;
  return c;
}

// One case from its first (or resumed) step to its result, as a sequence of named steps
// (the shape of Ceres' trust-region minimizer): schedule, resume, record, snapshot,
// checkpoint, progress, result.
class CaseRun {
 public:
  CaseRun(const SimulationCase& c, const RunOptions& opt)
      : c_(c),
        opt_(opt),
        start_(std::chrono::steady_clock::now()),
        sim_(with_coupling_interval(c, opt.coupling_interval), opt.backend),
        window_{c.window, {}, {}, {}, {}} {
    const double gamma = sim_.units().shear_rate;
    auto every = [&](double strain) { return std::max<std::int64_t>(1, std::llround(strain / gamma)); };
    total_steps_ = static_cast<std::int64_t>(std::ceil(c.strain_end / gamma - 1e-9));
    record_every_ = every(c.record_interval);
    vtk_every_ = c.vtk_interval > 0 ? every(c.vtk_interval) : 0;
    checkpoint_every_ = c.checkpoint_interval > 0 ? every(c.checkpoint_interval) : 0;
  }

  nlohmann::json run() {
    prefetch_ = sim_.set_prefetch_distance(opt_.prefetch_distance);
    announce();
    const bool resuming = opt_.resume && fs::exists(checkpoint_path());
    if (!resuming) start_interval_changes();
    const std::string kept_rows = resuming ? resume() : "";
    open_series(kept_rows);
    if (vtk_every_) fs::create_directories(opt_.output_dir + "/vtk");
    if (vtk_every_ && first_step_ == 1) snapshot(0);
    const StopOnSignals stop_on_signals;
    last_report_ = std::chrono::steady_clock::now();
    for (std::int64_t step = first_step_; step <= total_steps_; ++step) {
      advance(step);
      if (step % record_every_ == 0 || step == total_steps_) record(step);
      if (vtk_every_ && step % vtk_every_ == 0) snapshot(step);
      const bool stop_now = step < total_steps_ && (stop_requested || (opt_.max_steps > 0 &&
                                                                        step - first_step_ + 1 >= opt_.max_steps));
      if ((checkpoint_every_ && step % checkpoint_every_ == 0) || stop_now) {
        flush_series();
        sim_.save_checkpoint(checkpoint_path());
      }
      if (stop_now)
        return {{"status", "interrupted"}, {"strain", sim_.strain()}, {"checkpoint", checkpoint_path()},
                {"signal", static_cast<int>(stop_requested)}};
      report_progress(step);
    }
    flush_series();
    series_.close();
    return result();
  }

 private:
  std::string checkpoint_path() const { return opt_.output_dir + "/checkpoint.bin"; }
  std::string interval_changes_path() const { return opt_.output_dir + "/coupling_interval_changes.json"; }

  // A fresh run forgets earlier changes, and records its own if it overrides the case.
  void start_interval_changes() const {
    fs::remove(interval_changes_path());
    const int interval = sim_.simulation_case().coupling_interval;
    if (interval != c_.coupling_interval)
      formats::write_json_atomically(interval_changes_path(),
                                     nlohmann::json::array({{{"at_strain", 0.0}, {"from", c_.coupling_interval},
                                                             {"to", interval}}}));
  }

  // The changes of coupling interval made on resuming, oldest first (empty: none).
  nlohmann::json interval_changes() const {
    return fs::exists(interval_changes_path()) ? formats::read_json_file(interval_changes_path())
                                               : nlohmann::json::array();
  }
  std::string series_path() const { return opt_.output_dir + "/series.csv"; }
  // The rows so far on disk; a failed write (a full disk) stops the run as a write error.
  void flush_series() {
    series_.flush();
    if (!series_) throw formats::WriteError("error while writing " + series_path() + ": " + std::strerror(errno));
  }

  void announce() const {
    if (!opt_.progress) return;
    const LatticeUnits& u = sim_.units();
    *opt_.progress << "  " << sim_.positions().size() << " cells, phi = " << phi_actual() << ", lattice " << u.nx
                   << " x " << u.ny << " x " << u.nz << ", " << total_steps_ << " steps\n";
    if (c_.coupling_interval_chosen && opt_.coupling_interval == 0)
      *opt_.progress << "  coupling interval " << c_.coupling_interval << " (auto: K_s,lu (sum phi^2)^3 = "
                     << coupling_stiffness(c_) << " per step of interval, bound " << kCouplingStabilityBound << ")\n";
    // A given interval (or 1 from auto) beyond the measured bound: the run will likely stop at
    // the node Mach guard, so say why before it starts.
    const int interval = opt_.coupling_interval > 0 ? opt_.coupling_interval : c_.coupling_interval;
    if (!within_coupling_bound(c_, interval))
      *opt_.progress << "  warning: coupling interval " << interval << " is beyond the measured stability bound: K_s,lu k"
                     << " (sum phi^2)^3 = " << interval * coupling_stiffness(c_) << " > " << kCouplingStabilityBound
                     << " (docs/performance.md, \"Stability of the explicit coupling\"); expect the node Mach guard to stop"
                     << " the run\n";
    if (opt_.backend == Backend::Cpu)
      *opt_.progress << "  fluid update prefetch " << prefetch_.distance << " populations ahead"
                     << (prefetch_.timed                     ? " (timed on this host)"
                         : opt_.prefetch_distance < 0 ? " (the default: a lattice too small to time)"
                                                      : "")
                     << "\n";
  }

  // Restores the checkpoint and returns the series rows up to it (later ones are recomputed),
  // with their window samples kept.
  std::string resume() {
    const int saved_interval = sim_.restore_checkpoint(checkpoint_path(), opt_.coupling_interval > 0);
    first_step_ = sim_.steps_done() + 1;
    const int interval = sim_.simulation_case().coupling_interval;
    // Changes recorded at or after this checkpoint belong to a stretch that is now run
    // again (a run that failed after a switch resumes from the same checkpoint).
    nlohmann::json changes = nlohmann::json::array();
    for (const auto& change : interval_changes())
      if (change.value("at_strain", 0.0) < sim_.strain() - 1e-9) changes.push_back(change);
    const bool dropped = changes.size() != interval_changes().size();
    if (dropped) formats::write_json_atomically(interval_changes_path(), changes);
    if (saved_interval != interval) {
      changes.push_back({{"at_strain", sim_.strain()}, {"from", saved_interval}, {"to", interval}});
      formats::write_json_atomically(interval_changes_path(), changes);
      if (opt_.progress)
        *opt_.progress << "  coupling interval " << saved_interval << " -> " << interval << " from strain "
                       << sim_.strain() << "\n";
    }
    // A finished run continued to a later strain_end recorded its last step as its end;
    // that row stays only where this case records the same step.
    const std::int64_t done = first_step_ - 1;
    const bool keep_row_at_checkpoint = done % record_every_ == 0 || done == total_steps_;
    std::ifstream old(series_path());
    std::string line, kept;
    std::getline(old, line);
    while (std::getline(old, line)) {
      std::vector<double> v;
      std::stringstream ss(line);
      std::string cell;
      while (std::getline(ss, cell, ',')) v.push_back(std::stod(cell));
      if (v.size() < 5 || v[0] > sim_.strain() + 1e-9) break;
      if (!keep_row_at_checkpoint && v[0] > sim_.strain() - 1e-9) break;
      window_.keep(v[0], v[1], v[2], v[3], v[4]);
      kept += line + "\n";
    }
    if (opt_.progress) *opt_.progress << "  resuming from " << checkpoint_path() << " at strain " << sim_.strain() << "\n";
    return kept;
  }

  void open_series(const std::string& kept_rows) {
    series_.open(series_path(), std::ios::trunc);
    if (!series_) throw formats::WriteError("cannot write " + series_path() + ": " + std::strerror(errno));
    series_ << "strain,eta_re_stresslet,eta_re_wall,taylor_deformation,inclination_deg,max_volume_error,"
               "max_node_mach,axis_vorticity\n"
            << kept_rows << std::setprecision(17);  // exact round trip on resume
  }

  // Keeps the state a guard tripped on (checkpoint_failed.bin); returns "; state written to PATH".
  std::string saved_failed_state() const {
    const std::string failed = opt_.output_dir + "/checkpoint_failed.bin";
    sim_.save_checkpoint(failed);
    return "; state written to " + failed;
  }

  void advance(std::int64_t step) {
    try {
      sim_.step();
    } catch (const std::runtime_error& e) {
      throw std::runtime_error(run_stopped(step, sim_.strain(), e.what()) + saved_failed_state());
    }
  }

  // Observes, checks the guards (writing checkpoint_failed.bin if they fail), and writes a
  // series row.
  void record(std::int64_t step) {
    const Observables o = sim_.observe();
    try {
      check_state(o, step);
    } catch (const std::runtime_error& e) {
      throw std::runtime_error(e.what() + saved_failed_state());
    }
    double vol = 0.0;
    for (const auto& cell : o.cells) vol = std::max(vol, std::abs(cell.volume_error));
    const double d = o.cells.empty() ? 0.0 : o.cells[0].shape.taylor_deformation;
    const double angle = o.cells.empty() ? 0.0 : o.cells[0].shape.inclination * 180.0 / std::numbers::pi;
    const double axis = o.cells.empty() ? 0.0 : o.cells[0].axis_vorticity;
    series_ << o.strain << ',' << o.eta_re_stresslet << ',' << o.eta_re_wall << ',' << d << ',' << angle << ',' << vol
            << ',' << o.max_mach << ',' << axis << '\n';
    window_.keep(o.strain, o.eta_re_stresslet, o.eta_re_wall, d, angle);
  }

  void snapshot(std::int64_t step) {
    std::ostringstream name;
    name << std::setw(7) << std::setfill('0') << step;
    const std::string cells = "vtk/cells_" + name.str() + ".vtp", fluid = "vtk/fluid_" + name.str() + ".vti";
    write_membranes_vtp(opt_.output_dir + "/" + cells,
                        {&sim_.positions(), &sim_.velocities(), &sim_.membrane_forces(), &sim_.triangles()});
    write_fluid_vti(opt_.output_dir + "/" + fluid, sim_.fluid(), &sim_.inside_fraction().alpha());
    vtk_cells_.emplace_back(sim_.strain(), cells);
    vtk_fluid_.emplace_back(sim_.strain(), fluid);
    write_pvd(opt_.output_dir + "/cells.pvd", vtk_cells_);
    write_pvd(opt_.output_dir + "/fluid.pvd", vtk_fluid_);
  }

  void report_progress(std::int64_t step) {
    const auto now = std::chrono::steady_clock::now();
    if (!opt_.progress || std::chrono::duration<double>(now - last_report_).count() < opt_.progress_seconds) return;
    last_report_ = now;
    const double elapsed = std::chrono::duration<double>(now - start_).count();
    const double eta = elapsed / static_cast<double>(step - first_step_ + 1) * (total_steps_ - step);
    *opt_.progress << "  step " << step << "/" << total_steps_ << "  strain " << std::fixed << std::setprecision(2)
                   << sim_.strain() << "/" << c_.strain_end << "  elapsed " << format_duration(elapsed) << "  ETA "
                   << format_duration(eta) << std::endl;
  }

  double phi_actual() const {
    const double cell_volume =
        sim_.positions().empty() ? 0.0 : enclosed_volume(sim_.positions()[0], sim_.triangles());
    const LatticeUnits& u = sim_.units();
    return sim_.positions().size() * cell_volume / (static_cast<double>(u.nx) * u.ny * u.nz);
  }

  // result.json: the case, the lattice values, the windowed averages, provenance.
  nlohmann::json result() const {
    const MeanWithError eta = block_average(window_.stresslet), wall = block_average(window_.wall);
    const MeanWithError d = block_average(window_.deformation), angle = block_average(window_.angle);
    nlohmann::json j = case_to_json(c_);
    for (const auto& [name, value] : sim_.units().entries()) j["lattice"][name] = value;
    j["result"] = {
        {"eta_re", eta.mean},
        {"eta_re_sem", eta.sem},
        {"eta_re_wall", wall.mean},
        {"eta_re_wall_sem", wall.sem},
        {"window_samples", eta.samples},
        {"phi_actual", phi_actual()},
        {"n_cells", sim_.positions().size()},
        {"steps", total_steps_},
        {"taylor_deformation", d.mean},
        {"taylor_deformation_sem", d.sem},
        {"inclination_deg", angle.mean},
        {"inclination_deg_sem", angle.sem},
        {"wall_seconds", std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count()},
        {"backend", opt_.backend == Backend::Device ? "device (" + device_description() + ")" : "cpu"},
    };
    if (opt_.backend == Backend::Cpu) j["result"]["prefetch_distance"] = prefetch_.distance;
    // The window's late half against its early half: a drift of several sd says the blocking
    // error understates the run's error (a longer run, raised strain_end and --resume, tells).
    const WindowDrift drift = window_drift(window_.stresslet, eta.mean > 0.0 ? eta.sem / eta.mean : 0.0);
    if (drift.available) {
      j["result"]["eta_re_drift"] = drift.drift;
      j["result"]["eta_re_drift_sd"] = drift.sd;
    }
    // Membranes that interpenetrate at the end (the immersed boundary has no contact force).
    // About 1 s for a library case (76 cells of 642 nodes); some minutes for the seed
    // study's box (877 cells of 2562), once at the end of a run of days. The volume claimed
    // twice is sampled on a grid of spacing a / 6 (one lattice spacing at N_a 6), about 10 s
    // for a phi 0.55 library case.
    const LatticeUnits& u = sim_.units();
    const OverlapCount overlaps = count_overlaps(sim_.positions(), sim_.triangles(), u.nx, u.nz);
    j["result"]["overlapping_nodes"] = overlaps.nodes_inside;
    j["result"]["overlapping_cell_pairs"] = overlaps.cell_pairs;
    j["result"]["overlap_max_depth_dx"] = overlaps.max_depth;
    if (overlaps.nodes_inside > 0)
      j["result"]["overlap_volume_fraction"] = overlap_volume_fraction(
          sim_.positions(), sim_.triangles(), u.nx, u.ny, u.nz, overlap_grid_spacing(c_.resolution.nodes_per_radius));
    j["result"]["skalak_c"] = c_.effective_skalak_c();  // the C the membrane ran with
    // Mesh health at the end (solver/membrane/mesh_health.hpp).
    const MeshHealth q = mesh_health(sim_.positions(), sim_.reference_mesh());
    j["result"]["smallest_area_ratio"] = q.smallest_area_ratio;
    j["result"]["triangles_below_half_area"] = q.triangles_below_half;
    j["result"]["folded_hinges"] = q.folded_hinges;
    if (const nlohmann::json changes = interval_changes(); !changes.empty())
      j["result"]["coupling_interval_changes"] = changes;
    j["provenance"] = formats::provenance_block();
    formats::write_json_atomically(opt_.output_dir + "/result.json", j);
    return j;
  }

  const SimulationCase& c_;
  const RunOptions& opt_;
  const std::chrono::steady_clock::time_point start_;
  ShearFlowSimulation sim_;
  std::int64_t total_steps_ = 0, record_every_ = 1, vtk_every_ = 0, checkpoint_every_ = 0;
  ShearFlowSimulation::PrefetchChoice prefetch_;  // the fluid update's prefetch distance in use
  std::int64_t first_step_ = 1;
  WindowSamples window_;
  std::ofstream series_;
  std::vector<std::pair<double, std::string>> vtk_cells_, vtk_fluid_;
  std::chrono::steady_clock::time_point last_report_;
};

}  // namespace

nlohmann::json run_case(const SimulationCase& c, const RunOptions& opt) {
  if (const std::string why = memory_refusal(c, available_memory_bytes()); !why.empty()) throw std::runtime_error(why);
  const std::unique_ptr<FolderLock> lock = claim_output_folder(opt);
  try {
    return CaseRun(c, opt).run();
  } catch (const std::bad_alloc&) {
    // The estimate above let it start, yet the memory ran out (other programs took it).
    throw std::runtime_error("out of memory: the case needs about " +
                             std::to_string(estimated_peak_bytes(c) >> 20) + " MiB (numerics.N_a " +
                             std::to_string(c.resolution.nodes_per_radius) +
                             ", numerics.box); lower them, or free memory and resume with --resume");
  }
}

}  // namespace rbcal::solver
