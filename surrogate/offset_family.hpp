#pragma once
// A viscosity model with the immersed boundary's offset c as a nuisance parameter: one model per
// offset (each built from the same runs moved to their effective volume fraction at that c,
// `rbcal library effective-phi --offset C`), interpolated in c, with a prior on c.
//
// Why: the offset is one number common to every run, so its uncertainty shifts the whole
// surface together. Entered in each run's sd it would average away over a sample's points; as
// a parameter of the calibration it reaches G_s's interval in full (docs/calibration.md).
//
// Interpolation: members at equally spaced offsets c_0 < ... < c_n; between c_i and c_{i+1} a
// cubic Hermite (Catmull-Rom) of the members' predictions, with central-difference slopes
// inside and one-sided ones at the ends: continuous with a continuous first derivative in c,
// exact at the members and for predictions linear in c. Beyond the ends the end cubic goes on
// (only a derivative step leaves [c_0, c_n]: the prior is truncated there).
#include <memory>
#include <vector>

#include "surrogate/viscosity_model.hpp"

namespace rbcal::surrogate {

struct OffsetFamilyMember {
  double offset = 0.0;  // c in lattice spacings
  std::shared_ptr<const ViscosityModel> model;
};

class OffsetFamilyModel final : public ViscosityModel {
 public:
  // Throws std::invalid_argument unless there are at least two members at strictly increasing,
  // equally spaced offsets (relative tolerance 1e-9), none of which has an offset itself, and
  // the prior has sd > 0 with its mean inside [first, last] offset. prior.min and max are set
  // to the first and last offsets.
  OffsetFamilyModel(std::vector<OffsetFamilyMember> members, double prior_mean, double prior_sd);

  ViscosityPrediction predict(double phi, double capillary_number, double viscosity_ratio) const override;
  ViscosityPrediction predict_at_offset(double phi, double capillary_number, double viscosity_ratio,
                                        double offset) const override;
  // The intersection of the members' ranges.
  ParameterRange range() const override { return range_; }
  std::optional<OffsetPrior> offset_prior() const override { return prior_; }

  const std::vector<OffsetFamilyMember>& members() const { return members_; }

  // The interpolation's weight of each member at offset c (they sum to 1).
  std::vector<double> weights(double offset) const;

 private:
  std::vector<OffsetFamilyMember> members_;
  OffsetPrior prior_;
  ParameterRange range_;
};

}  // namespace rbcal::surrogate
