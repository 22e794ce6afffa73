#pragma once
// The stiffness the explicit membrane-fluid coupling takes. Measured on the dense bench
// case (docs/performance.md, "The stability bound per kernel"): the run is stable while
//   K_s,lu k (sum_j phi_j^2)^3 <= 0.154,
// with K_s,lu the membrane's area modulus in lattice units, k the coupling interval (fluid
// steps per membrane step, with the interval's mean velocity) and sum phi^2 the kernel's
// one-dimensional self-weight (3/8 for Peskin's 4-point kernel, 1/2 for Roma's 3-point, at
// most 1 for the linear one). The bound is 0.154 at k = 1 and 2 alike.
#include "solver/simulation/simulation_case.hpp"

namespace rbcal::solver {

inline constexpr double kCouplingStabilityBound = 0.154;

// K_s,lu (sum phi^2)^3 of the case: the stiffness per unit coupling interval. K_s is
// G_s (1 + 2C) for Skalak membranes and 3 G_s (the small-strain area modulus) for
// neo-Hookean ones.
double coupling_stiffness(const SimulationCase& c);

// Whether the case at coupling interval k stays within the bound: k coupling_stiffness(c) <= it.
bool within_coupling_bound(const SimulationCase& c, int k);

// The largest coupling interval in [1, largest] within the bound (1 where even 1 is not).
int stable_coupling_interval(const SimulationCase& c, int largest = 2);

}  // namespace rbcal::solver
