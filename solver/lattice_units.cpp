#include "solver/lattice_units.hpp"

#include <cmath>
#include <stdexcept>

namespace rbcal::solver {

namespace {

void require(bool ok, const std::string& what) {
  if (!ok) throw std::invalid_argument("lattice units: " + what);
}

int nodes_along(double length_in_radii, int nodes_per_radius, const char* name) {
  const double nodes = length_in_radii * nodes_per_radius;
  const double rounded = std::round(nodes);
  require(rounded >= 1.0 && std::abs(nodes - rounded) < 1e-9,
          std::string(name) + " = " + std::to_string(length_in_radii) +
              " radii is not a whole number of lattice nodes at N_a = " +
              std::to_string(nodes_per_radius));
  return static_cast<int>(rounded);
}

}  // namespace

LatticeUnits derive_lattice_units(const FlowParameters& flow, const LatticeResolution& res) {
  require(flow.capillary_number > 0.0, "Ca must be positive");
  require(flow.viscosity_ratio > 0.0, "lambda must be positive");
  require(flow.reynolds_number > 0.0, "Re must be positive");
  require(flow.reduced_bending >= 0.0, "reduced bending modulus must be >= 0");
  require(res.nodes_per_radius >= 1, "N_a must be >= 1");
  require(res.tau_out > 0.5, "tau_out must exceed 1/2");

  LatticeUnits u;
  const double n_a = res.nodes_per_radius;
  u.nx = nodes_along(res.box_in_radii[0], res.nodes_per_radius, "box Lx");
  u.ny = nodes_along(res.box_in_radii[1], res.nodes_per_radius, "box H");
  u.nz = nodes_along(res.box_in_radii[2], res.nodes_per_radius, "box Lz");
  u.dx_over_a = 1.0 / n_a;
  u.tau_out = res.tau_out;
  u.nu_out = (res.tau_out - 0.5) / 3.0;
  u.nu_in = flow.viscosity_ratio * u.nu_out;
  u.tau_in = 3.0 * u.nu_in + 0.5;
  u.shear_rate = flow.reynolds_number * u.nu_out / (n_a * n_a);
  u.wall_speed = 0.5 * u.shear_rate * u.ny;
  u.mach = u.wall_speed * std::sqrt(3.0);
  u.shear_modulus = u.nu_out * u.shear_rate * n_a / flow.capillary_number;
  u.bending_modulus = flow.reduced_bending * n_a * n_a * u.shear_modulus;
  return u;
}

std::vector<std::pair<std::string, double>> LatticeUnits::entries() const {
  return {{"nx", double(nx)},         {"ny", double(ny)},
          {"nz", double(nz)},         {"dx_over_a", dx_over_a},
          {"tau_out", tau_out},       {"tau_in", tau_in},
          {"nu_out", nu_out},         {"nu_in", nu_in},
          {"shear_rate", shear_rate}, {"wall_speed", wall_speed},
          {"mach", mach},             {"shear_modulus", shear_modulus},
          {"bending_modulus", bending_modulus}};
}

}  // namespace rbcal::solver
