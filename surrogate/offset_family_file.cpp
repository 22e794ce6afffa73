#include "surrogate/offset_family_file.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "formats/field_reader.hpp"
#include "formats/json_file.hpp"
#include "formats/library_schema.hpp"
#include "formats/provenance.hpp"
#include "surrogate/surrogate_file.hpp"

namespace rbcal::surrogate {

nlohmann::json surrogate_family_to_json(const std::vector<SurrogateFamilyMember>& members, double prior_mean,
                                        double prior_sd, const std::optional<BoxCorrectionRecord>& box) {
  nlohmann::json j;
  j["schema"] = formats::kSurrogateFamilySchema;
  j["parameter"] = "offset c of the immersed boundary in lattice spacings: each member is the surrogate of the "
                   "library's runs moved to their effective volume fraction at that c (rbcal library effective-phi)";
  j["prior"] = {{"mean", prior_mean}, {"sd", prior_sd}};
  if (box) {
    j["box_correction"] = {{"mean", box->prior.mean}, {"sd", box->prior.sd}, {"source", box->source}};
    if (box->prior.depends_on_ca())
      j["box_correction"].update({{"ca_knee", box->prior.ca_knee}, {"ca_slope", box->prior.ca_slope},
                                  {"ca_slope_sd", box->prior.ca_slope_sd}});
  }
  nlohmann::json list = nlohmann::json::array();
  for (const auto& m : members) {
    nlohmann::json s = surrogate_to_json(m.surrogate);
    s.erase("provenance");  // the family's own provenance covers them
    list.push_back({{"offset", m.offset}, {"surrogate", std::move(s)}});
  }
  j["members"] = std::move(list);
  j["provenance"] = formats::provenance_block();
  return j;
}

OffsetFamilyModel surrogate_family_from_json(const nlohmann::json& j, const std::string& source) {
  const formats::FieldReader r(j, source);
  r.expect_schema(formats::kSurrogateFamilySchema);
  r.only_known_keys("", {"schema", "parameter", "prior", "box_correction", "members", "provenance"});
  r.only_known_keys("box_correction", {"mean", "sd", "source", "ca_knee", "ca_slope", "ca_slope_sd"});
  const double mean = r.number("prior.mean");
  const double sd = r.positive("prior.sd");
  std::optional<BoxCorrectionPrior> box;
  if (r.find("box_correction")) {
    box = BoxCorrectionPrior{r.number("box_correction.mean"), r.positive("box_correction.sd")};
    if (r.find("box_correction.ca_knee")) {
      box->ca_knee = r.positive("box_correction.ca_knee");
      box->ca_slope = r.number("box_correction.ca_slope");
      box->ca_slope_sd = r.non_negative("box_correction.ca_slope_sd");
    }
  }
  const nlohmann::json& list = r.require("members");
  if (!list.is_array() || list.size() < 2) r.fail("members", "must be an array of at least two members");
  std::vector<OffsetFamilyMember> members;
  for (std::size_t i = 0; i < list.size(); ++i) {
    const std::string at = "members." + std::to_string(i);
    const double offset = r.number(at + ".offset");
    auto model = std::make_shared<ViscositySurrogate>(
        surrogate_from_json(r.require(at + ".surrogate"), source + " (" + at + ".surrogate)"));
    members.push_back({offset, std::move(model)});
  }
  try {
    return OffsetFamilyModel(std::move(members), mean, sd, box);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(source + ": " + e.what());
  }
}

OffsetFamilyModel save_surrogate_family(std::vector<SurrogateFamilyMember> members, double prior_mean, double prior_sd,
                           const std::filesystem::path& file, const std::optional<BoxCorrectionRecord>& box) {
  std::sort(members.begin(), members.end(), [](const auto& a, const auto& b) { return a.offset < b.offset; });
  std::vector<OffsetFamilyMember> check;
  for (const auto& m : members) check.push_back({m.offset, std::make_shared<ViscositySurrogate>(m.surrogate)});
  OffsetFamilyModel family(std::move(check), prior_mean, prior_sd,  // refuse what could not be read back
                           box ? std::optional<BoxCorrectionPrior>(box->prior) : std::nullopt);
  formats::write_json_atomically(file, surrogate_family_to_json(members, prior_mean, prior_sd, box));
  return family;
}

OffsetFamilyModel load_surrogate_family(const std::filesystem::path& file) {
  return surrogate_family_from_json(formats::read_json_file(file), file.string());
}

std::unique_ptr<ViscosityModel> viscosity_model_from_json(const nlohmann::json& j, const std::string& source) {
  const std::string schema = j.is_object() && j.contains("schema") && j["schema"].is_string() ? j["schema"] : "";
  if (schema == formats::kSurrogateFamilySchema)
    return std::make_unique<OffsetFamilyModel>(surrogate_family_from_json(j, source));
  return std::make_unique<ViscositySurrogate>(surrogate_from_json(j, source));
}

std::unique_ptr<ViscosityModel> load_viscosity_model(const std::filesystem::path& file) {
  return viscosity_model_from_json(formats::read_json_file(file), file.string());
}

std::optional<RecordedOffset> recorded_offset(const nlohmann::json& j) {
  if (!j.is_object()) return std::nullopt;
  const nlohmann::json mapping = j.contains("provenance") ? j["provenance"].value("recipe", nlohmann::json::object())
                                                                     .value("mapping", nlohmann::json::object())
                                                          : nlohmann::json::object();
  RecordedOffset r;
  r.slope = mapping.value("offset_slope", 0.0);
  if (j.value("schema", "") == formats::kSurrogateFamilySchema && j.contains("prior"))
    r.at_n8 = j["prior"].at("mean").get<double>();
  else if (mapping.contains("offset"))
    r.at_n8 = mapping["offset"].get<double>();
  else
    return std::nullopt;
  return r;
}

}  // namespace rbcal::surrogate
