#pragma once
// Strain-energy density w(I1, I2) of an isotropic hyperelastic membrane per unit
// reference area, in terms of the invariants I1 = lambda1^2 + lambda2^2 - 2 and
// I2 = lambda1^2 lambda2^2 - 1 of the in-plane stretch, with its partial derivatives.
// Units: those of G_s (N/m in SI, energy per area).
#include <stdexcept>
#include <string>

#include "solver/device/host_device.hpp"

namespace rbcal::solver {

enum class MembraneLaw { Skalak, NeoHookean };

struct MembraneMaterial {
  MembraneLaw law = MembraneLaw::Skalak;
  double shear_modulus = 1.0;     // G_s
  double area_dilation_c = 100.0;  // Skalak's C; area modulus K_s = G_s (1 + 2C)
};

struct EnergyDensity {
  double w;
  double dw_dI1;
  double dw_dI2;
};

// Skalak et al., Biophys. J. 13 (1973) 245: w = G_s/4 (I1^2 + 2 I1 - 2 I2 + C I2^2).
RBCAL_HD inline EnergyDensity skalak(double i1, double i2, double gs, double c) {
  return {0.25 * gs * (i1 * i1 + 2.0 * i1 - 2.0 * i2 + c * i2 * i2), 0.5 * gs * (i1 + 1.0),
          0.5 * gs * (c * i2 - 1.0)};
}

// Neo-Hookean (zero-thickness limit of an incompressible rubber sheet, as used in the
// capsule benchmarks, e.g. Barthes-Biesel, Diaz & Dhenin, J. Fluid Mech. 460 (2002) 211):
// w = G_s/2 (lambda1^2 + lambda2^2 - 3 + 1/(lambda1^2 lambda2^2)) = G_s/2 (I1 - 1 + 1/(I2 + 1)).
RBCAL_HD inline EnergyDensity neo_hookean(double i1, double i2, double gs) {
  const double inv_j2 = 1.0 / (i2 + 1.0);
  return {0.5 * gs * (i1 - 1.0 + inv_j2), 0.5 * gs, -0.5 * gs * inv_j2 * inv_j2};
}

inline EnergyDensity strain_energy(const MembraneMaterial& m, double i1, double i2) {
  return m.law == MembraneLaw::Skalak ? skalak(i1, i2, m.shear_modulus, m.area_dilation_c)
                                      : neo_hookean(i1, i2, m.shear_modulus);
}

inline std::string to_string(MembraneLaw law) { return law == MembraneLaw::Skalak ? "skalak" : "neo-hookean"; }

inline MembraneLaw membrane_law_from_string(const std::string& name) {
  if (name == "skalak") return MembraneLaw::Skalak;
  if (name == "neo-hookean") return MembraneLaw::NeoHookean;
  throw std::invalid_argument("unknown membrane law '" + name + "' (expected skalak or neo-hookean)");
}

}  // namespace rbcal::solver
