#include "formats/library_schema.hpp"

#include "formats/field_reader.hpp"
#include "formats/short_number.hpp"

namespace rbcal::formats {

std::string case_id(double phi, double capillary_number, double viscosity_ratio) {
  return "phi" + short_number(phi) + "_Ca" + short_number(capillary_number) + "_lambda" +
         short_number(viscosity_ratio);
}

const std::vector<SignatureField>& numerics_signature_fields() {
  using nlohmann::json;
  static const std::vector<SignatureField> fields = {
      {"numerics.N_a", std::nullopt},
      {"numerics.box", std::nullopt},
      {"numerics.tau_out", std::nullopt},
      {"numerics.kernel", std::nullopt},
      // Case results written before these fields existed were run with RK4, the inside
      // fraction rebuilt every step, the membrane updated every step and no volume penalty.
      {"numerics.integrator", json("rk4")},
      {"numerics.indicator_tolerance", json(0.0)},
      {"numerics.coupling_interval", json(1)},
      // Before this field existed a coupling interval moved the membrane by the velocity
      // after its last fluid step (at k = 1 the field does not matter: compared as null).
      {"numerics.node_velocity", json("last_step")},
      {"numerics.volume_stiffness", json(0.0)},
      {"numerics.precision", json("double")},  // population storage (fluid_lattice.hpp)
      {"cells.triangles", std::nullopt},
      {"cells.shape", std::nullopt},
      {"cells.law", std::nullopt},
      // The only profile before the field existed; C and the bending modulus compare as
      // absent (null) against absent only.
      {"cells.profile", json("evans-fung")},
      {"cells.skalak_c", json(nullptr)},
      {"cells.skalak_c_per_Ca", json(0.0)},  // C growing with Ca (simulation_case.hpp)
      {"run.window", std::nullopt},
      {"params.kb_hat", json(nullptr)},
  };
  return fields;
}

nlohmann::json numerics_signature(const nlohmann::json& case_file, const std::string& source) {
  const FieldReader r(case_file, source);
  nlohmann::json signature = nlohmann::json::object();
  for (const SignatureField& f : numerics_signature_fields()) {
    const nlohmann::json* node = r.find(f.path);
    if (!node && !f.absent) r.fail(f.path, "missing");
    signature[f.path] = node ? *node : *f.absent;
  }
  if (signature["numerics.coupling_interval"] == 1) signature["numerics.node_velocity"] = nullptr;
  if (const nlohmann::json* method = r.find("extrapolation.method"); method && *method == kEffectiveVolumeFraction)
    signature["numerics.N_a"] = kEffectiveVolumeFraction;
  return signature;
}

std::optional<std::string> first_signature_difference(const nlohmann::json& a, const nlohmann::json& b) {
  for (const SignatureField& f : numerics_signature_fields()) {
    const auto ia = a.find(f.path), ib = b.find(f.path);
    const bool has_a = ia != a.end(), has_b = ib != b.end();
    if (has_a != has_b || (has_a && *ia != *ib)) return std::string(f.path);
  }
  return std::nullopt;
}

}  // namespace rbcal::formats
