#include "bench/coupled_step.hpp"

#include <chrono>
#include <cstdio>
#include <stdexcept>

#include "solver/simulation/shear_flow_simulation.hpp"
#include "solver/simulation/state_guards.hpp"

namespace rbcal::bench {

namespace {

template <class... Args>
std::string line(const char* pattern, Args... args) {
  char buffer[256];
  std::snprintf(buffer, sizeof buffer, pattern, args...);
  return buffer;
}

}  // namespace

CoupledStepTimings time_coupled_step(const solver::SimulationCase& c, const std::string& case_name, int steps) {
  if (steps < 1) throw std::invalid_argument("coupled-step bench: steps must be >= 1");
  solver::ShearFlowSimulation sim(c);
  // NaNs run at their own speed: the guards after every step, outside the timed parts.
  auto step = [&] {
    try {
      try {
        sim.step();
      } catch (const std::runtime_error& e) {  // the per-step node guard
        throw std::runtime_error(solver::run_stopped(sim.steps_done(), sim.strain(), e.what()));
      }
      solver::check_state(sim.observe(), sim.steps_done());
    } catch (const std::runtime_error& e) {
      throw std::runtime_error(case_name + ": the case is not stable, so no timings: " + e.what());
    }
  };
  for (int s = 0; s < 2; ++s) step();  // warm-up: first touches, field allocation
  sim.reset_timings();
  for (int s = 0; s < steps; ++s) step();
  const solver::StepTimings& t = sim.timings();
  CoupledStepTimings out;
  out.nx = sim.units().nx, out.ny = sim.units().ny, out.nz = sim.units().nz;
  out.cells = sim.positions().size();
  for (const auto& x : sim.positions()) out.membrane_nodes += x.size();
  out.coupling_interval = c.coupling_interval;
  out.steps = t.steps;
  out.indicator_builds = t.indicator_builds;
  const double per = 1.0 / static_cast<double>(t.steps);
  out.fluid = t.fluid * per;
  out.membrane_forces = t.membrane_forces * per;
  out.ordering = t.ordering * per;
  out.spreading = t.spreading * per;
  out.indicator = t.indicator * per;
  out.interpolation = t.interpolation * per;
  // The plain fluid update of the same lattice (no velocity output, no coupling).
  solver::FluidLattice plain(sim.fluid().config());
  plain.step();
  const auto start = std::chrono::steady_clock::now();
  for (int s = 0; s < steps; ++s) plain.step();
  out.plain_fluid = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() / steps;
  return out;
}

std::string CoupledStepTimings::brief_report() const {
  std::string s = line("  lattice %d x %d x %d, %zu cells, %zu membrane nodes, %lld timed steps, coupling interval %d\n",
                       nx, ny, nz, cells, membrane_nodes, static_cast<long long>(steps), coupling_interval);
  s += line("  fluid update (+ velocity field) %9.3f ms/step\n", fluid * 1e3);
  s += line("  membrane forces              %9.3f ms/step\n", membrane_forces * 1e3);
  s += line("  node ordering                %9.3f ms/step\n", ordering * 1e3);
  s += line("  force spreading              %9.3f ms/step\n", spreading * 1e3);
  s += line("  inside fraction + viscosity  %9.3f ms/step (rebuilt in %lld of the steps)\n", indicator * 1e3,
            static_cast<long long>(indicator_builds));
  s += line("  interpolation + node update  %9.3f ms/step\n", interpolation * 1e3);
  s += line("  whole step                   %9.3f ms/step\n", whole() * 1e3);
  s += line("  plain fluid update           %9.3f ms/step (same lattice, no cells)\n", plain_fluid * 1e3);
  s += line("  whole step / plain fluid     %9.2f (target <= 4)\n", whole() / plain_fluid);
  s += line("  membrane + coupling / fluid  %9.2f (target <= 1)\n", coupling() / fluid);
  return s;
}

nlohmann::json CoupledStepTimings::to_json() const {
  const double n = static_cast<double>(steps);
  return {{"steps", steps},
          {"indicator_builds", indicator_builds},
          {"coupling_interval", coupling_interval},
          {"plain_fluid_seconds_per_step", plain_fluid},
          {"seconds", {{"fluid", fluid * n},
                       {"membrane_forces", membrane_forces * n},
                       {"ordering", ordering * n},
                       {"spreading", spreading * n},
                       {"indicator", indicator * n},
                       {"interpolation", interpolation * n}}}};
}

}  // namespace rbcal::bench
