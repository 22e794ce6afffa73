// `rbcal simulate CASE.json`: one solver case -> result JSON, time series, VTK.
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "cli/backend_option.hpp"
#include "cli/commands.hpp"
#include "cli/number_validators.hpp"
#include "solver/fluid/fluid_lattice.hpp"
#include "solver/simulation/case_runner.hpp"
#include "solver/simulation/window_drift.hpp"

namespace rbcal::cli {

namespace {

struct SimulateOptions {
  std::string case_path;
  std::string output_dir;
  bool quiet = false;
  bool resume = false;
  bool overwrite = false;
  long long max_steps = 0;
  int coupling_interval = 0;
  std::string backend = "cpu";
  std::string prefetch = "auto";
};

// The window's late half against its early half, and a warning where it drifts.
std::string drift_line(const nlohmann::json& r) {
  const solver::WindowDrift d = solver::drift_of_result(r);
  if (!d.available) return "";
  std::ostringstream s;
  s << std::showpos << std::fixed << std::setprecision(1) << "  drift over the window " << 100.0 * d.drift << " % +- "
    << std::noshowpos << 100.0 * d.sd << " % (late half against early half)\n";
  if (solver::drifts(d))
    s << "  warning: the window is not stationary (" << std::setprecision(1) << std::abs(d.z())
      << " sd): eta_re_sem understates the error; raise run.strain_end and the window, and continue with --resume\n";
  return s.str();
}

void run_simulate(const SimulateOptions& o) {
  const solver::SimulationCase c = solver::read_case(o.case_path);
  std::string out = o.output_dir;
  if (out.empty()) out = std::filesystem::path(o.case_path).stem().string() + ".out";
  solver::RunOptions ro;
  ro.output_dir = out;
  ro.progress = o.quiet ? nullptr : &std::cerr;
  ro.resume = o.resume;
  ro.overwrite = o.overwrite;
  ro.max_steps = o.max_steps;
  ro.coupling_interval = o.coupling_interval;
  ro.backend = backend_from_option(o.backend);
  ro.prefetch_distance = o.prefetch == "auto" ? -1 : std::stoi(o.prefetch);
  std::cerr << "rbcal simulate: " << o.case_path << " -> " << out << "/\n";
  const nlohmann::json j = solver::run_case(c, ro);
  if (!j.contains("result")) {
    const int signal_number = j.value("signal", 0);
    std::cout << "rbcal simulate: stopped at strain " << j["strain"].get<double>()
              << (signal_number ? " by signal " + std::to_string(signal_number) : std::string(" (--max-steps)"))
              << "; checkpoint " << j["checkpoint"].get<std::string>() << " (continue with --resume)\n";
    // A run stopped by a signal did not finish: exit as the shell expects, 128 + the signal.
    if (signal_number) throw ExitStatus{128 + signal_number};
    return;
  }
  const auto& r = j["result"];
  std::cout << "rbcal simulate: " << o.case_path << "\n"
            << "  lattice " << j["lattice"]["nx"].get<double>() << " x " << j["lattice"]["ny"].get<double>() << " x "
            << j["lattice"]["nz"].get<double>()
            << ", " << r["steps"] << " steps, " << r["wall_seconds"].get<double>() << " s\n"
            << "  eta_re (stresslet)   " << r["eta_re"].get<double>() << " +- " << r["eta_re_sem"].get<double>() << "\n"
            << "  eta_re (wall stress) " << r["eta_re_wall"].get<double>() << " +- " << r["eta_re_wall_sem"].get<double>()
            << "\n"
            << drift_line(r)
            << "  Taylor deformation   " << r["taylor_deformation"].get<double>() << ", inclination "
            << r["inclination_deg"].get<double>() << " deg (first cell)\n"
            << "  outputs in " << out << "/ (result.json, series.csv" << (c.vtk_interval > 0 ? ", vtk/" : "") << ")\n";
}

}  // namespace

void add_simulate_command(CLI::App& app) {
  auto o = std::make_shared<SimulateOptions>();
  CLI::App* cmd = app.add_subcommand(
      "simulate",
      "Run one solver case (JSON, schema rbcal.case/1): cells in wall-bounded shear flow -> eta_re, shapes, VTK");
  cmd->add_option("case", o->case_path, "Case file (see data/cases/ for examples)")->required()->check(CLI::ExistingFile);
  cmd->add_option("-o,--output", o->output_dir, "Output folder (default: CASE stem + .out)");
  cmd->add_flag("-q,--quiet", o->quiet, "No progress lines");
  cmd->add_flag("--resume", o->resume, "Continue from OUTPUT/checkpoint.bin if it exists (bit-identical)");
  cmd->add_flag("--overwrite", o->overwrite,
                "Start afresh in an OUTPUT that holds a run, discarding it (without this or --resume, such a folder is "
                "refused)");
  cmd->add_option("--max-steps", o->max_steps, "Stop after this many lattice steps, with a checkpoint (0: to the end)")
      ->check(kNonNegative);
  cmd->add_option("--coupling-interval", o->coupling_interval,
                  "Advance the membrane every K fluid steps instead of the case's numerics.coupling_interval; with "
                  "--resume, continue a checkpoint written under another interval (e.g. 1 after a late instability "
                  "at 2). Recorded in coupling_interval_changes.json and result.json")
      ->check(CLI::Range(1, 1000));
  add_backend_option(cmd, o->backend);
  std::vector<std::string> distances = {"auto"};
  for (const int d : solver::kPrefetchDistances) distances.push_back(std::to_string(d));
  cmd->add_option("--prefetch", o->prefetch,
                  "How far ahead the fluid update prefetches its read streams, in populations (0: none), or auto: the "
                  "fastest on this host, timed at the start of the run (lattices under 65536 nodes keep 64). The "
                  "results do not depend on it")
      ->check(CLI::IsMember(distances))
      ->capture_default_str();
  cmd->callback([o] { run_simulate(*o); });
}

}  // namespace rbcal::cli
