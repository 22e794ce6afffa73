#pragma once
// A rheometer sample whose true G_s is known (simulated truth): simulated eta_re at given
// (phi, Ca, lambda) turned into what a rheometer would read at a chosen G_s, eta0 and a,
//     shear rate = Ca G_s / (eta0 a),   viscosity = eta0 eta_re (1 + noise z),  z ~ N(0, 1),
// with the sd the reading reports: the relative noise and the run's own standard error in
// quadrature. eta0 comes as one plasma_assumed row with its sd. Calibrating such a sample
// and asking whether the intervals hold the G_s it was made with tests the model's level and
// the methods' coverage together (calibration/known_truth_recovery.hpp).
#include <cstdint>
#include <string>
#include <vector>

#include "calibration/capillary_number.hpp"
#include "calibration/rheometer_data.hpp"

namespace rbcal::calibration {

// One simulated point: the continuum volume fraction it stands for, its Ca and lambda, and the
// run's eta_re with its standard error.
struct SimulatedViscosity {
  std::string id;
  double phi = 0.0;
  double capillary_number = 0.0;
  double viscosity_ratio = 0.0;
  double eta_re = 1.0;
  double eta_re_se = 0.0;
};

struct SyntheticSampleOptions {
  std::string name = "synthetic";
  double shear_modulus = 2e-6;                 // the truth G_s [N/m]
  double plasma_viscosity = 1.2e-3;            // eta0 [Pa s]
  double plasma_viscosity_relative_sd = 0.02;  // the sd of the plasma_assumed row, relative to eta0
  double cell_radius = kDefaultCellRadius;     // a [m]
  double relative_noise = 0.05;                // sd of the multiplicative reading error
  std::uint64_t seed = 1;                      // of the noise: one sample per seed
};

// Throws std::invalid_argument naming the option or the point (by id) that is out of range:
// no points, G_s, eta0 or a not positive, noise negative, phi outside (0, 1), Ca, eta_re not
// positive, two points at one (phi, shear rate).
RheometerData synthetic_rheometer_data(const std::vector<SimulatedViscosity>& points,
                                       const SyntheticSampleOptions& options);

}  // namespace rbcal::calibration
