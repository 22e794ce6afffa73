#pragma once
// A library of runs moved to their effective volume fraction, as files: OUT/cases/ID_nN.json
// (mapped_case_json: the raw values kept beside the mapped ones) with each run's series
// copied beside it. Written by `rbcal library effective-phi` and by the model build.
#include <filesystem>
#include <string>

#include "surrogate/effective_volume_fraction.hpp"

namespace rbcal::surrogate {

// Throws std::invalid_argument naming both files when two runs share an id (the same point
// at the same N_a in two libraries would overwrite each other).
void write_mapped_library(const MappedLibrary& mapped, const EffectiveVolumeFractionOptions& options,
                          const std::filesystem::path& out);

// The mapping's table: the offset and g per resolution, then one line per run and one per
// run left out (libraries: how many libraries the runs came from).
std::string describe_mapped_library(const MappedLibrary& mapped, std::size_t libraries,
                                    const std::filesystem::path& out, const VolumeRatio& volume_ratio,
                                    const EffectiveVolumeFractionOptions& options);

}  // namespace rbcal::surrogate
