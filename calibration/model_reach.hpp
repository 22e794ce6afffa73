#pragma once
// Which measured points the model can reach at all, and by how much the others miss: the
// diagnosis that turns "no point inside the model's range" into an explanation. For each
// point (phi, eta_re), the surrogate's eta_re is scanned over its whole Ca range (and its
// lambda range when lambda is fitted, else at the fixed lambda). Since G_s only moves a
// point along Ca, a point is reachable exactly when its eta_re lies between the smallest
// and largest model value there, allowing two combined standard deviations (the point's
// and the model's at the nearer end). Points at a phi outside the model's range cannot be
// reached at any G_s.
#include <string>
#include <vector>

#include "calibration/calibration_input.hpp"
#include "calibration/model_setup.hpp"
#include "surrogate/viscosity_model.hpp"

namespace rbcal::calibration {

enum class Reach { reachable, phi_outside_model, below_model, above_model };
std::string to_string(Reach reach);  // "reachable", "phi outside the model", "below the model", ...

struct PointReach {
  RelativeViscosityPoint point;
  Reach reach = Reach::reachable;
  double model_min = 0.0, model_max = 0.0;  // eta_re over the scanned Ca (and lambda) range
  // measured / nearer model bound - 1 (negative: below the model); 0 when reachable or
  // when phi is outside the model.
  double relative_gap = 0.0;

  bool reachable() const { return reach == Reach::reachable; }
  std::string reason() const;  // one line: why the point cannot be reached, or "reachable"
};

// Unreachable points of one phi, summarised (phi in ascending order).
struct ReachGroup {
  double phi = 0.0;
  Reach reach = Reach::reachable;
  int points = 0;
  double measured_min = 0.0, measured_max = 0.0;  // eta_re of these points
  double model_min = 0.0, model_max = 0.0;        // over the scanned range at this phi
  double gap_min = 0.0, gap_max = 0.0;            // relative gaps of these points
  std::string line(const surrogate::ParameterRange& range, const ModelSetup& setup) const;
};

struct ReachDiagnosis {
  std::vector<PointReach> points;  // in the order given
  std::vector<ReachGroup> unreachable_groups;
  int reachable_count() const;
};

ReachDiagnosis diagnose_reach(const std::vector<RelativeViscosityPoint>& points,
                              const surrogate::ViscosityModel& model, const ModelSetup& setup);

}  // namespace rbcal::calibration
