#pragma once
// What the writer (solver/sweep) and the readers (surrogate/, calibration/) of the
// project's files must agree on: schema names, the library's folder layout, case ids,
// and the numerics signature that makes the cases of one library comparable.
//
// Library layout (LIB is a folder):
//   LIB/plan.json           the plan the library was generated from (rbcal.plan/1)
//   LIB/cases/ID.json       finished case results (rbcal.case/1 with "result")
//   LIB/cases/ID.csv        their time series
//   LIB/work/ID/, ID.lock   cases in progress and their claims
//   LIB/failed/             cases that stopped with an error
//   LIB/surrogate.json      the surrogate built on the cases (rbcal.surrogate/1)
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

namespace rbcal::formats {

inline constexpr const char* kCaseSchema = "rbcal.case/1";
inline constexpr const char* kPlanSchema = "rbcal.plan/1";
inline constexpr const char* kSurrogateSchema = "rbcal.surrogate/1";
inline constexpr const char* kSurrogateFamilySchema = "rbcal.surrogate_family/1";
inline constexpr const char* kProposalSchema = "rbcal.proposal/1";
inline constexpr const char* kCalibrationReportSchema = "rbcal.calibration_report/1";

// extrapolation.method of a case moved to its effective volume fraction
// (surrogate/effective_volume_fraction.hpp). Such cases stand for the continuum, so a
// library may mix their resolutions: their signature shows this name in place of N_a.
inline constexpr const char* kEffectiveVolumeFraction = "effective volume fraction";

namespace library_layout {
inline std::filesystem::path plan(const std::filesystem::path& lib) { return lib / "plan.json"; }
inline std::filesystem::path cases(const std::filesystem::path& lib) { return lib / "cases"; }
inline std::filesystem::path work(const std::filesystem::path& lib) { return lib / "work"; }
inline std::filesystem::path failed(const std::filesystem::path& lib) { return lib / "failed"; }
inline std::filesystem::path surrogate(const std::filesystem::path& lib) { return lib / "surrogate.json"; }
inline std::filesystem::path case_result(const std::filesystem::path& lib, const std::string& id) {
  return cases(lib) / (id + ".json");
}
inline std::filesystem::path case_series(const std::filesystem::path& lib, const std::string& id) {
  return cases(lib) / (id + ".csv");
}
}  // namespace library_layout

// File-name-safe id of a grid point, e.g. "phi0.21_Ca0.1_lambda5" (six significant digits).
std::string case_id(double phi, double capillary_number, double viscosity_ratio);

// The numerics signature: the fields of a case result that every case of one library
// must share, because they change eta_re beyond its standard error or define what was
// simulated. The Reynolds number is not among them: a plan may lower it for its low-Ca
// cases (a time-step choice at Re << 1). The integrator, the indicator tolerance and the
// coupling interval are: each changes the discrete dynamics, and their equivalence was
// shown on two cases (docs/performance.md), not for every case, so a library does not
// mix them silently.
struct SignatureField {
  const char* path;                       // dotted path in the case file
  std::optional<nlohmann::json> absent;   // what an absent field means (files written before
                                          // it existed); no value: the field is required
};
const std::vector<SignatureField>& numerics_signature_fields();

// The signature of one case file (absent optional fields replaced by their meaning);
// FormatError names source and field when a required field is missing.
nlohmann::json numerics_signature(const nlohmann::json& case_file, const std::string& source);

// The first field where two signatures differ, or nullopt when they agree.
std::optional<std::string> first_signature_difference(const nlohmann::json& a, const nlohmann::json& b);

}  // namespace rbcal::formats
