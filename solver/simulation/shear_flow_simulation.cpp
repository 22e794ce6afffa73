#include "solver/simulation/shear_flow_simulation.hpp"

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "solver/coupling/immersed_boundary.hpp"
#include "solver/simulation/checkpoint.hpp"

namespace rbcal::solver {

namespace {

FluidConfig fluid_config(const LatticeUnits& u, bool quiescent) {
  FluidConfig f;
  f.nx = u.nx;
  f.ny = u.ny;
  f.nz = u.nz;
  f.viscosity = u.nu_out;
  f.wall_velocity_bottom = quiescent ? 0.0 : -u.wall_speed;
  f.wall_velocity_top = quiescent ? 0.0 : u.wall_speed;
  return f;
}

TriangleMesh reference_cell(const SimulationCase& c, double radius) {
  return c.shape == CellShape::Sphere ? make_sphere(c.triangles, radius)
                                      : make_biconcave_cell(c.triangles, radius, c.profile);
}

}  // namespace

ShearFlowSimulation::ShearFlowSimulation(const SimulationCase& c)
    : case_(c),
      units_(derive_lattice_units(c.flow, c.resolution)),
      fluid_(fluid_config(units_, c.quiescent)),
      inside_(units_.nx, units_.ny, units_.nz) {
  const double a = c.resolution.nodes_per_radius;  // the radius in lattice units
  CellMembraneSettings ms;
  ms.material = {c.law, units_.shear_modulus, c.skalak_c};
  ms.bending_modulus = units_.bending_modulus;
  ms.volume_stiffness = c.volume_stiffness * units_.shear_modulus / a;
  membrane_ = std::make_unique<CellMembrane>(reference_cell(c, a), ms);

  const Vec3 centre = box_centre();
  for (std::size_t i = 0; i < c.cells.size(); ++i) {
    const CellPlacement& p = c.cells[i];
    Vec3 axis(p.rotation[0], p.rotation[1], p.rotation[2]);
    if (axis.norm() == 0.0) axis = Vec3::UnitZ();
    const Eigen::Matrix3d rot = Eigen::AngleAxisd(p.rotation[3] * std::numbers::pi / 180.0, axis.normalized()).toRotationMatrix();
    const Vec3 at = centre + a * Vec3(p.center[0], p.center[1], p.center[2]);
    std::vector<Vec3> x;
    for (const Vec3& v : membrane_->reference().vertices) {
      x.push_back(at + rot * v);
      // Keep every node two spacings off the walls: the kernels reach that far.
      if (x.back().y() < 1.5 || x.back().y() > units_.ny - 2.5)
        throw std::invalid_argument("cell " + std::to_string(i) + " reaches within two lattice spacings of a wall");
    }
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

void ShearFlowSimulation::update_viscosity() {
  if (case_.flow.viscosity_ratio == 1.0) return;
  std::vector<const std::vector<Vec3>*> meshes;
  for (const auto& x : x_) meshes.push_back(&x);
  inside_.update(meshes, membrane_->reference().triangles);
  double* nu = fluid_.viscosity();
  const double lambda = case_.flow.viscosity_ratio;
  for (std::size_t n : inside_.touched()) nu[n] = units_.nu_out * (1.0 + (lambda - 1.0) * inside_.alpha()[n]);
}

void ShearFlowSimulation::move_cells() {
  const KernelKind k = case_.kernel;
  for (std::size_t i = 0; i < x_.size(); ++i) {
    std::vector<Vec3>& x = x_[i];
    std::vector<Vec3>& v = v_[i];
    const long n = static_cast<long>(x.size());
#pragma omp parallel for schedule(static)
    for (long m = 0; m < n; ++m) {
      const Vec3 u1 = interpolate_velocity(k, fluid_, x[m]);
      if (case_.integrator == Integrator::Euler) {
        v[m] = u1;
      } else {
        // Classical RK4 through the velocity field of this step (dt = 1).
        const Vec3 u2 = interpolate_velocity(k, fluid_, x[m] + 0.5 * u1);
        const Vec3 u3 = interpolate_velocity(k, fluid_, x[m] + 0.5 * u2);
        const Vec3 u4 = interpolate_velocity(k, fluid_, x[m] + u3);
        v[m] = (u1 + 2.0 * u2 + 2.0 * u3 + u4) / 6.0;
      }
    }
    for (long m = 0; m < n; ++m) x[m] += v[m];
    correct_volume(x, membrane_->reference().triangles, membrane_->reference_volume());
  }
}

void ShearFlowSimulation::step() {
  compute_membrane_forces();
  fluid_.clear_force();
  for (std::size_t i = 0; i < x_.size(); ++i) spread_forces(case_.kernel, x_[i], f_[i], fluid_);
  update_viscosity();
  fluid_.step();
  move_cells();
}

void ShearFlowSimulation::save_checkpoint(const std::string& path) const {
  CheckpointState s;
  s.case_json = state_defining_json(case_).dump();
  s.steps = fluid_.steps_done();
  s.populations.assign(fluid_.populations().begin(), fluid_.populations().end());
  s.positions = x_;
  s.velocities = v_;
  s.forces = f_;
  write_checkpoint(path, s);
}

void ShearFlowSimulation::restore_checkpoint(const std::string& path) {
  CheckpointState s = read_checkpoint(path);
  if (s.case_json != state_defining_json(case_).dump())
    throw std::runtime_error("checkpoint " + path + " belongs to a different case");
  if (s.positions.size() != x_.size()) throw std::runtime_error("checkpoint " + path + ": wrong number of cells");
  for (std::size_t i = 0; i < x_.size(); ++i)
    if (s.positions[i].size() != x_[i].size() || s.velocities[i].size() != x_[i].size() ||
        s.forces[i].size() != x_[i].size())
      throw std::runtime_error("checkpoint " + path + ": cell " + std::to_string(i) + " has the wrong node count");
  fluid_.restore(s.populations, s.steps);
  x_ = std::move(s.positions);
  v_ = std::move(s.velocities);
  f_ = std::move(s.forces);
  update_viscosity();
}

Observables ShearFlowSimulation::observe() const {
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
    c.volume_error = enclosed_volume(x_[i], tri) / v0 - 1.0;
    c.centroid = (vertex_centroid(x_[i]) - box_centre()) / a;
    for (const Vec3& vel : v_[i]) o.max_mach = std::max(o.max_mach, vel.norm() * std::sqrt(3.0));
    o.cells.push_back(c);
  }
  o.eta_re_stresslet = 1.0 + sum(2, 1) / box_volume / (eta0 * gamma);
  const WallTraction t = fluid_.wall_traction();
  o.eta_re_wall = 0.5 * (t.bottom[2] - t.top[2]) / (eta0 * gamma);
  return o;
}

}  // namespace rbcal::solver
