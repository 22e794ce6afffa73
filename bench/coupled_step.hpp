#pragma once
// The cost of one coupled step of a simulation case, part by part (membrane forces, node
// ordering, spreading, inside fraction, fluid, interpolation), against a plain fluid
// update of the same lattice without cells, the yardstick of the target (a whole step
// within 3x the fluid update, docs/performance.md). The solver's guards run after every step, outside
// the timed parts: timings of a state that is blowing up mean nothing.
#include <cstdint>
#include <string>

#include <nlohmann/json.hpp>

#include "bench/coupling_kernels.hpp"
#include "solver/device/device_stepper.hpp"
#include "solver/simulation/simulation_case.hpp"

namespace rbcal::bench {

struct CoupledStepTimings {
  int nx = 0, ny = 0, nz = 0;
  std::size_t cells = 0, membrane_nodes = 0;
  int coupling_interval = 1;
  std::int64_t steps = 0, indicator_builds = 0, ordering_sorts = 0;
  // Seconds per step.
  double fluid = 0, membrane_forces = 0, ordering = 0, spreading = 0, indicator = 0, interpolation = 0;
  double plain_fluid = 0;
  // The device path only: the step run freely (no synchronisation between its parts), the
  // device, and its device-to-device copy bandwidth (bytes read + written per second; 0 on
  // host threads).
  double free_running = 0;
  std::string device;
  double copy_bandwidth = 0;
  double strain_per_step = 0;  // gamma_dot in lattice units
  double start_strain = 0;     // where the timed steps began (a checkpoint's strain; else 0)
  // Rounds of `steps` coupled and (CPU) `steps` plain fluid steps, alternating; the parts above
  // are medians over rounds, and so are the whole step and the ratio (of each round's own).
  int rounds = 1;
  double whole_median = 0, ratio_median = 0;
  // CPU: the spreading and interpolation kernels alone on the cells after the timed steps,
  // per node on one thread (coupling_kernels.hpp).
  CouplingKernelTimings kernels;
  double whole() const { return fluid + membrane_forces + ordering + spreading + indicator + interpolation; }
  double ratio() const { return ratio_median > 0 ? ratio_median : whole() / plain_fluid; }  // whole / plain fluid
  double coupling() const { return whole() - fluid; }

  std::string brief_report() const;  // the table `rbcal bench --case` prints
  nlohmann::json to_json() const;    // seconds in total over the timed steps, as before
};

// Two warm-up steps, then `rounds` rounds of `steps` timed steps of the case and (CPU) as
// many plain fluid steps, then (CPU) the coupling kernels per node. Throws std::runtime_error naming the case when it is not stable. On
// the device backend the parts are timed with a synchronisation after each, then the step
// again without, and the guards run once at the end. A checkpoint of the case (rbcal simulate
// --max-steps writes one) is the state to start from: a run's cells, which shear carries
// out of the box in x (positions are unwrapped), where a fresh start has them all inside.
CoupledStepTimings time_coupled_step(const solver::SimulationCase& c, const std::string& case_name, int steps,
                                     solver::Backend backend = solver::Backend::Cpu, int rounds = 1,
                                     const std::string& checkpoint = "");

}  // namespace rbcal::bench
