#pragma once
// Capsules or red blood cells in wall-bounded shear flow: the lattice-Boltzmann fluid,
// the membranes and the immersed-boundary coupling advanced together, one lattice step at
// a time, with the viscosity contrast lambda inside the cells. Everything inside runs
// in lattice units (lattice_units.hpp); observables are dimensionless.
//
// One membrane step (every numerics.coupling_interval = k fluid steps; k = 1: every
// step): membrane forces at X^n -> spread to the lattice -> inside fraction and
// viscosity from X^n (or kept from an earlier step while no node has moved farther than
// numerics.indicator_tolerance) -> k fluid steps (stream + collide) under these fields ->
// node velocities interpolated from the new populations -> X^{n+k} = X^n + k u by Euler
// (or RK4 through the frozen interpolated field) -> volume correction
// (volume_constraint.hpp). A larger k is the membrane time step of HemoCell-style
// multi-rate coupling; its stability limit is k times tighter (docs/performance.md).
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "solver/coupling/immersed_boundary.hpp"
#include "solver/coupling/inside_fraction.hpp"
#include "solver/coupling/stresslet.hpp"
#include "solver/device/device_stepper.hpp"
#include "solver/fluid/fluid_lattice.hpp"
#include "solver/membrane/cell_membrane.hpp"
#include "solver/simulation/simulation_case.hpp"

namespace rbcal::solver {

struct CellObservables {
  ShearPlaneShape shape;
  double axis_vorticity = 0.0;  // |x component| of the symmetry axis: 1 rolling, 0 in the shear plane
  double volume_error = 0.0;    // relative
  Vec3 centroid;              // in a, relative to the box centre
};

// Wall-clock seconds spent in each part of step(), accumulated since the last reset.
struct StepTimings {
  double membrane_forces = 0.0;  // elasticity, bending, volume penalty of all cells
  double ordering = 0.0;         // sorting the nodes (when needed) and copying their positions and forces
  std::int64_t ordering_sorts = 0;  // steps that sorted the nodes (the others kept the order)
  double spreading = 0.0;        // clearing the force field and spreading to the lattice
  double indicator = 0.0;        // inside fraction and viscosity field
  std::int64_t indicator_builds = 0;  // steps that rebuilt it (numerics.indicator_tolerance)
  double fluid = 0.0;            // lattice Boltzmann stream + collide (+ velocity field before an update)
  double interpolation = 0.0;    // interpolation, node update, volume correction
  std::int64_t steps = 0;
};

struct Observables {
  double strain = 0.0;            // gamma_dot t
  double eta_re_stresslet = 1.0;  // 1 + Sigma_p[z][y] / (eta0 gamma_dot)
  double eta_re_wall = 1.0;       // mean wall shear stress / (eta0 gamma_dot)
  double max_mach = 0.0;          // largest membrane-node speed / c_s
  std::vector<CellObservables> cells;
};

// Membrane nodes faster than this (in units of the lattice speed of sound) mean the
// explicit coupling has gone unstable; checked every membrane step and at every record.
inline constexpr double kMaxNodeMach = 0.3;

class ShearFlowSimulation {
 public:
  // Backend::Device runs every step on the device path (device_stepper.hpp): on the GPU
  // in a CUDA build, on the host's threads otherwise.
  explicit ShearFlowSimulation(const SimulationCase& c, Backend backend = Backend::Cpu);
  ~ShearFlowSimulation();

  void step();
  Observables observe() const;
  // The fluid update's prefetch distance (FluidConfig::prefetch_distance, a property of the
  // host: the results are the same at any): the given one, or for a negative one the
  // fastest on this lattice and host, timed without changing the state (on lattices of at
  // least kPrefetchTimingNodes; smaller ones keep the default). Returns it, and whether it
  // was timed; 0 on the device path, which does not prefetch.
  struct PrefetchChoice {
    int distance = 0;
    bool timed = false;
  };
  PrefetchChoice set_prefetch_distance(int distance);
  // Below this many nodes the timing (about half a second) is not worth it: such lattices
  // largely fit in the caches and their runs are short (a test's capsule).
  static constexpr std::size_t kPrefetchTimingNodes = 65536;

  const StepTimings& timings() const;
  void reset_timings();

  // Checkpoints (checkpoint.hpp): restoring continues bit-identically.
  void save_checkpoint(const std::string& path) const;
  // Throws if the checkpoint belongs to another case or lattice.
  // Throws if the checkpoint belongs to another case. With any_coupling_interval, a
  // checkpoint written under another numerics.coupling_interval is accepted (the membrane
  // step is a numerical choice, shown not to change eta_re: docs/library.md). Returns the
  // coupling interval the checkpoint was written under.
  int restore_checkpoint(const std::string& path, bool any_coupling_interval = false);

  double strain() const { return static_cast<double>(steps_done()) * units_.shear_rate; }
  std::int64_t steps_done() const { return device_ ? device_->steps_done() : fluid_.steps_done(); }
  const LatticeUnits& units() const { return units_; }
  const SimulationCase& simulation_case() const { return case_; }
  const FluidLattice& fluid() const {
    refresh_fluid();
    return fluid_;
  }
  // On the device path: the inside fraction of the start or the last restore.
  const InsideFraction& inside_fraction() const { return inside_; }
  const std::vector<std::vector<Vec3>>& positions() const {
    refresh_cells();
    return x_;
  }
  const std::vector<std::vector<Vec3>>& velocities() const {
    refresh_cells();
    return v_;
  }
  const std::vector<std::vector<Vec3>>& membrane_forces() const {
    refresh_cells();
    return f_;
  }
  // Positions the inside fraction was last built from (empty for lambda = 1).
  const std::vector<std::vector<Vec3>>& indicator_positions() const {
    refresh_cells();
    return x_indicator_;
  }
  // The device path, or nullptr on the CPU backend.
  DeviceStepper* device() { return device_.get(); }
  // The device path only: `steps` fluid updates without the cells (benchmarks, tests).
  void device_fluid_steps(int steps);
  const std::vector<Triangle>& triangles() const { return membrane_->reference().triangles; }
  const TriangleMesh& reference_mesh() const { return membrane_->reference(); }
  Vec3 box_centre() const;

 private:
  void compute_membrane_forces();
  // Rebuilds the inside fraction and viscosity once a node has moved more than
  // numerics.indicator_tolerance since the last rebuild (always when it is 0); true if it did.
  bool update_viscosity();
  void rebuild_viscosity();  // from x_indicator_
  // Fills order_ for the spreading and the interpolation, sorting the nodes only when
  // `resort` or when the order was not sorted from x_indicator_.
  void order_membrane_nodes(bool resort);
  void move_cells(double dt);
  // On the device path, copy its state back where the host's copy is out of date.
  void refresh_cells() const;
  void refresh_fluid() const;
  DeviceHostState host_state() const;

  SimulationCase case_;
  LatticeUnits units_;
  // The state. On the device path these are the host's copy of the device's state,
  // refreshed when read (hence mutable).
  mutable FluidLattice fluid_;
  std::unique_ptr<CellMembrane> membrane_;
  InsideFraction inside_;
  mutable std::vector<std::vector<Vec3>> x_, v_, f_;  // per cell: positions, velocities, membrane forces
  mutable std::vector<std::vector<Vec3>> x_indicator_;  // positions of the last inside-fraction build
  // Fluid velocity at every lattice node (x, y, z components, node_count() each), written
  // by the fluid steps before a membrane update: one evaluation of the moments per node
  // instead of one per stencil visit. Under the interval mean it holds the sum over the
  // u_field_steps_ fluid steps of the interval so far. Aligned, and in huge pages as the
  // populations are: with 4 KiB pages its three streams cost the N_a 12 anchors' fluid
  // update 0.4-1.1 ms/step more (docs/performance.md).
  mutable AlignedVector<double> u_field_;
  mutable int u_field_steps_ = 0;
  mutable StepTimings timings_;
  std::unique_ptr<DeviceStepper> device_;
  mutable bool cells_stale_ = false, fluid_stale_ = false;
  NodeOrder order_;  // of the membrane nodes, sorted at x_indicator_, gathered at x_ (node_order.hpp)
  bool order_from_indicator_ = false;  // order_ sorted from the current x_indicator_
  // A bound on how far any node has moved from x_indicator_: the sum over the membrane
  // updates since of the fastest node's step and the largest volume-correction shift
  // (infinite where not known, as after a restore). While it stays below the indicator
  // tolerance, update_viscosity skips its pass over all nodes, whose answer it knows.
  double drift_bound_ = std::numeric_limits<double>::infinity();
};

}  // namespace rbcal::solver
