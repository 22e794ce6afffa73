#pragma once
// A model with one of its nuisance parameters held at a given value: the calibration then
// fits the others only. For sensitivity studies ("G_s at c held at 0.6"), where the
// nuisance's prior would otherwise let the data move it.
#include <string>
#include <vector>

#include "surrogate/viscosity_model.hpp"

namespace rbcal::surrogate {

class FixedNuisanceModel : public ViscosityModel {
 public:
  // Throws std::invalid_argument when base has no nuisance of that name or the value lies
  // outside its range. base must outlive this model.
  FixedNuisanceModel(const ViscosityModel& base, const std::string& name, double value);

  ParameterRange range() const override { return base_.range(); }
  std::vector<ModelNuisance> nuisances() const override { return free_; }

 private:
  // The base model asked with the free values given and the fixed one set.
  JointViscosityPrediction joint_prediction(const std::vector<ParameterPoint>& queries, const NuisanceValues& values,
                                            CovarianceForm form) const override;

  const ViscosityModel& base_;
  std::vector<ModelNuisance> free_;
  std::string fixed_name_;
  double fixed_value_ = 0.0;
};

}  // namespace rbcal::surrogate
