#include "surrogate/model_build.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>
#include <stdexcept>
#include <utility>

#include "formats/json_file.hpp"
#include "formats/library_schema.hpp"
#include "formats/printf_string.hpp"
#include "formats/provenance.hpp"
#include "surrogate/box_anchors.hpp"
#include "surrogate/box_twins.hpp"
#include "surrogate/leave_one_out_report.hpp"
#include "surrogate/mapped_library_file.hpp"
#include "surrogate/model_description.hpp"
#include "surrogate/offset_family_file.hpp"
#include "surrogate/surrogate_file.hpp"

namespace rbcal::surrogate {

using formats::printf_string;

namespace {

namespace fs = std::filesystem;

double rounded(double x, int decimals) {
  const double scale = std::pow(10.0, decimals);
  return std::round(x * scale) / scale;
}

// The surrogate of the library at `root`, fitted or with `like`'s hyper-parameters, its sd
// scale fixed when the recipe says so.
ViscositySurrogate fit_member(const ModelRecipe& recipe, const fs::path& root, const ViscositySurrogate* like) {
  ViscositySurrogate s = like ? build_surrogate_like(root, *like) : build_surrogate(root);
  if (!recipe.sd_scale) return s;
  return ViscositySurrogate(s.training_cases(), s.process().hyperparameters(), root.string(), s.fit_info(),
                            *recipe.sd_scale);
}

nlohmann::json with_recipe(nlohmann::json j, const ModelRecipe& recipe) {
  j["provenance"]["recipe"] = recipe.document;
  j["provenance"]["recipe_file"] = recipe.file.string();
  return j;
}

// OUT/cases and OUT/family_members are replaced by the build; refused, before anything is
// written, where that would lose runs: OUT is one of the recipe's run folders, or OUT/cases
// holds a file that is not a mapped case (one the mapping wrote, with its raw values kept).
void check_output_is_replaceable(const ModelRecipe& recipe, const fs::path& out) {
  const fs::path target = fs::weakly_canonical(out);
  for (const fs::path& runs : recipe.runs)
    if (fs::weakly_canonical(runs) == target)
      throw std::invalid_argument("rbcal model build: the output folder " + out.string() + " is the run folder " +
                                  runs.string() + " of " + recipe.file.string() +
                                  " (its cases/ would be replaced); build into another folder");
  const fs::path cases = out / "cases";
  if (!fs::is_directory(cases)) return;
  for (const auto& entry : fs::directory_iterator(cases)) {
    if (entry.path().extension() != ".json") continue;
    const nlohmann::json j = formats::read_json_file(entry.path());
    if (!(j.contains("extrapolation") && j["extrapolation"].value("method", "") == formats::kEffectiveVolumeFraction))
      throw std::invalid_argument("rbcal model build: " + entry.path().string() +
                                  " is not a mapped case (no extrapolation.method \"effective volume fraction\"), "
                                  "and the build replaces " + cases.string() + ": build into another folder");
  }
}

// Drops the cases that are not among `keep`'s (by id).
void keep_only(MappedLibrary& mapped, const MappedLibrary& keep) {
  std::set<std::string> ids;
  for (const auto& c : keep.cases) ids.insert(mapped_case_id(c));
  std::erase_if(mapped.cases, [&](const MappedCase& c) { return !ids.count(mapped_case_id(c)); });
}

}  // namespace

ModelBuild build_model(const ModelRecipe& recipe, const fs::path& out, const VolumeRatio& volume_ratio,
                       const std::function<void(const std::string&)>& progress) {
  std::string report;
  auto note = [&](const std::string& text) {
    report += text;
    if (progress) progress(text);
  };
  const nlohmann::json provenance = formats::provenance_block();
  note(printf_string("rbcal model build %s -> %s (rbcal %s, %s)\n", recipe.file.string().c_str(), out.string().c_str(),
              provenance.value("git_revision", "").c_str(), provenance.value("date", "").c_str()));
  if (!recipe.about.empty()) note("  " + recipe.about + "\n");

  check_output_is_replaceable(recipe, out);
  // 1. The runs at their effective volume fraction.
  std::vector<SimulationLibrary> tiers;
  for (const fs::path& r : recipe.runs) tiers.push_back(read_library(r));
  const MappedLibrary mapped = map_to_effective_volume_fraction(tiers, volume_ratio, recipe.mapping);
  fs::remove_all(out / "cases");
  write_mapped_library(mapped, recipe.mapping, out);
  note(describe_mapped_library(mapped, tiers.size(), out, volume_ratio, recipe.mapping));

  // 2. The central surrogate and its checks.
  ViscositySurrogate central = fit_member(recipe, out, nullptr);
  formats::write_json_atomically(out / "surrogate.json", with_recipe(surrogate_to_json(central), recipe));
  note(printf_string("rbcal surrogate build: %s -> %s\n", out.string().c_str(),
                     (out / "surrogate.json").string().c_str()));
  note(describe_surrogate(central));
  note(format_leave_one_out(central.leave_one_out()));
  TrendCheck trends = check_trends(central);
  note("rbcal surrogate check: " + (out / "surrogate.json").string() + "\n" + trends.report());
  if (!trends.passed()) note("trend check FAILED (see above)\n");

  // 3. The family's members.
  const fs::path work = out / "family_members";
  fs::remove_all(work);
  std::vector<SurrogateFamilyMember> members;
  for (const double c : recipe.family_offsets) {
    if (c == recipe.mapping.offset) {
      members.push_back({c, central});
      continue;
    }
    EffectiveVolumeFractionOptions at_c = recipe.mapping;
    at_c.offset = c;
    // Same runs: no cut of its own; the central library's cut decides below.
    if (recipe.same_runs) at_c.phi_max = std::nextafter(1.0, 0.0);
    MappedLibrary member = map_to_effective_volume_fraction(tiers, volume_ratio, at_c);
    if (recipe.same_runs) keep_only(member, mapped);
    const fs::path root = work / printf_string("c%g", c);
    write_mapped_library(member, at_c, root);
    ViscositySurrogate s = fit_member(recipe, root, recipe.shared_hyperparameters ? &central : nullptr);
    note(printf_string(
        "family member at offset %g:\n  training cases      %zu\n  RMS relative error  %.4g (leave-one-out)\n", c,
        s.training_cases().size(), s.leave_one_out().rms_relative_error));
    members.push_back({c, std::move(s)});
  }

  // 4. The box correction.
  std::optional<BoxCorrectionRecord> box;
  if (!recipe.box_twins.empty()) {
    const BoxTwinPrior twins = box_twin_prior(recipe.box_twins);
    note("box correction from twin runs:\n" + describe_box_twins(twins));
    // Where a run at its own resolution stands under the recipe's mapping.
    const auto phi_eff_of = [&](const LibraryCase& r) {
      return volume_ratio(recipe.mapping.offset_at(r.nodes_per_radius) / r.nodes_per_radius) * r.phi_actual;
    };
    double lo = 1.0, hi = 0.0;
    for (const BoxTwin& t : twins.twins) {
      const double phi_eff = phi_eff_of(t.library_box);
      lo = std::min(lo, phi_eff), hi = std::max(hi, phi_eff);
    }
    BoxCorrectionPrior prior{twins.mean, twins.sd};
    std::string source = printf_string(
        "%zu twin runs in a box twice the library's height at phi_eff %.2f-%.2f (docs/library.md, The box twins)",
        twins.twins.size(), lo, hi);
    if (!recipe.box_anchors.empty()) {
      std::vector<int> resolutions;
      for (const SimulationLibrary& t : tiers)
        for (const LibraryCase& c : t.cases) resolutions.push_back(c.nodes_per_radius);
      BoxAnchorPrior anchors;
      try {
        anchors = box_anchor_prior(recipe.box_anchors, central, phi_eff_of, resolutions, twins);
      } catch (const std::invalid_argument& e) {
        throw std::invalid_argument(recipe.file.string() + ": field box_correction.anchors: " + e.what());
      }
      note("box correction from anchor runs (the model's step to the bigger box):\n" + describe_box_anchors(anchors));
      prior = {anchors.mean, anchors.sd};
      source = printf_string(
          "%zu anchor runs in a box twice the library's height against the model, the step to the bulk from %zu twin "
          "runs (docs/library.md, The box twins)",
          anchors.anchors.size(), twins.twins.size());
    }
    if (recipe.box_decimals)
      prior = {rounded(prior.mean, *recipe.box_decimals), rounded(prior.sd, *recipe.box_decimals)};
    box = BoxCorrectionRecord{prior, source};
  }

  // 5. The family.
  const fs::path family_file = out / "surrogate_family.json";
  const nlohmann::json family_json =
      with_recipe(surrogate_family_to_json(members, recipe.prior_mean, recipe.prior_sd, box), recipe);
  OffsetFamilyModel family =
      surrogate_family_from_json(family_json, family_file.string());  // its checks, before writing
  formats::write_json_atomically(family_file, family_json);
  fs::remove_all(work);
  note(printf_string("rbcal surrogate family: %zu members -> %s\n", members.size(), family_file.string().c_str()));
  note(describe_family(family, box ? box->source : ""));
  formats::write_file_atomically(out / "build_report.txt", report);
  return {std::move(central), std::move(trends), std::move(family), std::move(report)};
}

}  // namespace rbcal::surrogate
