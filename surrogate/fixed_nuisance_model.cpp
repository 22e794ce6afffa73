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
    fixed_name_ = name;
    if (!(std::isfinite(value) && value >= all[k].min && value <= all[k].max))
      throw std::invalid_argument(name + " = " + std::to_string(value) + " lies outside the model's range " +
                                  std::to_string(all[k].min) + " .. " + std::to_string(all[k].max));
  }
  if (!found) throw std::invalid_argument("the model has no nuisance parameter '" + name + "'");
}

JointViscosityPrediction FixedNuisanceModel::joint_prediction(const std::vector<ParameterPoint>& queries,
                                                              const NuisanceValues& values, CovarianceForm form) const {
  NuisanceValues all = values;
  all.set(fixed_name_, fixed_value_);
  return base_.predict_joint(queries, all, form);
}

}  // namespace rbcal::surrogate
