#pragma once
// The surrogate-family file (schema "rbcal.surrogate_family/1"): surrogates of the same runs
// at equally spaced immersed-boundary offsets and the offset's prior, read as one
// OffsetFamilyModel (offset_family.hpp):
//   {"schema": "rbcal.surrogate_family/1",
//    "parameter": "...",                       (what the offset is; informational)
//    "prior": {"mean": 0.75, "sd": 0.15},      (lattice spacings; truncated to the members)
//    "box_correction": {"mean": ..., "sd": ..., "source": "...",    (optional; beta)
//                       "ca_knee": ..., "ca_slope": ..., "ca_slope_sd": ...},  (optional; its Ca dependence)
//    "members": [{"offset": 0.45, "surrogate": {rbcal.surrogate/1}}, ...],
//    "provenance": {...}}
// load_viscosity_model reads either schema, so a calibration takes either file.
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <nlohmann/json.hpp>
#include <vector>

#include "surrogate/offset_family.hpp"
#include "surrogate/viscosity_surrogate.hpp"

namespace rbcal::surrogate {

struct SurrogateFamilyMember {
  double offset = 0.0;
  ViscositySurrogate surrogate;
};

// The box correction's prior and where its numbers come from (kept in the file).
struct BoxCorrectionRecord {
  BoxCorrectionPrior prior;
  std::string source;
};

nlohmann::json surrogate_family_to_json(const std::vector<SurrogateFamilyMember>& members, double prior_mean,
                                        double prior_sd, const std::optional<BoxCorrectionRecord>& box = std::nullopt);
OffsetFamilyModel surrogate_family_from_json(const nlohmann::json& j, const std::string& source);

// Members sorted by offset; the constructor's checks (offset_family.hpp) are made before writing.
// Returns the family as written (what load_surrogate_family would read back).
OffsetFamilyModel save_surrogate_family(std::vector<SurrogateFamilyMember> members, double prior_mean, double prior_sd,
                           const std::filesystem::path& file, const std::optional<BoxCorrectionRecord>& box = std::nullopt);
OffsetFamilyModel load_surrogate_family(const std::filesystem::path& file);

// A surrogate (rbcal.surrogate/1) or a surrogate family (rbcal.surrogate_family/1), by its schema.
std::unique_ptr<ViscosityModel> load_viscosity_model(const std::filesystem::path& file);
// The same from the file's parsed content (source: the file, for messages).
std::unique_ptr<ViscosityModel> viscosity_model_from_json(const nlohmann::json& j, const std::string& source);

// The offset a model file's runs were mapped with, c(N_a) = at_n8 + slope (1 / N_a - 1 / 8)
// (effective_volume_fraction.hpp): for a family the prior's mean, for a surrogate its recipe's
// mapping.offset; the slope from the recipe the file records (0 when it records none).
struct RecordedOffset {
  double at_n8 = 0.0, slope = 0.0;
  double at(int nodes_per_radius) const { return at_n8 + slope * (1.0 / nodes_per_radius - 1.0 / 8.0); }
};
// Empty when the file records no offset (a surrogate built without a recipe).
std::optional<RecordedOffset> recorded_offset(const nlohmann::json& model_file);

}  // namespace rbcal::surrogate
