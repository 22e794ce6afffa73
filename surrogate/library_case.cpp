#include "surrogate/library_case.hpp"

#include "formats/field_reader.hpp"
#include "formats/json_file.hpp"
#include "formats/library_schema.hpp"

namespace rbcal::surrogate {

LibraryCase library_case_from_json(const nlohmann::json& j, const std::filesystem::path& source) {
  const formats::FieldReader r(j, source.string());
  r.expect_schema(formats::kCaseSchema);

  LibraryCase c;
  c.id = source.stem().string();
  c.source = source;
  c.capillary_number = r.positive("params.Ca");
  c.viscosity_ratio = r.positive("params.lambda");
  c.phi_actual = r.in_range("result.phi_actual", 0.0, 1.0);
  c.phi = r.find("params.phi") ? r.in_range("params.phi", 0.0, 1.0) : c.phi_actual;
  c.eta_re = r.positive("result.eta_re");
  c.eta_re_sem = r.non_negative("result.eta_re_sem");
  c.eta_re_wall = r.number("result.eta_re_wall");
  c.eta_re_wall_sem = r.non_negative("result.eta_re_wall_sem");
  c.n_cells = r.integer("result.n_cells", 1);
  c.steps = r.integer("result.steps", 0);
  c.wall_seconds = r.non_negative("result.wall_seconds");

  c.numerics_signature = formats::numerics_signature(j, source.string());
  c.nodes_per_radius = static_cast<int>(r.integer("numerics.N_a", 1));
  if (r.find("extrapolation")) {
    c.extrapolation_method = r.text("extrapolation.method");
    const nlohmann::json& raw = r.require("extrapolation.raw");
    if (!raw.is_array() || raw.empty()) r.fail("extrapolation.raw", "must be a non-empty array");
    for (std::size_t i = 0; i < raw.size(); ++i) {
      const std::string at = "extrapolation.raw." + std::to_string(i);
      c.raw_results.push_back({static_cast<int>(r.integer(at + ".N_a", 1)), r.positive(at + ".eta_re"),
                               r.non_negative(at + ".eta_re_sem")});
    }
    if (c.extrapolation_method == formats::kEffectiveVolumeFraction)
      c.phi_as_run = r.in_range("extrapolation.phi_raw", 0.0, 1.0);
    if (r.find("extrapolation.run_sd")) c.run_sd = r.non_negative("extrapolation.run_sd");
  }
  r.numbers("numerics.box", 3);
  r.positive("numerics.tau_out");
  r.positive("numerics.Re");
  r.text("numerics.kernel");
  r.integer("cells.triangles", 1);
  r.text("cells.shape");
  r.text("cells.law");
  r.numbers("run.window", 2);
  return c;
}

LibraryCase read_library_case(const std::filesystem::path& file) {
  return library_case_from_json(formats::read_json_file(file), file);
}

}  // namespace rbcal::surrogate
