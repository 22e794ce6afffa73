#include "bench/coupled_step.hpp"

#include <algorithm>
#include <chrono>
#include <memory>
#include <vector>
#include <cstdio>
#include <stdexcept>

#include "formats/printf_string.hpp"
#include "solver/simulation/shear_flow_simulation.hpp"
#include "solver/simulation/state_guards.hpp"

namespace rbcal::bench {

using formats::printf_string;

CoupledStepTimings time_coupled_step(const solver::SimulationCase& c, const std::string& case_name, int steps,
                                     solver::Backend backend, int rounds, const std::string& checkpoint) {
  if (steps < 1) throw std::invalid_argument("coupled-step bench: steps must be >= 1");
  solver::ShearFlowSimulation sim(c, backend);
  if (!checkpoint.empty()) sim.restore_checkpoint(checkpoint, false);
  const double start_strain = sim.strain();
  solver::DeviceStepper* device = sim.device();
  if (device) device->set_timing(true);
  // NaNs run at their own speed: the guards after every step, outside the timed parts.
  auto step = [&] {
    try {
      try {
        sim.step();
      } catch (const std::runtime_error& e) {  // the per-step node guard
        throw std::runtime_error(solver::run_stopped(sim.steps_done(), sim.strain(), e.what()));
      }
      if (!device) solver::check_state(sim.observe(), sim.steps_done());
    } catch (const std::runtime_error& e) {
      throw std::runtime_error(case_name + ": the case is not stable, so no timings: " + e.what());
    }
  };
  for (int s = 0; s < 2; ++s) step();  // warm-up: first touches, field allocation
  CoupledStepTimings out;
  out.nx = sim.units().nx, out.ny = sim.units().ny, out.nz = sim.units().nz;
  out.cells = sim.positions().size();
  for (const auto& x : sim.positions()) out.membrane_nodes += x.size();
  out.coupling_interval = c.coupling_interval;
  out.strain_per_step = sim.units().shear_rate;
  out.start_strain = start_strain;
  // One round: `steps` coupled steps, part by part, then (CPU) as many plain fluid steps of
  // the same lattice, so that both see the same state of a noisy host.
  std::unique_ptr<solver::FluidLattice> plain;
  if (!device) {
    plain = std::make_unique<solver::FluidLattice>(sim.fluid().config());
    plain->step();
  }
  std::vector<CoupledStepTimings> per_round;
  for (int round = 0; round < std::max(1, rounds); ++round) {
    sim.reset_timings();
    for (int s = 0; s < steps; ++s) step();
    const solver::StepTimings& t = sim.timings();
    CoupledStepTimings r = out;
    r.steps = t.steps;
    r.indicator_builds = t.indicator_builds;
    r.ordering_sorts = t.ordering_sorts;
    const double per = 1.0 / static_cast<double>(t.steps);
    r.fluid = t.fluid * per;
    r.membrane_forces = t.membrane_forces * per;
    r.ordering = t.ordering * per;
    r.spreading = t.spreading * per;
    r.indicator = t.indicator * per;
    r.interpolation = t.interpolation * per;
    if (plain) {
      const auto start = std::chrono::steady_clock::now();
      for (int s = 0; s < steps; ++s) plain->step();
      r.plain_fluid = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() / steps;
    }
    per_round.push_back(r);
  }
  // Medians over rounds, part by part; the ratio's median over the rounds' own ratios.
  auto median_of = [&](auto field) {
    std::vector<double> v;
    for (const CoupledStepTimings& r : per_round) v.push_back(field(r));
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
  };
  out.rounds = static_cast<int>(per_round.size());
  out.steps = per_round.back().steps;
  out.indicator_builds = per_round.back().indicator_builds;
  out.ordering_sorts = per_round.back().ordering_sorts;
  out.fluid = median_of([](const CoupledStepTimings& r) { return r.fluid; });
  out.membrane_forces = median_of([](const CoupledStepTimings& r) { return r.membrane_forces; });
  out.ordering = median_of([](const CoupledStepTimings& r) { return r.ordering; });
  out.spreading = median_of([](const CoupledStepTimings& r) { return r.spreading; });
  out.indicator = median_of([](const CoupledStepTimings& r) { return r.indicator; });
  out.interpolation = median_of([](const CoupledStepTimings& r) { return r.interpolation; });
  out.whole_median = median_of([](const CoupledStepTimings& r) { return r.whole(); });
  if (plain) {
    constexpr int kernel_passes = 21;
    // Into the plain lattice's force field: its timing is done, and a third lattice would
    // cost as much memory again.
    out.kernels = time_coupling_kernels(c.kernel, sim.positions(), sim.membrane_forces(), *plain, kernel_passes);
    out.plain_fluid = median_of([](const CoupledStepTimings& r) { return r.plain_fluid; });
    out.ratio_median = median_of([](const CoupledStepTimings& r) { return r.whole() / r.plain_fluid; });
    return out;
  }
  if (device) {
    device->set_timing(false);
    auto start = std::chrono::steady_clock::now();
    for (int s = 0; s < steps; ++s) step();
    device->wall_shear_traction();  // a small read: waits for the device
    out.free_running = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() / steps;
    const solver::Observables o = sim.observe();  // the guards, untimed
    try {
      solver::check_state(o, sim.steps_done());
    } catch (const std::runtime_error& e) {
      throw std::runtime_error(case_name + ": the case is not stable, so no timings: " + e.what());
    }
    sim.device_fluid_steps(1);
    start = std::chrono::steady_clock::now();
    sim.device_fluid_steps(steps);
    out.plain_fluid = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() / steps;
    out.device = solver::device_description();
    if (solver::device_is_gpu()) out.copy_bandwidth = solver::device_copy_bandwidth(std::size_t{1} << 30, 20);
    return out;
  }
  return out;
}

std::string CoupledStepTimings::brief_report() const {
  std::string s =
      printf_string("  lattice %d x %d x %d, %zu cells, %zu membrane nodes, %lld timed steps x %d rounds, coupling interval %d\n",
                    nx, ny, nz, cells, membrane_nodes, static_cast<long long>(steps), rounds, coupling_interval);
  if (start_strain > 0) s += printf_string("  from a checkpoint at strain %.3f\n", start_strain);
  s += printf_string("  fluid update (+ velocity field) %9.3f ms/step\n", fluid * 1e3);
  s += printf_string("  membrane forces              %9.3f ms/step\n", membrane_forces * 1e3);
  s += printf_string("  node ordering                %9.3f ms/step (sorted in %lld of the steps)\n", ordering * 1e3,
                     static_cast<long long>(ordering_sorts));
  s += printf_string("  force spreading              %9.3f ms/step\n", spreading * 1e3);
  s += printf_string("  inside fraction + viscosity  %9.3f ms/step (rebuilt in %lld of the steps)\n", indicator * 1e3,
            static_cast<long long>(indicator_builds));
  s += printf_string("  interpolation + node update  %9.3f ms/step\n", interpolation * 1e3);
  s += printf_string("  whole step                   %9.3f ms/step\n", (whole_median > 0 ? whole_median : whole()) * 1e3);
  s += printf_string("  plain fluid update           %9.3f ms/step (same lattice, no cells)\n", plain_fluid * 1e3);
  s += printf_string("  whole step / plain fluid     %9.2f (target <= 3)%s\n", ratio(),
                     rounds > 1 ? printf_string(", median of %d rounds' ratios", rounds).c_str() : "");
  if (!device.empty()) {
    const double nodes = static_cast<double>(nx) * ny * nz;
    // 19 populations read and written, force (3) and viscosity read: 336 B per node.
    constexpr double bytes_per_update = 19 * 16 + 4 * 8;
    s += printf_string("  device                       %s\n", device.c_str());
    s += printf_string("  whole step, free running     %9.3f ms/step (no synchronisation between the parts)\n",
              free_running * 1e3);
    s += printf_string("  plain fluid                  %9.1f MLUPS, %.0f GB/s at %.0f B/update\n",
                       nodes / plain_fluid * 1e-6, nodes / plain_fluid * bytes_per_update * 1e-9, bytes_per_update);
    if (copy_bandwidth > 0)
      s += printf_string(
          "  device copy bandwidth        %9.0f GB/s (read + written); fluid at %.1f %% of it (target >= 50 %%)\n",
          copy_bandwidth * 1e-9, 100.0 * nodes / plain_fluid * bytes_per_update / copy_bandwidth);
    const double steps_to_40 = 40.0 / strain_per_step;
    s += printf_string("  to strain 40                 %9.0f steps, %.1f min at the free-running step\n", steps_to_40,
              steps_to_40 * free_running / 60.0);
  }
  s += printf_string("  membrane + coupling / fluid  %9.2f (target <= 1)\n", coupling() / fluid);
  if (kernels.nodes > 0)
    s += printf_string("  per node, one thread         spreading %.1f ns, interpolation %.1f ns (median of %d passes over the\n"
                       "                               %zu nodes; fastest %.1f and %.1f)\n",
                       kernels.spreading_median, kernels.interpolation_median, kernels.passes, kernels.nodes,
                       kernels.spreading_fastest, kernels.interpolation_fastest);
  return s;
}

nlohmann::json CoupledStepTimings::to_json() const {
  const double n = static_cast<double>(steps);
  nlohmann::json j = {{"steps", steps},
          {"rounds", rounds},
          {"whole_over_plain_fluid", ratio()},
          {"indicator_builds", indicator_builds},
          {"ordering_sorts", ordering_sorts},
          {"coupling_interval", coupling_interval},
          {"start_strain", start_strain},
          {"plain_fluid_seconds_per_step", plain_fluid},
          {"free_running_seconds_per_step", free_running},
          {"device", device},
          {"device_copy_bytes_per_s", copy_bandwidth},
          {"seconds", {{"fluid", fluid * n},
                       {"membrane_forces", membrane_forces * n},
                       {"ordering", ordering * n},
                       {"spreading", spreading * n},
                       {"indicator", indicator * n},
                       {"interpolation", interpolation * n}}}};
  if (kernels.nodes > 0)
    j["kernel_ns_per_node"] = {{"nodes", kernels.nodes},
                               {"passes", kernels.passes},
                               {"spreading", kernels.spreading_median},
                               {"interpolation", kernels.interpolation_median},
                               {"spreading_fastest", kernels.spreading_fastest},
                               {"interpolation_fastest", kernels.interpolation_fastest}};
  return j;
}

}  // namespace rbcal::bench
