#pragma once
// Guards on a running simulation: a non-finite viscosity, a cell whose volume has run
// away, or a membrane node faster than Mach 0.3 means the explicit coupling has become
// unstable, and nothing computed after that is worth keeping.
#include <cstdint>
#include <string>

#include "solver/simulation/shear_flow_simulation.hpp"

namespace rbcal::solver {

// Throws std::runtime_error naming the quantity, the cell (where there is one), the step
// and the strain when a guard trips.
void check_state(const Observables& o, std::int64_t step);

// The guards' wording: "run stopped at step N (strain S): what".
std::string run_stopped(std::int64_t step, double strain, const std::string& what);

// The node-speed guard's reason, checked at every membrane step and at every record.
std::string node_mach_exceeded(double mach);

}  // namespace rbcal::solver
