#pragma once
// One measured curve (the points of one hematocrit) read at any shear rate inside its measured
// range: ln eta_re linear in ln shear rate between neighbouring points, no extrapolation. Used
// where curves measured at different shear rates must be compared at one rate (the hematocrit
// order rule, the alpha method on digitised data).
#include <optional>
#include <vector>

#include "calibration/calibration_input.hpp"

namespace rbcal::calibration {

// A curve sorted once by shear rate, then read at any rate in O(log n): a sample of a few
// hundred thousand points is read point by point in seconds (sorting the curve for every
// reading had made a 50 MB file take more than ten minutes).
class SortedCurve {
 public:
  explicit SortedCurve(std::vector<RelativeViscosityPoint> curve);
  // eta_re at shear_rate; nullopt outside [lowest, highest] measured rate. At a repeated rate,
  // the first of its points in the sorted order.
  std::optional<double> at(double shear_rate) const;

 private:
  std::vector<RelativeViscosityPoint> curve_;
};

// eta_re of the curve at shear_rate (one reading of SortedCurve).
std::optional<double> curve_at(std::vector<RelativeViscosityPoint> curve, double shear_rate);

}  // namespace rbcal::calibration
