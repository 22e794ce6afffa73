#pragma once
// `rbcal model build RECIPE -o OUT`: the model from its recipe (surrogate/model_recipe.hpp),
// in the steps the recipe names:
//   1. the runs moved to their effective volume fraction at the recipe's offset, written to
//      OUT/cases (surrogate/mapped_library_file.hpp);
//   2. the central surrogate fitted to them, OUT/surrogate.json, with its leave-one-out report
//      and the trend check;
//   3. one member per family offset, the same runs mapped at that offset (in
//      OUT/family_members while it is built, removed after);
//   4. the box correction's prior from the twin runs (surrogate/box_twins.hpp);
//   5. the family, OUT/surrogate_family.json, the model the calibration uses by default.
// Both model files record the recipe under provenance.recipe. Everything the steps print
// goes to OUT/build_report.txt too. OUT/cases and OUT/family_members are replaced; nothing
// else in OUT is touched. The build is deterministic: the same recipe and runs give the
// same files but for provenance's date, revision and host.
#include <filesystem>
#include <functional>
#include <string>

#include "surrogate/model_recipe.hpp"
#include "surrogate/offset_family.hpp"
#include "surrogate/trend_check.hpp"
#include "surrogate/viscosity_surrogate.hpp"

namespace rbcal::surrogate {

struct ModelBuild {
  ViscositySurrogate central;
  TrendCheck trends;
  OffsetFamilyModel family;
  std::string report;  // what OUT/build_report.txt holds
};

// volume_ratio: g(offset / radius) of the runs' cell (the caller reads the cell's shape:
// surrogate/ never depends on the solver). progress: each step's text as it is done.
ModelBuild build_model(const ModelRecipe& recipe, const std::filesystem::path& out, const VolumeRatio& volume_ratio,
                       const std::function<void(const std::string&)>& progress = {});

}  // namespace rbcal::surrogate
