#include "surrogate/library_case.hpp"

#include "surrogate/field_reader.hpp"
#include "surrogate/json_file.hpp"

namespace rbcal::surrogate {

namespace {
// The numerics every case of a library must share. The Reynolds number is not among
// them: a plan may lower it for its low-Ca cases (a time-step choice at Re << 1).
constexpr const char* kNumericsFields[] = {"numerics.N_a",   "numerics.box",    "numerics.tau_out", "numerics.kernel",
                                           "cells.triangles", "cells.shape",     "cells.law",        "cells.profile",
                                           "cells.skalak_c",  "run.window",      "params.kb_hat",    nullptr};
// These may be absent (the solver's defaults; older case files); the others are required.
bool optional_signature_field(const std::string& field) {
  return field == "params.kb_hat" || field == "cells.profile" || field == "cells.skalak_c";
}
}  // namespace

const char* const* library_numerics_fields() { return kNumericsFields; }

LibraryCase library_case_from_json(const nlohmann::json& j, const std::filesystem::path& source) {
  FieldReader r(j, source.string());
  if (!j.is_object()) r.fail("(top level)", "must be a JSON object");
  const std::string schema = r.text("schema");
  if (schema != "rbcal.case/1") r.fail("schema", "must be \"rbcal.case/1\", got \"" + schema + "\"");

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

  for (const char* const* f = kNumericsFields; *f; ++f) {
    const std::string field = *f;
    const nlohmann::json* node = r.find(field);
    if (!node) {
      if (optional_signature_field(field)) continue;
      r.fail(field, "missing");
    }
    c.numerics_signature[field] = *node;
  }
  r.integer("numerics.N_a", 1);
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
  return library_case_from_json(read_json_file(file), file);
}

}  // namespace rbcal::surrogate
