#pragma once
// Plane Couette flow driven to steady state: the simplest end-to-end check of the
// fluid solver (walls, streaming, collision, momentum exchange), used by the
// `rbcal couette` demonstration and the tests.
#include <cstdint>
#include <vector>

#include "solver/fluid/fluid_lattice.hpp"
#include "solver/lattice_units.hpp"

namespace rbcal::solver {

struct CouetteRun {
  std::int64_t max_steps = 1000000;
  int check_interval = 200;
  // Stop when the profile changes by less than this (relative to the wall speed
  // difference) over one check interval.
  double tolerance = 1e-12;
};

struct CouetteResult {
  std::int64_t steps = 0;
  bool converged = false;
  double imposed_shear_rate = 0.0;   // (U_top - U_bottom) / ny, lattice units
  double measured_shear_rate = 0.0;  // least-squares slope of u_z(y)
  double wall_shear_stress = 0.0;    // mean of the two walls' tractions, sign of the flow
  std::vector<double> profile;       // u_z(y) averaged over x and z
};

// Plane-averaged streamwise velocity u_z(y).
std::vector<double> streamwise_profile(const FluidLattice& fluid);

// Runs the lattice (configured with MovingWalls) until steady or max_steps.
CouetteResult run_to_steady_couette(FluidLattice& fluid, const CouetteRun& run);

// The demonstration in physical units (`rbcal couette`): plasma between walls a gap H apart
// sheared at gamma_dot, simulated on the lattice that docs/reference.md derives for N_a,
// tau and Re, and converted back to SI through dt = gamma_dot_lu / gamma_dot and the
// stress scale eta0 gamma_dot / (nu gamma_dot_lu).
struct CouetteDemo {
  double shear_rate = 100.0;           // 1/s
  double plasma_viscosity = 1.569e-3;  // Pa s (seed study, plasma at 22 C)
  double radius = 4e-6;                // m: dx = radius / nodes_per_radius
  double height_in_radii = 10.0;
  int nodes_per_radius = 8;
  double tau = 1.0;
  double reynolds = 0.2;
  double tolerance = 1e-12;
};

struct CouetteDemoResult {
  LatticeUnits lattice;
  CouetteResult run;
  double dt = 0.0;                  // s per lattice step
  double measured_shear_rate = 0.0;  // 1/s
  double wall_shear_stress = 0.0;    // Pa
  double viscosity_from_walls = 0.0;  // Pa s
};

// Throws std::invalid_argument naming the field for a non-positive rate, viscosity or radius.
CouetteDemoResult run_couette_demo(const CouetteDemo& demo);

}  // namespace rbcal::solver
