#pragma once
// A viscosity model with the library's two systematic unknowns as nuisance parameters
// (viscosity_model.hpp, ModelNuisance):
// - the immersed boundary's offset c: one model per offset (each built from the same runs moved
//   to their effective volume fraction at that c, `rbcal library effective-phi --offset C`),
//   interpolated in c, with a prior on c;
// - optionally the box correction beta: ln eta_bulk = (1 + beta) ln eta_re, with a prior
//   normal(mean, sd) from runs of the same points in a taller box (docs/library.md). ln eta_re
//   grows about as alpha phi, so beta rescales alpha: a bias that vanishes in the dilute limit,
//   as the wall layering that causes it does.
//
// Each is one number common to every run, so its uncertainty shifts the whole surface together.
// Entered in each point's sd it would average away over a sample's points. The offset is
// therefore a parameter of the calibration. The box correction enters linearly in ln eta, so it
// is integrated out in closed form instead: the model predicts at beta's mean, and its joint
// covariance (predict_joint) carries sd^2 g g^T with g_i = d eta_i / d beta = eta_i ln eta_re_i
// (and, for a step that depends on Ca, slope_sd^2 h h^T with h_i = g_i ln(Ca_i / knee) above the knee),
// an error that moves every point together and so reaches G_s's interval in full
// (docs/calibration.md); predict's sd includes it. As a sampled parameter it had left the MCMC's
// walkers stranded.
//
// The joint covariance at offset c: each point's sd as predict gives it, correlated as the two
// members that bracket c correlate their points (their correlation matrices weighted linearly
// in c: a convex sum, so a valid correlation matrix).
//
// Interpolation in c: members at equally spaced offsets c_0 < ... < c_n; between c_i and c_{i+1}
// a cubic Hermite (Catmull-Rom) of the members' predictions, with central-difference slopes
// inside and one-sided ones at the ends: continuous with a continuous first derivative in c,
// exact at the members and for predictions linear in c. Beyond the ends the end cubic goes on
// (only a derivative step leaves [c_0, c_n]: the prior is truncated there).
#include <cmath>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "surrogate/viscosity_model.hpp"

namespace rbcal::surrogate {

struct OffsetFamilyMember {
  double offset = 0.0;  // c in lattice spacings
  std::shared_ptr<const ViscosityModel> model;
};

// The box correction's prior: normal(mean, sd), its mean inside (-0.5, 1) (a factor on ln eta_re
// between 0.5 and 2, far wider than any measured). Optionally the step depends on Ca above a
// knee, where the narrow gap's effect changes sign (docs/library.md, "The box twins"):
// beta(Ca) = mean + ca_slope ln(Ca / ca_knee) for Ca > ca_knee, mean below it; the slope
// normal(ca_slope, ca_slope_sd), independent of the level. ca_knee 0: one step for every Ca.
struct BoxCorrectionPrior {
  double mean = 0.0, sd = 0.0;
  double ca_knee = 0.0, ca_slope = 0.0, ca_slope_sd = 0.0;

  bool depends_on_ca() const { return ca_knee > 0.0; }
  // d beta / d ca_slope: ln(Ca / ca_knee) above the knee, else 0.
  double lever(double capillary_number) const {
    return depends_on_ca() && capillary_number > ca_knee ? std::log(capillary_number / ca_knee) : 0.0;
  }
  double at(double capillary_number) const { return mean + ca_slope * lever(capillary_number); }
};

class OffsetFamilyModel final : public ViscosityModel {
 public:
  // Throws std::invalid_argument unless there are at least two members at strictly increasing,
  // equally spaced offsets (relative tolerance 1e-9), none of which has nuisance parameters
  // itself, the offset's prior has sd > 0 with its mean inside [first, last] offset (min and
  // max are the first and last offsets), and a box prior, if any, has sd > 0 and its mean
  // inside its truncation.
  OffsetFamilyModel(std::vector<OffsetFamilyMember> members, double prior_mean, double prior_sd,
                    std::optional<BoxCorrectionPrior> box = std::nullopt);

  // The intersection of the members' ranges.
  ParameterRange range() const override { return range_; }
  std::vector<ModelNuisance> nuisances() const override;

  ViscosityPrediction predict_at_offset(double phi, double capillary_number, double viscosity_ratio,
                                        double offset) const;
  const std::vector<OffsetFamilyMember>& members() const { return members_; }
  const ModelNuisance& offset_prior() const { return offset_; }
  const std::optional<BoxCorrectionPrior>& box_correction() const { return box_; }

  // The interpolation's weight of each member at offset c (they sum to 1).
  std::vector<double> weights(double offset) const;

 private:
  // Nuisance "offset_c" (beta is at its mean: see above); members asked once each, jointly
  // where their correlation is needed.
  JointViscosityPrediction joint_prediction(const std::vector<ParameterPoint>& queries, const NuisanceValues& values,
                                            CovarianceForm form) const override;
  // A prediction at Ca with the box correction at its prior mean, its sd with the correction's
  // share (sd_without_box without it), d eta / d beta and d eta / d ca_slope.
  struct Boxed {
    ViscosityPrediction prediction;
    double sd_without_box = 0.0;
    double box_gradient = 0.0;
    double slope_gradient = 0.0;
  };
  Boxed boxed(const ViscosityPrediction& p, double capillary_number) const;
  // The members' predictions weighted by w (weights()); member(k) is asked only where w[k] != 0.
  ViscosityPrediction combined(const std::vector<double>& w,
                               const std::function<ViscosityPrediction(std::size_t)>& member) const;

  std::vector<OffsetFamilyMember> members_;
  ModelNuisance offset_;
  std::optional<BoxCorrectionPrior> box_;
  ParameterRange range_;
};

// ln eta -> (1 + beta) ln eta, with sd and derivatives carried by the chain rule.
ViscosityPrediction with_box_correction(const ViscosityPrediction& p, double beta);

}  // namespace rbcal::surrogate
