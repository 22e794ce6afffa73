#pragma once
// The calibration's parameter vector, one layout for the direct fit, the posterior, the
// samplers and the reports: ln_G_s first, then, when they are parameters, ln_lambda,
// ln_sigma_d (the posterior's discrepancy), ln_eta0, and the model's nuisances in the model's
// order (viscosity_model.hpp), by name.
#include <string>
#include <vector>

#include "surrogate/viscosity_model.hpp"

namespace rbcal::calibration {

// The index of a named parameter among `names`, -1 when it is not one.
inline int index_in(const std::vector<std::string>& names, const std::string& name) {
  for (std::size_t i = 0; i < names.size(); ++i)
    if (names[i] == name) return static_cast<int>(i);
  return -1;
}

struct ParameterLayout {
  std::vector<std::string> names;
  int lambda = -1, discrepancy = -1, plasma_viscosity = -1;  // indices; -1 where not a parameter
  int nuisance = -1;  // the first of the model's nuisances; -1 without them

  ParameterLayout(bool lambda_fitted = false, bool discrepancy_fitted = false, bool plasma_viscosity_fitted = false,
                  const std::vector<surrogate::ModelNuisance>& nuisances = {}) {
    names = {"ln_G_s"};
    auto add = [&](const char* name) {
      names.push_back(name);
      return static_cast<int>(names.size()) - 1;
    };
    if (lambda_fitted) lambda = add("ln_lambda");
    if (discrepancy_fitted) discrepancy = add("ln_sigma_d");
    if (plasma_viscosity_fitted) plasma_viscosity = add("ln_eta0");
    if (!nuisances.empty()) nuisance = static_cast<int>(names.size());
    for (const auto& n : nuisances) names.push_back(n.name);
  }
  int dimension() const { return static_cast<int>(names.size()); }
  int index_of(const std::string& name) const { return index_in(names, name); }
};

}  // namespace rbcal::calibration
