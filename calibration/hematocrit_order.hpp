#pragma once
// A consistency rule for measured curves: at a given shear rate the viscosity of blood rises
// with the hematocrit (every data set and every model of the seed study's range agree;
// eta_re = exp(alpha phi) with alpha > 0). A point whose eta_re is not above the curve of the
// next lower hematocrit of its sample, interpolated at its shear rate, contradicts that and is
// most likely a measurement or digitisation defect (the shipped Kim et al. 2017 data: two
// 55 % points at 780 and 992 1/s below the 45 % ones). The rule names such points so that
// the calibration can leave them out and say so, instead of the numbers being edited by hand.
#include <string>
#include <vector>

#include "calibration/calibration_input.hpp"

namespace rbcal::calibration {

struct OutOfOrderPoint {
  RelativeViscosityPoint point;
  double lower_phi = 0.0;     // the next lower hematocrit of the sample
  double lower_eta_re = 0.0;  // its curve at the point's shear rate (log-log interpolation)
  std::string reason() const;  // "line L: eta_re X at phi P, Y 1/s is not above Z at phi Q"
};

// The points not above the next lower hematocrit's curve. Only shear rates inside that
// curve's measured range are judged (no extrapolation).
std::vector<OutOfOrderPoint> points_out_of_hematocrit_order(const std::vector<RelativeViscosityPoint>& points);

}  // namespace rbcal::calibration
