#pragma once
// The capillary number that links a measured shear rate to the simulated flows:
// Ca = eta0 * gamma_dot * a / G_s (docs/reference.md; seed study, Takeishi et al., eq. for Ca).
// SI units throughout: eta0 [Pa s], gamma_dot [1/s], a [m], G_s [N/m].

namespace rbcal::calibration {

// Default major RBC radius used by the seed study (<a> = 4 um).
inline constexpr double kDefaultCellRadius = 4e-6;

inline double capillary_number(double plasma_viscosity, double shear_rate, double cell_radius,
                               double shear_modulus) {
  return plasma_viscosity * shear_rate * cell_radius / shear_modulus;
}

// The shear rate at which a cell of modulus G_s meets a given Ca: gamma_dot = Ca G_s / (eta0 a).
inline double shear_rate_from_capillary_number(double plasma_viscosity, double cell_radius, double shear_modulus,
                                               double ca) {
  return ca * shear_modulus / (plasma_viscosity * cell_radius);
}

// The inverse: G_s = eta0 * gamma_dot * a / Ca (seed study, <G_s> = eta0 gamma_dot <a> / Ca).
inline double shear_modulus_from_capillary_number(double plasma_viscosity, double shear_rate,
                                                  double cell_radius, double ca) {
  return plasma_viscosity * shear_rate * cell_radius / ca;
}

}  // namespace rbcal::calibration
