#pragma once
// An offset family (surrogate/offset_family.hpp) of analytic models: the member at offset c is
// AnalyticViscosityModel with c0 = 2.0 + slope (c - 0.75), so the offset scales alpha as the
// immersed boundary's offset scales the effective volume fraction. slope 0: the data cannot see c.
#include <memory>
#include <optional>
#include <vector>

#include "analytic_viscosity_model.hpp"
#include "surrogate/offset_family.hpp"

namespace rbcal::calibration::test_models {

inline surrogate::OffsetFamilyModel analytic_offset_family(
    double slope, double prior_mean = 0.75, double prior_sd = 0.15,
    std::optional<surrogate::BoxCorrectionPrior> box = std::nullopt) {
  std::vector<surrogate::OffsetFamilyMember> members;
  for (double c : {0.45, 0.6, 0.75, 0.9, 1.05}) {
    auto m = std::make_shared<AnalyticViscosityModel>();
    m->c0 = 2.0 + slope * (c - 0.75);
    members.push_back({c, std::move(m)});
  }
  return surrogate::OffsetFamilyModel(std::move(members), prior_mean, prior_sd, box);
}

}  // namespace rbcal::calibration::test_models
