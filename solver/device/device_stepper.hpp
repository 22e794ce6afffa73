#pragma once
// The whole coupled step of ShearFlowSimulation on a device: the fluid update, the
// membrane forces (elasticity, bending, volume penalty), the spreading of the forces, the
// inside fraction and viscosity field, the interpolation and node update with the volume
// correction. The state stays on the device between steps; the simulation copies it
// back only to observe it or write a checkpoint.
//
// Compiled by nvcc (cmake -DRBCAL_CUDA=ON) it runs on an NVIDIA GPU; otherwise the same
// code runs on the host's threads (device_runtime.hpp), which is how CI tests it. It
// follows the CPU solver's algorithm step for step, with the per-node and per-element
// arithmetic taken from the same headers; where threads meet (spreading, element forces)
// it adds with atomics, so sums come in no fixed order and a run is reproducible to
// round-off, not bit for bit. Two parts take another route to the same quantity: the
// inside fraction sums the signed scan-line crossings as steps along z instead of sorting
// them (equal for cells that do not overlap), and the wall traction is reduced on the
// device.
#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "solver/fluid/fluid_lattice.hpp"
#include "solver/lattice_units.hpp"
#include "solver/membrane/cell_membrane.hpp"
#include "solver/simulation/simulation_case.hpp"

namespace rbcal::solver {

enum class Backend {
  Cpu,       // the tuned CPU solver (the default)
  Device,  // the device path: on the GPU in a CUDA build, else on the host's threads (tests)
};

// True when this build runs the device path on a GPU (cmake -DRBCAL_CUDA=ON).
bool device_is_gpu();
// "NVIDIA H200, 132 SMs, 141 GB" or "host threads".
std::string device_description();

// What the simulation holds on the host, read from and written to by upload and download.
struct DeviceHostState {
  FluidLattice* fluid;                            // populations (and force and viscosity fields)
  std::vector<std::vector<Vec3>>* positions;
  std::vector<std::vector<Vec3>>* velocities;
  std::vector<std::vector<Vec3>>* forces;
  std::vector<std::vector<Vec3>>* indicator_positions;  // empty: not built yet
  AlignedVector<double>* velocity_sum;            // FluidLattice::component_stride layout
  int* velocity_sum_steps;
};

// Per-part seconds, as StepTimings of the CPU solver (parts timed only with set_timing).
struct DeviceTimings {
  double membrane_forces = 0, spreading = 0, indicator = 0, fluid = 0, interpolation = 0;
  std::int64_t indicator_builds = 0, steps = 0;
};

// Device-to-device copy bandwidth (bytes read and written per second) over a buffer of
// `bytes`: the yardstick of the fluid update on a GPU.
double device_copy_bandwidth(std::size_t bytes, int repeats);

class DeviceStepper {
 public:
  DeviceStepper(const SimulationCase& c, const LatticeUnits& units, const CellMembrane& membrane, std::size_t cells);
  ~DeviceStepper();
  DeviceStepper(const DeviceStepper&) = delete;
  DeviceStepper& operator=(const DeviceStepper&) = delete;

  // The whole state to the device (after construction or a checkpoint's restore).
  void upload(const DeviceHostState& host, std::int64_t steps);
  // The membranes (positions, velocities, forces, indicator positions) back to the host.
  void download_cells(const DeviceHostState& host) const;
  // The populations and the interval's velocity sum back to the host.
  void download_fluid(const DeviceHostState& host) const;

  // One lattice step (and a membrane step every coupling_interval steps). Throws
  // std::runtime_error when a node outruns kMaxNodeMach, as the CPU solver does.
  void step();
  // Only the fluid update, `steps` times (for `rbcal bench`): no cells, no velocity field.
  void fluid_steps(int steps);

  std::int64_t steps_done() const;
  // Force per unit area on the bottom and top walls (z components), lattice units.
  std::array<double, 2> wall_shear_traction() const;

  void set_timing(bool on);  // synchronise after each part and time it (slower)
  const DeviceTimings& timings() const;
  void reset_timings();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace rbcal::solver
