#pragma once
// Conversion from the dimensionless description of a sheared suspension case to lattice
// units (docs/reference.md, "Lattice units"). The lattice spacing is dx = a / N_a, the plasma density
// is 1 and its relaxation time tau_out fixes nu_out = (tau_out - 1/2) / 3; the
// Reynolds number Re = rho gamma_dot a^2 / eta0 then fixes the lattice shear rate
// gamma_dot = Re nu_out / N_a^2, and Ca fixes the lattice shear modulus.
#include <array>
#include <string>
#include <utility>
#include <vector>

namespace rbcal::solver {

struct FlowParameters {
  double capillary_number = 0.1;  // Ca = eta0 gamma_dot a / G_s
  double viscosity_ratio = 5.0;   // lambda = eta1 / eta0
  double reynolds_number = 0.2;   // Re = rho gamma_dot a^2 / eta0
  // kb_hat = k_b / (a^2 G_s); default from k_b = 5e-19 J, G_s = 4 uN/m, a = 4 um.
  double reduced_bending = 5e-19 / (4e-6 * 4e-6 * 4e-6);
};

struct LatticeResolution {
  int nodes_per_radius = 16;                            // N_a
  double tau_out = 1.0;                                 // plasma relaxation time
  std::array<double, 3> box_in_radii = {16.0, 10.0, 16.0};  // Lx, H, Lz in units of a
};

struct LatticeUnits {
  int nx = 0, ny = 0, nz = 0;  // lattice nodes along x, y, z
  double dx_over_a = 0.0;      // lattice spacing in cell radii
  double tau_out = 0.0, tau_in = 0.0;
  double nu_out = 0.0, nu_in = 0.0;  // kinematic viscosities outside / inside cells
  double shear_rate = 0.0;           // gamma_dot
  double wall_speed = 0.0;           // U = gamma_dot H / 2
  double mach = 0.0;                 // U / c_s
  double shear_modulus = 0.0;        // G_s (rho = 1)
  double bending_modulus = 0.0;      // k_b = kb_hat a^2 G_s

  // Name/value pairs, for run records and printing.
  std::vector<std::pair<std::string, double>> entries() const;
};

// Throws std::invalid_argument naming the offending input when a value is out of range
// or the box is not a whole number of lattice nodes.
LatticeUnits derive_lattice_units(const FlowParameters& flow, const LatticeResolution& resolution);

}  // namespace rbcal::solver
