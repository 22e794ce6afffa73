#include "surrogate/fixed_nuisance_model.hpp"

#include <cmath>
#include <stdexcept>

namespace rbcal::surrogate {

FixedNuisanceModel::FixedNuisanceModel(const ViscosityModel& base, const std::string& name, double value)
    : base_(base), fixed_value_(value) {
  const std::vector<ModelNuisance> all = base.nuisances();
  bool found = false;
  for (std::size_t k = 0; k < all.size(); ++k) {
    if (all[k].name != name) {
      free_.push_back(all[k]);
      continue;
    }
    found = true;
    fixed_index_ = k;
    if (!(std::isfinite(value) && value >= all[k].min && value <= all[k].max))
      throw std::invalid_argument(name + " = " + std::to_string(value) + " lies outside the model's range " +
                                  std::to_string(all[k].min) + " .. " + std::to_string(all[k].max));
  }
  if (!found) throw std::invalid_argument("the model has no nuisance parameter '" + name + "'");
}

std::vector<double> FixedNuisanceModel::all_values(const std::vector<double>& free_values) const {
  std::vector<double> values;
  std::size_t next = 0;
  for (std::size_t k = 0; k <= free_.size(); ++k) {
    if (k == fixed_index_) values.push_back(fixed_value_);
    if (k < free_.size()) values.push_back(free_values.empty() ? free_[k].mean : free_values.at(next++));
  }
  return values;
}

ViscosityPrediction FixedNuisanceModel::predict(double phi, double capillary_number, double viscosity_ratio) const {
  return base_.predict_with(phi, capillary_number, viscosity_ratio, all_values({}));
}

ViscosityPrediction FixedNuisanceModel::predict_with(double phi, double capillary_number, double viscosity_ratio,
                                                     const std::vector<double>& values) const {
  return base_.predict_with(phi, capillary_number, viscosity_ratio, all_values(values));
}

JointViscosityPrediction FixedNuisanceModel::predict_joint(const std::vector<ParameterPoint>& queries,
                                                           const std::vector<double>& values,
                                                           CovarianceForm form) const {
  return base_.predict_joint(queries, all_values(values), form);
}

std::vector<ViscosityPrediction> FixedNuisanceModel::predict_many(const std::vector<ParameterPoint>& queries) const {
  return base_.predict_many_with(queries, all_values({}));
}

std::vector<ViscosityPrediction> FixedNuisanceModel::predict_many_with(const std::vector<ParameterPoint>& queries,
                                                                       const std::vector<double>& values) const {
  return base_.predict_many_with(queries, all_values(values));
}

}  // namespace rbcal::surrogate
