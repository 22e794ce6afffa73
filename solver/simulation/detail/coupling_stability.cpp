#include "solver/simulation/detail/coupling_stability.hpp"

#include <algorithm>

#include "solver/lattice_units.hpp"

namespace rbcal::solver {

double coupling_stiffness(const SimulationCase& c) {
  const LatticeUnits u = derive_lattice_units(c.flow, c.resolution);
  const double area_modulus = c.law == MembraneLaw::Skalak ? u.shear_modulus * (1.0 + 2.0 * c.effective_skalak_c())
                                                           : 3.0 * u.shear_modulus;
  const double self_weight = c.kernel == KernelKind::Peskin4 ? 3.0 / 8.0 : c.kernel == KernelKind::Roma3 ? 0.5 : 1.0;
  return area_modulus * self_weight * self_weight * self_weight;
}

bool within_coupling_bound(const SimulationCase& c, int k) {
  return k * coupling_stiffness(c) <= kCouplingStabilityBound;
}

int stable_coupling_interval(const SimulationCase& c, int largest) {
  int k = 1;
  while (k < largest && within_coupling_bound(c, k + 1)) ++k;
  return k;
}

}  // namespace rbcal::solver
