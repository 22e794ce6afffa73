#pragma once
// The surrogate file (schema "rbcal.surrogate/1"): hyper-parameters, training data, mean
// coefficients, source library and leave-one-out summary, enough to predict again without
// refitting. A loaded surrogate predicts bit-identically to the one that was saved (the
// doubles round-trip exactly and the factorisation is recomputed by the same code).
//
// Everything outside the "provenance" key is a deterministic function of the library:
// building twice gives identical content there. "provenance" is formats::provenance_block()
// (version, revision, date honouring SOURCE_DATE_EPOCH, host).
#include <filesystem>
#include <nlohmann/json.hpp>

#include "surrogate/viscosity_surrogate.hpp"

namespace rbcal::surrogate {

nlohmann::json surrogate_to_json(const ViscositySurrogate& surrogate);
ViscositySurrogate surrogate_from_json(const nlohmann::json& j, const std::string& source);

void save_surrogate(const ViscositySurrogate& surrogate, const std::filesystem::path& file);
ViscositySurrogate load_surrogate(const std::filesystem::path& file);

// read_library(library_root) + ViscositySurrogate::fit, source_library = library_root.
ViscositySurrogate build_surrogate(const std::filesystem::path& library_root);
// The same with the hyper-parameters of the surrogate in reference_file (not fitted).
ViscositySurrogate build_surrogate_like(const std::filesystem::path& library_root,
                                        const std::filesystem::path& reference_file);
// ... or of this surrogate.
ViscositySurrogate build_surrogate_like(const std::filesystem::path& library_root, const ViscositySurrogate& reference);

}  // namespace rbcal::surrogate
