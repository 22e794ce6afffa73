#include "surrogate/model_recipe.hpp"

#include <algorithm>
#include <cmath>

#include "formats/field_reader.hpp"
#include "formats/json_file.hpp"

namespace rbcal::surrogate {

namespace {

constexpr const char* kModelRecipeSchema = "rbcal.model_recipe/1";

bool flag_or(const formats::FieldReader& r, const std::string& path, bool fallback) {
  const nlohmann::json* n = r.find(path);
  if (!n) return fallback;
  if (!n->is_boolean()) r.fail(path, "must be true or false");
  return n->get<bool>();
}

std::filesystem::path existing_path(const formats::FieldReader& r, const std::string& path,
                                    const std::filesystem::path& folder) {
  const std::filesystem::path p = folder / r.text(path);
  if (!std::filesystem::exists(p)) r.fail(path, "no such file or folder: " + p.string());
  return p;
}

}  // namespace

ModelRecipe model_recipe_from_json(const nlohmann::json& j, const std::filesystem::path& file) {
  const formats::FieldReader r(j, file.string());
  r.expect_schema(kModelRecipeSchema);
  r.only_known_keys("", {"schema", "about", "runs", "mapping", "surrogate", "family", "box_correction"});
  r.only_known_keys("mapping", {"offset", "offset_slope", "offset_sd", "phi_max", "scatter_floor", "scatter_phi"});
  r.only_known_keys("surrogate", {"sd_scale"});
  r.only_known_keys("family", {"offsets", "prior", "shared_hyperparameters", "same_runs"});
  r.only_known_keys("family.prior", {"mean", "sd"});
  r.only_known_keys("box_correction", {"twins", "anchors", "decimals"});
  const std::filesystem::path folder = file.parent_path();
  ModelRecipe m;
  m.file = file;
  m.document = j;
  m.about = r.text_or("about", "");

  const nlohmann::json& runs = r.require("runs");
  if (!runs.is_array() || runs.empty()) r.fail("runs", "must be a non-empty array of library folders");
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const std::string at = "runs." + std::to_string(i);
    m.runs.push_back(existing_path(r, at, folder));
    if (!std::filesystem::is_directory(m.runs.back())) r.fail(at, "must be a library folder");
  }

  m.mapping.offset = r.non_negative("mapping.offset");
  m.mapping.offset_slope = r.number_or("mapping.offset_slope", 0.0, -1e3, 1e3);
  m.mapping.offset_sd = r.non_negative("mapping.offset_sd");
  m.mapping.phi_max = r.in_range("mapping.phi_max", 0.0, 1.0);
  m.mapping.scatter.scatter_floor = r.number_or("mapping.scatter_floor", 0.0, 0.0, 1.0);
  const std::array<double, 2> phi = r.numbers_or<2>(
      "mapping.scatter_phi", {m.mapping.scatter.scatter_phi_low, m.mapping.scatter.scatter_phi_high});
  if (!(phi[0] >= 0.0 && phi[0] <= phi[1] && phi[1] < 1.0))
    r.fail("mapping.scatter_phi", "must be [LOW, HIGH] with 0 <= LOW <= HIGH < 1");
  m.mapping.scatter.scatter_phi_low = phi[0];
  m.mapping.scatter.scatter_phi_high = phi[1];

  if (const nlohmann::json* scale = r.find("surrogate.sd_scale")) {
    if (scale->is_string()) {
      if (scale->get<std::string>() != "held_out")
        r.fail("surrogate.sd_scale", "must be \"held_out\" (measured from held-out runs) or a number >= 1");
    } else {
      m.sd_scale = r.number_or("surrogate.sd_scale", 1.0, 1.0, 1e6);
    }
  }

  m.family_offsets = r.numbers("family.offsets", 2);
  if (!std::is_sorted(m.family_offsets.begin(), m.family_offsets.end()) ||
      std::adjacent_find(m.family_offsets.begin(), m.family_offsets.end()) != m.family_offsets.end())
    r.fail("family.offsets", "must rise strictly");
  if (std::none_of(m.family_offsets.begin(), m.family_offsets.end(),
                   [&](double c) { return c == m.mapping.offset; }))
    r.fail("family.offsets", "must hold mapping.offset (" + std::to_string(m.mapping.offset) +
                                 "): that member is the central surrogate");
  m.prior_mean = r.number("family.prior.mean");
  m.prior_sd = r.positive("family.prior.sd");
  m.shared_hyperparameters = flag_or(r, "family.shared_hyperparameters", false);
  m.same_runs = flag_or(r, "family.same_runs", false);

  if (r.find("box_correction")) {
    const nlohmann::json& twins = r.require("box_correction.twins");
    if (!twins.is_array() || twins.empty())
      r.fail("box_correction.twins", "must be a non-empty array of {\"library_box\": FILE, \"bigger_box\": FILE}");
    for (std::size_t i = 0; i < twins.size(); ++i) {
      const std::string at = "box_correction.twins." + std::to_string(i);
      r.only_known_keys(at, {"library_box", "bigger_box"});
      m.box_twins.push_back(
          {existing_path(r, at + ".library_box", folder), existing_path(r, at + ".bigger_box", folder)});
    }
    if (const nlohmann::json* anchors = r.find("box_correction.anchors")) {
      if (!anchors->is_array() || anchors->empty())
        r.fail("box_correction.anchors", "must be a non-empty array of run result files");
      for (std::size_t i = 0; i < anchors->size(); ++i)
        m.box_anchors.push_back(existing_path(r, "box_correction.anchors." + std::to_string(i), folder));
    }
    if (r.find("box_correction.decimals")) m.box_decimals = r.integer_or("box_correction.decimals", 3, 0, 12);
  }
  return m;
}

ModelRecipe read_model_recipe(const std::filesystem::path& file) {
  return model_recipe_from_json(formats::read_json_file(file), file);
}

}  // namespace rbcal::surrogate
