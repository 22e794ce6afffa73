#pragma once
// The recipe of a model (schema "rbcal.model_recipe/1"): everything `rbcal model build` needs
// to turn runs into the model files, so that the shipped model is rebuilt by one command.
//   {"schema": "rbcal.model_recipe/1",
//    "about": "...",                                   (optional; what this model is)
//    "runs": ["../v2/n6", "../v2/n8"],                 (libraries of runs, any resolutions)
//    "mapping": {"offset": 0.75, "offset_slope": 0, "offset_sd": 0.05, "phi_max": 0.62,
//                "scatter_floor": 0.054, "scatter_phi": [0.05, 0.41]},
//    "surrogate": {"sd_scale": "held_out"},            (or a number >= 1; optional)
//    "family": {"offsets": [0.45, 0.6, 0.75, 0.9, 1.05], "prior": {"mean": 0.75, "sd": 0.15},
//               "shared_hyperparameters": false, "same_runs": false},
//    "box_correction": {"twins": [{"library_box": "...", "bigger_box": "..."}],
//                       "anchors": ["...", ...], "decimals": 3}}
// Paths are relative to the recipe's folder. "mapping" is `rbcal library effective-phi`'s
// options (docs/library.md): the central surrogate is built at "offset", and every member of
// the family at one of "offsets" (which must hold "offset"). "shared_hyperparameters": the
// members take the central surrogate's hyper-parameters; "same_runs": they keep exactly the
// central surrogate's runs (its phi_max cut), so that they differ only by the mapping.
// "box_correction" (optional): the prior of the box exponent beta from twin runs
// (surrogate/box_twins.hpp), its mean and sd rounded to "decimals" (optional; their own
// uncertainty is several hundredths). "anchors" (optional, with "twins"): result files of runs
// in the bigger box at one of the library's resolutions; the prior then comes from the model's
// step to them (surrogate/box_anchors.hpp), the twins giving only the step beyond the bigger box.
#include <filesystem>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include <nlohmann/json.hpp>

#include "surrogate/box_twins.hpp"
#include "surrogate/effective_volume_fraction.hpp"

namespace rbcal::surrogate {

struct ModelRecipe {
  std::filesystem::path file;  // where it was read
  nlohmann::json document;     // as read: recorded in the model files' provenance
  std::string about;
  std::vector<std::filesystem::path> runs;  // resolved against the recipe's folder
  EffectiveVolumeFractionOptions mapping;
  std::optional<double> sd_scale;  // empty: measured from held-out runs (the default)
  std::vector<double> family_offsets;
  double prior_mean = 0.0, prior_sd = 0.0;
  bool shared_hyperparameters = false, same_runs = false;
  std::vector<BoxTwinFiles> box_twins;  // empty: no box correction
  std::vector<std::filesystem::path> box_anchors;  // empty: the prior from the twins alone
  std::optional<int> box_decimals;
};

ModelRecipe model_recipe_from_json(const nlohmann::json& j, const std::filesystem::path& file);
// Throws formats::FormatError naming the file and the field (and the line, for bad JSON).
ModelRecipe read_model_recipe(const std::filesystem::path& file);

}  // namespace rbcal::surrogate
