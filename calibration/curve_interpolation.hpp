#pragma once
// One measured curve (the points of one hematocrit) read at any shear rate inside its measured
// range: ln eta_re linear in ln shear rate between neighbouring points, no extrapolation. Used
// where curves measured at different shear rates must be compared at one rate (the hematocrit
// order rule, the alpha method on digitised data).
#include <optional>
#include <vector>

#include "calibration/calibration_input.hpp"

namespace rbcal::calibration {

// eta_re of the curve at shear_rate; nullopt outside [lowest, highest] measured rate.
std::optional<double> curve_at(std::vector<RelativeViscosityPoint> curve, double shear_rate);

}  // namespace rbcal::calibration
