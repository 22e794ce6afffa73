#include "solver/device/device_stepper.hpp"

#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>

#include "solver/device/detail/device_kernels.hpp"
#include "solver/device/detail/device_runtime.hpp"
#include "solver/fluid/d3q19.hpp"
#include "solver/simulation/shear_flow_simulation.hpp"
#include "solver/simulation/state_guards.hpp"

namespace rbcal::solver {

namespace dk = device_kernels;
using device::Buffer;

bool device_is_gpu() { return device::kOnGpu; }

std::string device_description() {
#if defined(__CUDACC__)
  int id = 0;
  device::check(cudaGetDevice(&id), "cudaGetDevice");
  cudaDeviceProp p{};
  device::check(cudaGetDeviceProperties(&p, id), "cudaGetDeviceProperties");
  return std::string(p.name) + ", " + std::to_string(p.multiProcessorCount) + " SMs, " +
         std::to_string(p.totalGlobalMem >> 30) + " GiB";
#else
  return "host threads";
#endif
}

struct DeviceStepper::Impl {
  // The case.
  dk::LatticeShape lattice{};
  bool walls = true;
  double u_bottom = 0, u_top = 0, magic = 3.0 / 16.0, nu_out = 0, lambda = 1;
  KernelKind kernel = KernelKind::Peskin4;
  bool rk4 = false, interval_mean = true;
  int interval = 1;
  double indicator_tolerance = 0;
  dk::Cells cells{};
  std::size_t triangles = 0, hinges = 0;
  MembraneMaterial material;
  bool bending = false;
  double kd = 0, volume_stiffness = 0, v0 = 0;
  std::size_t packed = 0;  // FluidLattice::populations() stride
  bool single = false;     // populations in float, as f_q - w_q (numerics.precision)

  // The state.
  Buffer<double> f, f_next, force, viscosity, velocity;
  Buffer<float> h, h_next;  // the populations in float storage
  int velocity_steps = 0;
  std::int64_t steps = 0;
  Buffer<double> x, v, forces, x_indicator;
  bool indicator_built = false;
  // The meshes (shared by all cells).
  Buffer<int> triangle_nodes, hinge_nodes;
  Buffer<ElasticElementReference> triangle_reference;
  Buffer<HingeReference> hinge_reference;
  // Scratch.
  Buffer<double> gradient, cell_volume, cell_norm2, scalar;
  Buffer<double> partial, jump, column_base;
  Buffer<int> oversized;

  DeviceTimings timings;
  bool timing = false;

  void membrane_forces();
  void spread();
  void update_viscosity();
  void rebuild_viscosity();
  void fluid_step(bool write_velocity, bool accumulate);
  void move_cells(double dt);
  double read_scalar() const {
    double value = 0.0;
    scalar.download(&value, 1);
    return value;
  }
};

DeviceStepper::DeviceStepper(const SimulationCase& c, const LatticeUnits& u, const CellMembrane& membrane,
                             std::size_t cells)
    : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  m.single = c.single_precision;
  m.lattice = {u.nx, u.ny, u.nz, static_cast<std::size_t>(u.nx) * u.ny * u.nz};
  m.u_bottom = c.quiescent ? 0.0 : -u.wall_speed;
  m.u_top = c.quiescent ? 0.0 : u.wall_speed;
  m.nu_out = u.nu_out;
  m.lambda = c.flow.viscosity_ratio;
  m.kernel = c.kernel;
  m.rk4 = c.integrator != Integrator::Euler;
  m.interval_mean = c.node_velocity == NodeVelocity::IntervalMean;
  m.interval = c.coupling_interval;
  m.indicator_tolerance = c.indicator_tolerance;
  const TriangleMesh& mesh = membrane.reference();
  m.cells = {cells, mesh.vertices.size()};
  m.triangles = mesh.triangles.size();
  m.material = membrane.elasticity().material();
  m.bending = membrane.has_bending();
  m.kd = membrane.bending().hinge_constant();
  m.volume_stiffness = membrane.volume_stiffness();
  m.v0 = membrane.reference_volume();

  const std::size_t n = m.lattice.nodes;
  if (m.single) {
    m.h.resize(d3q19::Q * n);
    m.h_next.resize(d3q19::Q * n);
  } else {
    m.f.resize(d3q19::Q * n);
    m.f_next.resize(d3q19::Q * n);
  }
  m.force.resize(3 * n);
  m.viscosity.resize(n);
  m.velocity.resize(3 * n);
  const std::size_t nodes = m.cells.nodes();
  for (Buffer<double>* b : {&m.x, &m.v, &m.forces, &m.x_indicator, &m.gradient}) b->resize(3 * nodes);
  m.cell_volume.resize(cells);
  m.cell_norm2.resize(cells);
  m.scalar.resize(2);
  m.oversized.resize(1);
  if (m.lambda != 1.0) {
    m.partial.resize(n);
    m.jump.resize(n);
    m.column_base.resize(static_cast<std::size_t>(u.nx) * u.ny);
  }

  std::vector<int> tri;
  for (const Triangle& t : mesh.triangles) tri.insert(tri.end(), t.begin(), t.end());
  m.triangle_nodes.resize(tri.size());
  m.triangle_nodes.upload(tri.data(), tri.size());
  const MembraneElasticity::Elements& e = membrane.elasticity().elements();
  std::vector<ElasticElementReference> ref(m.triangles);
  for (std::size_t i = 0; i < ref.size(); ++i)
    ref[i] = {e.inv_g11[i], e.inv_g12[i], e.inv_g22[i], e.inv_det_g[i], e.area[i]};
  m.triangle_reference.resize(ref.size());
  m.triangle_reference.upload(ref.data(), ref.size());
  if (m.bending) {
    std::vector<int> h;
    for (const Hinge& hinge : membrane.bending().hinges()) h.insert(h.end(), {hinge.a, hinge.b, hinge.c, hinge.d});
    const std::vector<HingeReference> href = membrane.bending().references();
    m.hinges = href.size();
    m.hinge_nodes.resize(h.size());
    m.hinge_nodes.upload(h.data(), h.size());
    m.hinge_reference.resize(href.size());
    m.hinge_reference.upload(href.data(), href.size());
  }
}

DeviceStepper::~DeviceStepper() = default;

void DeviceStepper::upload(const DeviceHostState& host, std::int64_t steps) {
  Impl& m = *impl_;
  const std::size_t n = m.lattice.nodes;
  const std::vector<double> populations = host.fluid->populations();
  m.packed = populations.size() / d3q19::Q;
  std::vector<float> shifted(m.single ? n : 0);
  for (int q = 0; q < d3q19::Q; ++q) {
    const double* from = populations.data() + q * m.packed;
    if (m.single) {
      for (std::size_t i = 0; i < n; ++i) shifted[i] = static_cast<float>(from[i] - d3q19::w[q]);
      m.h.upload(shifted.data(), n, q * n);
    } else {
      m.f.upload(from, n, q * n);
    }
  }
  for (int d = 0; d < 3; ++d) m.force.upload(host.fluid->force(d), n, d * n);
  m.viscosity.upload(host.fluid->viscosity(), n);
  m.velocity_steps = 0;
  const std::size_t stride = FluidLattice::component_stride(n);
  if (*host.velocity_sum_steps > 0 && host.velocity_sum->size() == 3 * stride) {
    for (int d = 0; d < 3; ++d) m.velocity.upload(host.velocity_sum->data() + d * stride, n, d * n);
    m.velocity_steps = *host.velocity_sum_steps;
  }
  const std::size_t per_cell = m.cells.nodes_per_cell;
  auto upload_cells = [&](const std::vector<std::vector<Vec3>>& from, Buffer<double>& to) {
    for (std::size_t c = 0; c < from.size(); ++c) to.upload(from[c].front().data(), 3 * per_cell, 3 * c * per_cell);
  };
  upload_cells(*host.positions, m.x);
  upload_cells(*host.velocities, m.v);
  upload_cells(*host.forces, m.forces);
  m.indicator_built = host.indicator_positions->size() == m.cells.count && m.cells.count > 0;
  if (m.indicator_built) upload_cells(*host.indicator_positions, m.x_indicator);
  m.steps = steps;
}

void DeviceStepper::download_cells(const DeviceHostState& host) const {
  const Impl& m = *impl_;
  const std::size_t per_cell = m.cells.nodes_per_cell;
  auto download = [&](const Buffer<double>& from, std::vector<std::vector<Vec3>>& to) {
    to.resize(m.cells.count, std::vector<Vec3>(per_cell, Vec3::Zero()));
    for (std::size_t c = 0; c < m.cells.count; ++c) from.download(to[c].front().data(), 3 * per_cell, 3 * c * per_cell);
  };
  download(m.x, *host.positions);
  download(m.v, *host.velocities);
  download(m.forces, *host.forces);
  if (m.indicator_built) download(m.x_indicator, *host.indicator_positions);
}

void DeviceStepper::download_fluid(const DeviceHostState& host) const {
  const Impl& m = *impl_;
  const std::size_t n = m.lattice.nodes;
  std::vector<double> populations(d3q19::Q * m.packed, 0.0);
  std::vector<float> shifted(m.single ? n : 0);
  for (int q = 0; q < d3q19::Q; ++q) {
    double* to = populations.data() + q * m.packed;
    if (m.single) {
      m.h.download(shifted.data(), n, q * n);
      for (std::size_t i = 0; i < n; ++i) to[i] = static_cast<double>(shifted[i]) + d3q19::w[q];
    } else {
      m.f.download(to, n, q * n);
    }
  }
  host.fluid->restore(populations, m.steps);
  *host.velocity_sum_steps = m.velocity_steps;
  if (m.velocity_steps > 0) {
    const std::size_t stride = FluidLattice::component_stride(n);
    host.velocity_sum->assign(3 * stride, 0.0);
    for (int d = 0; d < 3; ++d) m.velocity.download(host.velocity_sum->data() + d * stride, n, d * n);
  }
}

void DeviceStepper::Impl::membrane_forces() {
  forces.fill_zero();
  dk::elastic_forces(material.law, cells, x.data(), triangle_nodes.data(), triangle_reference.data(), triangles,
                     material.shear_modulus, material.area_dilation_c, forces.data());
  if (bending) dk::bending_forces(cells, x.data(), hinge_nodes.data(), hinge_reference.data(), hinges, kd, forces.data());
  if (volume_stiffness > 0.0) {
    cell_volume.fill_zero();
    gradient.fill_zero();
    dk::volume_and_gradient(cells, x.data(), triangle_nodes.data(), triangles, cell_volume.data(), gradient.data());
    dk::add_volume_penalty(cells, gradient.data(), cell_volume.data(), volume_stiffness, v0, forces.data());
  }
}

void DeviceStepper::Impl::spread() {
  force.fill_zero();
  dk::spread_forces(lattice, kernel, cells.nodes(), x.data(), forces.data(), force.data());
}

void DeviceStepper::Impl::update_viscosity() {
  if (lambda == 1.0) return;
  if (indicator_tolerance > 0.0 && indicator_built) {
    scalar.fill_zero();
    dk::max_displacement2(cells.nodes(), x.data(), x_indicator.data(), scalar.data());
    if (read_scalar() <= indicator_tolerance * indicator_tolerance) return;
  }
  x_indicator.copy_from(x);
  indicator_built = true;
  rebuild_viscosity();
}

void DeviceStepper::Impl::rebuild_viscosity() {
  ++timings.indicator_builds;
  partial.fill_zero();
  jump.fill_zero();
  column_base.fill_zero();
  oversized.fill_zero();
  dk::inside_crossings(lattice, 2, cells, x_indicator.data(), triangle_nodes.data(), triangles, partial.data(),
                       jump.data(), column_base.data(), oversized.data());
  int blown_up = 0;
  oversized.download(&blown_up, 1);
  if (blown_up)
    throw std::runtime_error("inside fraction: a cell spans more than the lattice in x or y (the membrane has blown up)");
  dk::viscosity_from_crossings(lattice, partial.data(), jump.data(), column_base.data(), nu_out, lambda,
                               viscosity.data());
}

void DeviceStepper::Impl::fluid_step(bool write_velocity, bool accumulate) {
  dk::FluidUpdate a{single ? nullptr : f.data(), single ? nullptr : f_next.data(), single ? h.data() : nullptr,
                    single ? h_next.data() : nullptr, viscosity.data(), force.data(),
                    write_velocity ? velocity.data() : nullptr, accumulate, walls, u_bottom, u_top, magic};
  dk::fluid_update(lattice, a);
  f.swap(f_next);
  h.swap(h_next);
  ++steps;
}

void DeviceStepper::Impl::move_cells(double dt) {
  scalar.fill_zero();
  dk::interpolate_velocities(lattice, kernel, cells.nodes(), x.data(), velocity.data(),
                             static_cast<double>(velocity_steps), rk4, dt, v.data(), scalar.data());
  // The explicit coupling's instability shows first as runaway node speeds (as on the CPU).
  const double mach = std::sqrt(3.0 * read_scalar());
  if (!(mach < kMaxNodeMach)) throw std::runtime_error(node_mach_exceeded(mach));
  dk::advance_positions(cells.nodes(), v.data(), dt, x.data());
  cell_volume.fill_zero();
  gradient.fill_zero();
  cell_norm2.fill_zero();
  dk::volume_and_gradient(cells, x.data(), triangle_nodes.data(), triangles, cell_volume.data(), gradient.data());
  dk::correct_volumes(cells, gradient.data(), cell_volume.data(), v0, cell_norm2.data(), x.data());
}

void DeviceStepper::step() {
  Impl& m = *impl_;
  using clock = std::chrono::steady_clock;
  auto t = clock::now();
  auto lap = [&](double& into) {
    if (!m.timing) return;
    device::synchronize();
    const auto now = clock::now();
    into += std::chrono::duration<double>(now - t).count();
    t = now;
  };
  const bool has_cells = m.cells.count > 0;
  if (m.steps % m.interval == 0 && has_cells) {
    m.membrane_forces();
    lap(m.timings.membrane_forces);
    m.spread();
    lap(m.timings.spreading);
    m.update_viscosity();
    lap(m.timings.indicator);
  }
  // The velocity field as ShearFlowSimulation::step writes it: every step of the interval,
  // summed, for the interval mean; the last step's otherwise.
  const bool update_follows = (m.steps + 1) % m.interval == 0;
  const bool write_u = update_follows || m.interval_mean;
  const bool add_to_sum = write_u && m.interval_mean && m.velocity_steps > 0;
  m.fluid_step(write_u, add_to_sum);
  if (write_u) m.velocity_steps = add_to_sum ? m.velocity_steps + 1 : 1;
  lap(m.timings.fluid);
  if (m.steps % m.interval == 0) {
    if (has_cells) m.move_cells(static_cast<double>(m.interval));
    m.velocity_steps = 0;
    lap(m.timings.interpolation);
  }
  ++m.timings.steps;
}

void DeviceStepper::fluid_steps(int steps) {
  for (int i = 0; i < steps; ++i) impl_->fluid_step(false, false);
  device::synchronize();
}

std::int64_t DeviceStepper::steps_done() const { return impl_->steps; }

std::array<double, 2> DeviceStepper::wall_shear_traction() const {
  Impl& m = *impl_;
  m.scalar.fill_zero();
  if (m.walls)
    dk::wall_shear_traction(m.lattice, m.single ? nullptr : m.f.data(), m.single ? m.h.data() : nullptr, m.u_bottom,
                            m.u_top, m.scalar.data());
  std::array<double, 2> t{};
  m.scalar.download(t.data(), 2);
  return t;
}

void DeviceStepper::set_timing(bool on) { impl_->timing = on; }
const DeviceTimings& DeviceStepper::timings() const { return impl_->timings; }
void DeviceStepper::reset_timings() { impl_->timings = DeviceTimings{}; }

double device_copy_bandwidth(std::size_t bytes, int repeats) { return dk::copy_bandwidth(bytes, repeats); }

}  // namespace rbcal::solver
