// `rbcal model build RECIPE -o OUT`: the model files from a recipe (surrogate/model_build.hpp).
#include <cstdio>
#include <memory>
#include <string>

#include "cli/cell_thickening.hpp"
#include "cli/commands.hpp"
#include "surrogate/model_build.hpp"
#include "surrogate/model_recipe.hpp"
#include "surrogate/simulation_library.hpp"

namespace rbcal::cli {

namespace {

struct ModelBuildOptions {
  std::string recipe;
  std::string output;
};

void run_model_build(const ModelBuildOptions& o) {
  const surrogate::ModelRecipe recipe = surrogate::read_model_recipe(o.recipe);
  const surrogate::SimulationLibrary first = surrogate::read_library(recipe.runs.front());
  if (first.cases.empty()) throw std::invalid_argument(recipe.runs.front().string() + ": no finished runs");
  const surrogate::VolumeRatio ratio = volume_ratio_of(cell_terms(first.cases.front()));
  const surrogate::ModelBuild built = surrogate::build_model(recipe, o.output, ratio, [](const std::string& text) {
    std::printf("%s", text.c_str());
    std::fflush(stdout);
  });
  if (!built.trends.passed()) throw ExitStatus{1};
}

}  // namespace

void add_model_command(CLI::App& app) {
  CLI::App* model = app.add_subcommand("model", "The viscosity model the calibration uses: build it from a recipe");
  model->require_subcommand(1);
  auto o = std::make_shared<ModelBuildOptions>();
  CLI::App* build = model->add_subcommand(
      "build",
      "Runs -> effective volume fraction -> surrogate, family of offsets and box correction, as the recipe says "
      "(docs/library.md, \"Build.\"): OUT/surrogate.json, OUT/surrogate_family.json, "
      "OUT/build_report.txt; exit 1 when the trend check fails");
  build->add_option("recipe", o->recipe, "Recipe file (rbcal.model_recipe/1; data/library/default/recipe.json is the "
                                         "shipped model's)")
      ->required()
      ->check(CLI::ExistingFile);
  build->add_option("-o,--output", o->output, "Output folder (its cases/ and family_members/ are replaced)")
      ->required();
  build->callback([o] { run_model_build(*o); });
}

}  // namespace rbcal::cli
