#pragma once
// Plane Couette flow driven to steady state: the simplest end-to-end check of the
// fluid solver (walls, streaming, collision, momentum exchange), used by the
// `rbcal couette` demonstration and the tests.
#include <cstdint>
#include <vector>

#include "solver/fluid/fluid_lattice.hpp"

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

}  // namespace rbcal::solver
