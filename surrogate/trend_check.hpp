#pragma once
// The physical trends a library must show before the calibration can trust it, checked on a
// model over a probe grid inside its range:
//  - eta_re rises with phi at every (Ca, lambda) of the grid;
//  - eta_re falls with Ca (shear thinning) at every phi >= 0.21 and lambda;
//  - at phi 0.41, Ca 0.8, lambda 5 (or the nearest the range allows) it lies within 25 %
//    of blood at high shear: the large-tube in-vitro correlation of Pries, Neuhaus and
//    Gaehtgens, Am. J. Physiol. 263 (1992) H1770, eta_rel = 1 + 2.2 ((1 - H)^-0.8 - 1) /
//    (0.55^-0.8 - 1) (eta_45 = 3.2, C = -0.8; transcription in docs/validation.md);
//  - the dilute end: the intrinsic viscosity (eta_re - 1) / phi at the smallest probed phi,
//    reported at the lowest and highest Ca (no pass/fail: docs/library.md compares it).
#include <cmath>
#include <string>
#include <vector>

#include "surrogate/viscosity_model.hpp"

namespace rbcal::surrogate {

double pries_1992_relative_viscosity(double hematocrit);

struct TrendViolation : ParameterPoint {  // the lower end of the failing step
  double eta_re_here, eta_re_next;                // at this point and the next along the trend's axis
  double sd_here = 0.0;                           // the model's predictive sd of eta_re at this point
  // The step against the trend in units of that sd (0 where the model gives no sd).
  double size_in_sd() const { return sd_here > 0.0 ? std::abs(eta_re_next - eta_re_here) / sd_here : 0.0; }
};

struct TrendCheck {
  std::vector<double> phi, capillary_number, viscosity_ratio;  // the probe grid
  int phi_steps = 0, ca_steps = 0;                              // steps checked per trend
  std::vector<TrendViolation> not_rising_with_phi;
  std::vector<TrendViolation> not_falling_with_ca;  // at phi >= 0.21
  double high_shear_phi = 0.0, high_shear_ca = 0.0, high_shear_lambda = 0.0;
  double high_shear_eta_re = 0.0, high_shear_pries = 0.0;
  double intrinsic_low_ca = 0.0, intrinsic_high_ca = 0.0;  // (eta_re - 1) / phi at the smallest phi
  bool high_shear_ok() const;  // within 25 % of Pries
  bool passed() const { return not_rising_with_phi.empty() && not_falling_with_ca.empty() && high_shear_ok(); }
  // One line per check, the worst violations listed; for the Ca trend also the count per
  // phi and the largest step against it in units of the model's sd.
  std::string report() const;
};

// Probe grid: phi 0.05 to 0.55 (11 values), Ca 0.01 to 3.2 (log, 11 values), lambda 0.1,
// 0.3, 1, 3, 5, 10, each clipped to the model's range.
TrendCheck check_trends(const ViscosityModel& model);

}  // namespace rbcal::surrogate
