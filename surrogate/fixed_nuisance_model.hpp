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

  ViscosityPrediction predict(double phi, double capillary_number, double viscosity_ratio) const override;
  ParameterRange range() const override { return base_.range(); }
  std::vector<ModelNuisance> nuisances() const override { return free_; }
  ViscosityPrediction predict_with(double phi, double capillary_number, double viscosity_ratio,
                                   const std::vector<double>& values) const override;
  JointViscosityPrediction predict_joint(const std::vector<ParameterPoint>& queries,
                                         const std::vector<double>& values,
                                         CovarianceForm form = CovarianceForm::automatic) const override;
  std::vector<ViscosityPrediction> predict_many(const std::vector<ParameterPoint>& queries) const override;
  std::vector<ViscosityPrediction> predict_many_with(const std::vector<ParameterPoint>& queries,
                                                     const std::vector<double>& values) const override;

 private:
  // The base model's nuisance values: the free ones given (or their means), the fixed one set.
  std::vector<double> all_values(const std::vector<double>& free_values) const;

  const ViscosityModel& base_;
  std::vector<ModelNuisance> free_;
  std::size_t fixed_index_ = 0;
  double fixed_value_ = 0.0;
};

}  // namespace rbcal::surrogate
