#include "solver/simulation/shear_flow_simulation.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "solver/coupling/immersed_boundary.hpp"
#include "solver/simulation/detail/cell_seeding.hpp"
#include "solver/simulation/checkpoint.hpp"
#include "solver/simulation/state_guards.hpp"

namespace rbcal::solver {

namespace {

// For the largest-displacement and fastest-node maxima: std::max drops a NaN, which would let
// a node gone NaN pass both checks unnoticed.
double nan_as_infinite(double x) { return std::isnan(x) ? std::numeric_limits<double>::infinity() : x; }

FluidConfig fluid_config(const LatticeUnits& u, bool quiescent, bool single_precision) {
  FluidConfig f;
  f.nx = u.nx;
  f.ny = u.ny;
  f.nz = u.nz;
  f.viscosity = u.nu_out;
  f.wall_velocity_bottom = quiescent ? 0.0 : -u.wall_speed;
  f.wall_velocity_top = quiescent ? 0.0 : u.wall_speed;
  f.single_precision = single_precision;
  return f;
}

}  // namespace

ShearFlowSimulation::ShearFlowSimulation(const SimulationCase& c, Backend backend)
    : case_(c),
      units_(derive_lattice_units(c.flow, c.resolution)),
      fluid_(fluid_config(units_, c.quiescent, c.single_precision)),
      inside_(units_.nx, units_.ny, units_.nz) {
  const double a = c.resolution.nodes_per_radius;  // the radius in lattice units
  CellMembraneSettings ms;
  ms.material = {c.law, units_.shear_modulus, c.effective_skalak_c()};
  ms.bending_modulus = units_.bending_modulus;
  ms.volume_stiffness = c.volume_stiffness * units_.shear_modulus / a;
  membrane_ = std::make_unique<CellMembrane>(reference_cell(c, a), ms);

  const Vec3 centre = box_centre();
  if (case_.cells.empty()) {
    // Seed for the target volume fraction, two lattice spacings (and a little) off the walls.
    const TriangleMesh unit_cell = reference_cell(c, 1.0);
    const double gap = 2.0 / a + 1e-6;
    const std::array<double, 3> box = {units_.nx / a, units_.ny / a, units_.nz / a};
    case_.cells = seed_cells(c.target_phi, unit_cell, box, gap, c.seed).placements;
  }
  for (std::size_t i = 0; i < case_.cells.size(); ++i) {
    std::vector<Vec3> x = placed_nodes(membrane_->reference(), case_.cells[i], centre, a);
    // Keep every node two spacings off the walls: the kernels reach that far.
    for (const Vec3& node : x)
      if (node.y() < 1.5 || node.y() > units_.ny - 2.5)
        throw std::invalid_argument("cell " + std::to_string(i) + " reaches within two lattice spacings of a wall");
    x_.push_back(std::move(x));
  }
  v_.assign(x_.size(), std::vector<Vec3>(membrane_->reference().vertices.size(), Vec3::Zero()));
  f_ = v_;

  // Start from the undisturbed linear shear profile.
  const double u_wall = c.quiescent ? 0.0 : units_.wall_speed;
  for (int ix = 0; ix < units_.nx; ++ix)
    for (int iy = 0; iy < units_.ny; ++iy)
      for (int iz = 0; iz < units_.nz; ++iz)
        fluid_.set_equilibrium(fluid_.index(ix, iy, iz), 1.0, 0.0, 0.0,
                               -u_wall + 2.0 * u_wall * (iy + 0.5) / units_.ny);
  update_viscosity();
  if (backend == Backend::Device) {
    device_ = std::make_unique<DeviceStepper>(case_, units_, *membrane_, x_.size());
    device_->upload(host_state(), 0);
  }
}

ShearFlowSimulation::~ShearFlowSimulation() = default;

DeviceHostState ShearFlowSimulation::host_state() const {
  return {&fluid_, &x_, &v_, &f_, &x_indicator_, &u_field_, &u_field_steps_};
}

void ShearFlowSimulation::device_fluid_steps(int steps) {
  if (!device_) throw std::logic_error("device_fluid_steps: not on the device backend");
  device_->fluid_steps(steps);
  fluid_stale_ = true;
}

void ShearFlowSimulation::refresh_cells() const {
  if (!cells_stale_) return;
  device_->download_cells(host_state());
  cells_stale_ = false;
}

void ShearFlowSimulation::refresh_fluid() const {
  if (!fluid_stale_) return;
  device_->download_fluid(host_state());
  fluid_stale_ = false;
}

const StepTimings& ShearFlowSimulation::timings() const {
  if (device_) {
    const DeviceTimings& d = device_->timings();
    timings_ = StepTimings{};
    timings_.membrane_forces = d.membrane_forces;
    timings_.spreading = d.spreading;
    timings_.indicator = d.indicator;
    timings_.indicator_builds = d.indicator_builds;
    timings_.fluid = d.fluid;
    timings_.interpolation = d.interpolation;
    timings_.steps = d.steps;
  }
  return timings_;
}

void ShearFlowSimulation::reset_timings() {
  timings_ = StepTimings{};
  if (device_) device_->reset_timings();
}

Vec3 ShearFlowSimulation::box_centre() const {
  return Vec3(0.5 * (units_.nx - 1), 0.5 * (units_.ny - 1), 0.5 * (units_.nz - 1));
}

void ShearFlowSimulation::compute_membrane_forces() {
#pragma omp parallel for schedule(dynamic)
  for (std::size_t i = 0; i < x_.size(); ++i) {
    std::fill(f_[i].begin(), f_[i].end(), Vec3::Zero());
    membrane_->add_forces(x_[i], f_[i]);
  }
}

bool ShearFlowSimulation::update_viscosity() {
  if (case_.flow.viscosity_ratio == 1.0) return false;
  const double tolerance = case_.indicator_tolerance;
  if (tolerance > 0.0 && x_indicator_.size() == x_.size()) {
    // The bound (with a margin for the rounding of the positions' sums) settles most steps.
    if (drift_bound_ <= (1.0 - 1e-9) * tolerance) return false;
    double largest = 0.0;  // squared displacement since the last build
#pragma omp parallel for schedule(static) reduction(max : largest)
    for (std::size_t i = 0; i < x_.size(); ++i)
      for (std::size_t m = 0; m < x_[i].size(); ++m)
        largest = std::max(largest, nan_as_infinite((x_[i][m] - x_indicator_[i][m]).squaredNorm()));
    if (largest <= tolerance * tolerance) return false;
  }
  x_indicator_ = x_;
  drift_bound_ = 0.0;
  rebuild_viscosity();
  return true;
}

void ShearFlowSimulation::order_membrane_nodes(bool resort) {
  // Sorted where the nodes stood at the last build of the inside fraction: none has moved
  // more than the indicator tolerance since (update_viscosity), within the drift the
  // spreading's slabs allow, and a resumed run sorts them from the same positions (the
  // checkpoint holds them), so every sum keeps its order. Sorting is most of the ordering's
  // cost; the inside fraction is rebuilt every 10 or so membrane updates on the bench case.
  // Without an inside fraction (lambda 1), sorted at every update where the nodes stand.
  const bool from_indicator =
      x_indicator_.size() == x_.size() && case_.indicator_tolerance <= NodeOrder::max_drift;
  if (!from_indicator || resort || !order_from_indicator_) {
    sort_nodes(case_.kernel, from_indicator ? x_indicator_ : x_, units_.nx, units_.ny, units_.nz, order_);
    order_from_indicator_ = from_indicator;
    ++timings_.ordering_sorts;
  }
  gather_nodes(x_, f_, order_);
}

void ShearFlowSimulation::rebuild_viscosity() {
  ++timings_.indicator_builds;
  std::vector<const std::vector<Vec3>*> meshes;
  for (const auto& x : x_indicator_) meshes.push_back(&x);
  inside_.update(meshes, membrane_->reference().triangles);
  double* nu = fluid_.viscosity();
  const double lambda = case_.flow.viscosity_ratio;
  const double* alpha = inside_.alpha().data();
  const double nu_out = units_.nu_out;
  // The footprints before and after the update, each without repeats (so parallel).
  for (const InsideFraction::Footprint* chunks : {&inside_.previous_footprint(), &inside_.footprint()}) {
    const long count = static_cast<long>(chunks->size());
#pragma omp parallel for schedule(dynamic)
    for (long k = 0; k < count; ++k)
      for (const std::size_t n : (*chunks)[k]) nu[n] = nu_out * (1.0 + (lambda - 1.0) * alpha[n]);
  }
}

void ShearFlowSimulation::move_cells(double dt) {
  const KernelKind k = case_.kernel;
  const int nx = units_.nx, ny = units_.ny, nz = units_.nz;
  const std::size_t stride = FluidLattice::component_stride(fluid_.node_count());
  const double* const u[3] = {u_field_.data(), u_field_.data() + stride, u_field_.data() + 2 * stride};
  // The field holds a sum over u_field_steps_ fluid steps (one but under the interval
  // mean); a division by 1 is exact, so k = 1 moves the nodes as before.
  const double steps = static_cast<double>(u_field_steps_);
  auto velocity_at = [&](const Vec3& p) {
    return Vec3(interpolate_field(make_stencil(k, p, nx, ny, nz), u, ny, nz) / steps);
  };
  // All nodes of all cells in one parallel loop, in the order of their stencils' rows
  // (order_membrane_nodes, gathered from these positions when the forces were spread).
  const std::size_t total = order_.nodes.size();
  constexpr std::size_t block = 64;  // nodes interpolated together (interpolate_sorted)
  const long blocks = static_cast<long>((total + block - 1) / block);
  double fastest = 0.0;  // squared node speed
  order_.velocity.resize(total);
#pragma omp parallel for schedule(static) reduction(max : fastest)
  for (long k = 0; k < blocks; ++k) {
    const std::size_t begin = static_cast<std::size_t>(k) * block, end = std::min(total, begin + block);
    Vec3 sampled[block];
    interpolate_sorted(order_, begin, end, u, sampled);
    for (std::size_t g = begin; g < end; ++g) {
      const Vec3& x = order_.position[g];
      const Vec3 u1 = sampled[g - begin] / steps;
      Vec3 velocity = u1;
      if (case_.integrator != Integrator::Euler) {
        // Classical RK4 through the velocity field of this step (over dt).
        const Vec3 u2 = velocity_at(x + (0.5 * dt) * u1);
        const Vec3 u3 = velocity_at(x + (0.5 * dt) * u2);
        const Vec3 u4 = velocity_at(x + dt * u3);
        velocity = (u1 + 2.0 * u2 + 2.0 * u3 + u4) / 6.0;
      }
      fastest = std::max(fastest, nan_as_infinite(velocity.squaredNorm()));
      order_.velocity[g] = velocity;
    }
  }
  // The explicit coupling's instability shows first as runaway node speeds. Caught here,
  // every membrane step, it stops the run before exploding meshes reach the inside
  // fraction (whose scan-line grid follows their bounding boxes: a blow-up caught only
  // at the next recorded row once grew past 7 GB).
  const double mach = std::sqrt(3.0 * fastest);
  if (!(mach < kMaxNodeMach)) {
    std::string hint;
    if (case_.coupling_interval > 1)
      hint = "; numerics.coupling_interval " + std::to_string(case_.coupling_interval) +
             " lowers the stiffness the coupling can take that many times: run it at 1 (rbcal simulate --resume"
             " --coupling-interval 1) or at a lower Re";
    throw std::runtime_error(node_mach_exceeded(mach) + hint);
  }
  double largest_shift = 0.0;  // by a volume correction
#pragma omp parallel for schedule(dynamic) reduction(max : largest_shift)
  for (std::size_t i = 0; i < x_.size(); ++i) {
    Vec3* const x = x_[i].data();  // raw pointers: the vectors' data are not reloaded per node
    Vec3* const v = v_[i].data();
    const std::uint32_t* const place = order_.sorted_place.data() + order_.cell_first[i];
    const Vec3* const sorted = order_.velocity.data();
    const std::size_t n = x_[i].size();
    constexpr std::size_t gather_ahead = 8;
    for (std::size_t m = 0; m < n; ++m) {
      if (m + gather_ahead < n) __builtin_prefetch(sorted + place[m + gather_ahead], 0, 3);
      v[m] = sorted[place[m]];
      x[m] += dt * v[m];
    }
    double shift = 0.0;
    correct_volume(x_[i], membrane_->reference().triangles, membrane_->reference_volume(), &shift);
    largest_shift = std::max(largest_shift, nan_as_infinite(shift));
  }
  drift_bound_ += dt * std::sqrt(fastest) + largest_shift;
}

ShearFlowSimulation::PrefetchChoice ShearFlowSimulation::set_prefetch_distance(int distance) {
  if (device_) return {};
  if (distance >= 0) {
    fluid_.set_prefetch_distance(distance);
    return {distance, false};
  }
  if (fluid_.node_count() < kPrefetchTimingNodes) return {fluid_.config().prefetch_distance, false};
  return {fluid_.choose_fastest_prefetch_distance(), true};
}

void ShearFlowSimulation::step() {
  if (device_) {
    device_->step();
    cells_stale_ = fluid_stale_ = true;
    return;
  }
  using clock = std::chrono::steady_clock;
  auto t = clock::now();
  auto lap = [&](double& into) {
    const auto now = clock::now();
    into += std::chrono::duration<double>(now - t).count();
    t = now;
  };
  // The membrane advances once every coupling_interval fluid steps (numerics.coupling_interval);
  // in between, the fluid steps under the frozen force and viscosity fields.
  const int interval = case_.coupling_interval;
  if (fluid_.steps_done() % interval == 0) {
    compute_membrane_forces();
    lap(timings_.membrane_forces);
    const bool rebuilt = update_viscosity();
    lap(timings_.indicator);
    order_membrane_nodes(rebuilt);
    lap(timings_.ordering);
    fluid_.clear_force();
    spread_forces(order_, fluid_);
    lap(timings_.spreading);
  }
  // The fluid writes the velocity field the membrane update interpolates: at every step
  // of the interval, summed, for the interval mean; at the last step for the last step's.
  const bool update_follows = (fluid_.steps_done() + 1) % interval == 0;
  const bool write_u = update_follows || case_.node_velocity == NodeVelocity::IntervalMean;
  const bool add_to_sum = write_u && case_.node_velocity == NodeVelocity::IntervalMean && u_field_steps_ > 0;
  const std::size_t stride = FluidLattice::component_stride(fluid_.node_count());
  if (write_u && u_field_.size() != 3 * stride) u_field_.assign(3 * stride, 0.0);
  double* const u[3] = {u_field_.data(), u_field_.data() + stride, u_field_.data() + 2 * stride};
  fluid_.step(write_u ? u : nullptr, add_to_sum);
  if (write_u) u_field_steps_ = add_to_sum ? u_field_steps_ + 1 : 1;
  lap(timings_.fluid);
  if (fluid_.steps_done() % interval == 0) {
    move_cells(static_cast<double>(interval));
    u_field_steps_ = 0;
    lap(timings_.interpolation);
  }
  ++timings_.steps;
}

void ShearFlowSimulation::save_checkpoint(const std::string& path) const {
  refresh_cells();
  refresh_fluid();
  CheckpointState s;
  s.case_json = state_defining_json(case_).dump();
  s.steps = fluid_.steps_done();
  s.populations = fluid_.populations();
  s.positions = x_;
  s.velocities = v_;
  s.forces = f_;
  s.indicator_positions = x_indicator_;
  // Inside an interval the velocity summed so far is part of the state (a sum is held only
  // there: the membrane update that ends an interval resets it).
  if (u_field_steps_ > 0) {
    s.velocity_sum.assign(u_field_.begin(), u_field_.end());
    s.velocity_sum_steps = u_field_steps_;
  }
  write_checkpoint(path, s);
}

int ShearFlowSimulation::restore_checkpoint(const std::string& path, bool any_coupling_interval) {
  CheckpointState s = read_checkpoint(path);
  nlohmann::json saved = nlohmann::json::parse(s.case_json), ours = state_defining_json(case_);
  const int saved_interval = saved["numerics"].value("coupling_interval", 1);
  // Checkpoints from before numerics.node_velocity moved their membranes by the last
  // step's velocity.
  if (saved_interval > 1 && !saved["numerics"].contains("node_velocity"))
    saved["numerics"]["node_velocity"] = to_string(NodeVelocity::LastStep);
  if (any_coupling_interval)
    for (nlohmann::json* j : {&saved, &ours}) {
      (*j)["numerics"].erase("coupling_interval");
      (*j)["numerics"].erase("node_velocity");
    }
  if (saved != ours) {
    // Where the node velocity is all that differs, say which one the checkpoint needs.
    auto without_node_velocity = [](nlohmann::json j) {
      j["numerics"].erase("node_velocity");
      return j;
    };
    const std::string hint =
        without_node_velocity(saved) == without_node_velocity(ours)
            ? " (it was run with numerics.node_velocity \"" + saved["numerics"].value("node_velocity", "") +
                  "\": set that in the case to resume it)"
            : "";
    throw std::runtime_error("checkpoint " + path + " belongs to a different case" + hint);
  }
  // The inside fraction is rebuilt from the positions it was built from before the stop.
  const bool contrast = case_.flow.viscosity_ratio != 1.0;
  if (s.positions.size() != x_.size() || (contrast && s.indicator_positions.size() != x_.size()))
    throw std::runtime_error("checkpoint " + path + ": wrong number of cells");
  for (std::size_t i = 0; i < x_.size(); ++i)
    if (s.positions[i].size() != x_[i].size() || s.velocities[i].size() != x_[i].size() ||
        s.forces[i].size() != x_[i].size() || (contrast && s.indicator_positions[i].size() != x_[i].size()))
      throw std::runtime_error("checkpoint " + path + ": cell " + std::to_string(i) + " has the wrong node count");
  fluid_.restore(s.populations, s.steps);
  // The velocity summed over the interval so far, when the checkpoint has it for this
  // lattice; otherwise the mean is taken over the interval's remaining steps.
  u_field_steps_ = 0;
  const bool inside_interval = s.steps % case_.coupling_interval != 0;
  if (inside_interval && case_.node_velocity == NodeVelocity::IntervalMean && s.velocity_sum_steps > 0 &&
      s.velocity_sum.size() == 3 * FluidLattice::component_stride(fluid_.node_count())) {
    u_field_.assign(s.velocity_sum.begin(), s.velocity_sum.end());
    u_field_steps_ = static_cast<int>(s.velocity_sum_steps);
  }
  x_ = std::move(s.positions);
  drift_bound_ = std::numeric_limits<double>::infinity();  // moved since x_indicator_, by how much unknown
  v_ = std::move(s.velocities);
  f_ = std::move(s.forces);
  // Within a coupling interval the force field is the one spread at its start, from the
  // positions and forces the checkpoint holds. (A run resumed under another interval
  // spreads it from them too: its next membrane update may be steps away.)
  if (contrast) {
    x_indicator_ = std::move(s.indicator_positions);
    rebuild_viscosity();
  }
  order_from_indicator_ = false;
  if (fluid_.steps_done() % case_.coupling_interval != 0 || saved_interval != case_.coupling_interval) {
    if (fluid_.steps_done() % saved_interval != 0) {
      // Inside the saved run's interval: the nodes have not moved since its membrane update,
      // which kept them within the tolerance of x_indicator_; sorted as that run sorted them.
      order_membrane_nodes(true);
    } else {
      // At the end of its interval they have moved since, possibly past the tolerance: sorted
      // where they stand (a run resumed under another interval, not bit for bit anyway).
      order_nodes(case_.kernel, x_, f_, units_.nx, units_.ny, units_.nz, order_);
    }
    fluid_.clear_force();
    spread_forces(order_, fluid_);
  }
  if (device_) {
    device_->upload(host_state(), fluid_.steps_done());
    cells_stale_ = fluid_stale_ = false;
  }
  return saved_interval;
}

Observables ShearFlowSimulation::observe() const {
  refresh_cells();
  Observables o;
  o.strain = strain();
  const double eta0 = units_.nu_out;  // rho = 1
  const double gamma = units_.shear_rate;
  const double box_volume = static_cast<double>(units_.nx) * units_.ny * units_.nz;
  const auto& tri = membrane_->reference().triangles;
  const double v0 = membrane_->reference_volume();
  const double a = case_.resolution.nodes_per_radius;
  Mat3 sum = Mat3::Zero();
  for (std::size_t i = 0; i < x_.size(); ++i) {
    sum += cell_stresslet(x_[i], f_[i], v_[i], tri, eta0, case_.flow.viscosity_ratio);
    CellObservables c;
    c.shape = shear_plane_shape(x_[i], tri);
    c.axis_vorticity = std::abs(short_axis(x_[i], tri).x());
    c.volume_error = enclosed_volume(x_[i], tri) / v0 - 1.0;
    c.centroid = (vertex_centroid(x_[i]) - box_centre()) / a;
    for (const Vec3& vel : v_[i]) o.max_mach = std::max(o.max_mach, vel.norm() * std::sqrt(3.0));
    o.cells.push_back(c);
  }
  o.eta_re_stresslet = 1.0 + sum(2, 1) / box_volume / (eta0 * gamma);
  if (device_) {
    const std::array<double, 2> t = device_->wall_shear_traction();
    o.eta_re_wall = 0.5 * (t[0] - t[1]) / (eta0 * gamma);
  } else {
    const WallTraction t = fluid_.wall_traction();
    o.eta_re_wall = 0.5 * (t.bottom[2] - t.top[2]) / (eta0 * gamma);
  }
  return o;
}

}  // namespace rbcal::solver
