#include "solver/simulation/case_runner.hpp"


#include <chrono>
#include <csignal>
#include <cmath>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <numbers>
#include <ostream>
#include <sstream>
#include <stdexcept>

#include "formats/json_file.hpp"
#include "formats/provenance.hpp"
#include "solver/io/format_duration.hpp"
#include "solver/io/vtk_writer.hpp"
#include "solver/simulation/block_average.hpp"
#include "solver/simulation/shear_flow_simulation.hpp"
#include "solver/simulation/state_guards.hpp"

namespace rbcal::solver {

namespace fs = std::filesystem;

namespace {

// Set by SIGINT / SIGTERM: the run stops at the next step with a checkpoint.
volatile std::sig_atomic_t stop_requested = 0;
extern "C" void request_stop(int) { stop_requested = 1; }

}  // namespace

nlohmann::json run_case(const SimulationCase& c, const RunOptions& opt) {
  const auto start = std::chrono::steady_clock::now();
  if (opt.output_dir.empty()) throw std::invalid_argument("run_case: no output folder");
  fs::create_directories(opt.output_dir);
  ShearFlowSimulation sim(c);
  const LatticeUnits& u = sim.units();
  const double gamma = u.shear_rate;
  const auto total_steps = static_cast<std::int64_t>(std::ceil(c.strain_end / gamma - 1e-9));
  const auto record_every = std::max<std::int64_t>(1, std::llround(c.record_interval / gamma));
  const std::int64_t vtk_every = c.vtk_interval > 0 ? std::max<std::int64_t>(1, std::llround(c.vtk_interval / gamma)) : 0;

  if (opt.progress) {
    const double v_cell = sim.positions().empty() ? 0.0 : enclosed_volume(sim.positions()[0], sim.triangles());
    *opt.progress << "  " << sim.positions().size() << " cells, phi = "
                  << sim.positions().size() * v_cell / (static_cast<double>(u.nx) * u.ny * u.nz) << ", lattice "
                  << u.nx << " x " << u.ny << " x " << u.nz << ", " << total_steps << " steps\n";
  }
  const std::string series_path = opt.output_dir + "/series.csv";
  const std::string checkpoint_path = opt.output_dir + "/checkpoint.bin";
  const std::int64_t checkpoint_every =
      c.checkpoint_interval > 0 ? std::max<std::int64_t>(1, std::llround(c.checkpoint_interval / gamma)) : 0;
  std::vector<double> window_stresslet, window_wall, window_d, window_angle;
  auto keep_for_window = [&](double strain, double eta_s, double eta_w, double d, double angle) {
    if (strain < c.window[0] - 1e-9 || strain > c.window[1] + 1e-9) return;
    window_stresslet.push_back(eta_s);
    window_wall.push_back(eta_w);
    window_d.push_back(d);
    window_angle.push_back(angle);
  };
  const std::string header =
      "strain,eta_re_stresslet,eta_re_wall,taylor_deformation,inclination_deg,max_volume_error,max_node_mach,axis_vorticity\n";

  std::int64_t first_step = 1;
  std::string kept_rows;
  if (opt.resume && fs::exists(checkpoint_path)) {
    sim.restore_checkpoint(checkpoint_path);
    first_step = sim.steps_done() + 1;
    // Keep the rows up to the checkpoint; later ones are recomputed.
    std::ifstream old(series_path);
    std::string line;
    std::getline(old, line);
    while (std::getline(old, line)) {
      std::vector<double> v;
      std::stringstream ss(line);
      std::string cell;
      while (std::getline(ss, cell, ',')) v.push_back(std::stod(cell));
      if (v.size() < 5 || v[0] > sim.strain() + 1e-9) break;
      keep_for_window(v[0], v[1], v[2], v[3], v[4]);
      kept_rows += line + "\n";
    }
    if (opt.progress) *opt.progress << "  resuming from " << checkpoint_path << " at strain " << sim.strain() << "\n";
  }
  std::ofstream series(series_path, std::ios::trunc);
  if (!series) throw std::runtime_error("cannot write " + series_path);
  series << header << kept_rows << std::setprecision(17);  // exact round trip on resume
  std::vector<std::pair<double, std::string>> vtk_cells, vtk_fluid;
  if (vtk_every) fs::create_directories(opt.output_dir + "/vtk");
  auto snapshot = [&](std::int64_t step) {
    std::ostringstream name;
    name << std::setw(7) << std::setfill('0') << step;
    const std::string cells = "vtk/cells_" + name.str() + ".vtp", fluid = "vtk/fluid_" + name.str() + ".vti";
    write_membranes_vtp(opt.output_dir + "/" + cells,
                        {&sim.positions(), &sim.velocities(), &sim.membrane_forces(), &sim.triangles()});
    write_fluid_vti(opt.output_dir + "/" + fluid, sim.fluid(), &sim.inside_fraction().alpha());
    vtk_cells.emplace_back(sim.strain(), cells);
    vtk_fluid.emplace_back(sim.strain(), fluid);
    write_pvd(opt.output_dir + "/cells.pvd", vtk_cells);
    write_pvd(opt.output_dir + "/fluid.pvd", vtk_fluid);
  };
  if (vtk_every && first_step == 1) snapshot(0);

  stop_requested = 0;
  auto previous_int = std::signal(SIGINT, request_stop);
  auto previous_term = std::signal(SIGTERM, request_stop);
  struct RestoreSignals {
    decltype(previous_int) i, t;
    ~RestoreSignals() {
      std::signal(SIGINT, i);
      std::signal(SIGTERM, t);
    }
  } restore_signals{previous_int, previous_term};

  auto last_report = std::chrono::steady_clock::now();
  for (std::int64_t step = first_step; step <= total_steps; ++step) {
    try {
      sim.step();
    } catch (const std::runtime_error& e) {
      throw std::runtime_error("run stopped at step " + std::to_string(step) + ": " + e.what());
    }
    if (step % record_every == 0 || step == total_steps) {
      const Observables o = sim.observe();
      try {
        check_state(o, step);
      } catch (const std::runtime_error& e) {
        const std::string failed = opt.output_dir + "/checkpoint_failed.bin";
        sim.save_checkpoint(failed);
        throw std::runtime_error(std::string(e.what()) + "; state written to " + failed);
      }
      double vol = 0.0;
      for (const auto& cell : o.cells) vol = std::max(vol, std::abs(cell.volume_error));
      const double d = o.cells.empty() ? 0.0 : o.cells[0].shape.taylor_deformation;
      const double angle = o.cells.empty() ? 0.0 : o.cells[0].shape.inclination * 180.0 / std::numbers::pi;
      const double axis = o.cells.empty() ? 0.0 : o.cells[0].axis_vorticity;
      series << o.strain << ',' << o.eta_re_stresslet << ',' << o.eta_re_wall << ',' << d << ',' << angle << ','
             << vol << ',' << o.max_mach << ',' << axis << '\n';
      keep_for_window(o.strain, o.eta_re_stresslet, o.eta_re_wall, d, angle);
    }
    if (vtk_every && step % vtk_every == 0) snapshot(step);
    const bool stop_now =
        step < total_steps && (stop_requested || (opt.max_steps > 0 && step - first_step + 1 >= opt.max_steps));
    if ((checkpoint_every && step % checkpoint_every == 0) || stop_now) {
      series.flush();
      sim.save_checkpoint(checkpoint_path);
    }
    if (stop_now) return {{"status", "interrupted"}, {"strain", sim.strain()}, {"checkpoint", checkpoint_path}};
    const auto now = std::chrono::steady_clock::now();
    if (opt.progress && std::chrono::duration<double>(now - last_report).count() >= opt.progress_seconds) {
      last_report = now;
      const double elapsed = std::chrono::duration<double>(now - start).count();
      const double eta = elapsed / static_cast<double>(step - first_step + 1) * (total_steps - step);
      *opt.progress << "  step " << step << "/" << total_steps << "  strain " << std::fixed << std::setprecision(2)
                    << sim.strain() << "/" << c.strain_end << "  elapsed " << format_duration(elapsed) << "  ETA "
                    << format_duration(eta) << std::endl;
    }
  }
  series.close();

  const MeanWithError eta = block_average(window_stresslet), wall = block_average(window_wall);
  const MeanWithError d = block_average(window_d), angle = block_average(window_angle);
  const double cell_volume = enclosed_volume(sim.positions().empty() ? std::vector<Vec3>{} : sim.positions()[0],
                                             sim.triangles());
  nlohmann::json j = case_to_json(c);
  for (const auto& [name, value] : u.entries()) j["lattice"][name] = value;
  j["result"] = {
      {"eta_re", eta.mean},
      {"eta_re_sem", eta.sem},
      {"eta_re_wall", wall.mean},
      {"eta_re_wall_sem", wall.sem},
      {"window_samples", eta.samples},
      {"phi_actual", sim.positions().size() * cell_volume / (static_cast<double>(u.nx) * u.ny * u.nz)},
      {"n_cells", sim.positions().size()},
      {"steps", total_steps},
      {"taylor_deformation", d.mean},
      {"taylor_deformation_sem", d.sem},
      {"inclination_deg", angle.mean},
      {"inclination_deg_sem", angle.sem},
      {"wall_seconds", std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()},
  };
  j["provenance"] = formats::provenance_block();
  formats::write_json_atomically(opt.output_dir + "/result.json", j);
  return j;
}

}  // namespace rbcal::solver
