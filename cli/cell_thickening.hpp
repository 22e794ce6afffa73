#pragma once
// The thickening of the cell a library's runs simulated: its Steiner terms at radius 1
// (cells.* of a case file, read as `rbcal simulate` reads it; every run of a library shares
// them, they are part of the numerics signature) and g(offset / radius), the volume ratio
// the effective-volume-fraction mapping needs (surrogate/effective_volume_fraction.hpp).
#include "formats/json_file.hpp"
#include "solver/membrane/thickened_volume.hpp"
#include "solver/simulation/simulation_case.hpp"
#include "surrogate/effective_volume_fraction.hpp"
#include "surrogate/library_case.hpp"

namespace rbcal::cli {

inline solver::SteinerTerms cell_terms(const surrogate::LibraryCase& c) {
  const solver::SimulationCase run = solver::case_from_json(formats::read_json_file(c.source), c.source.string());
  return solver::steiner_terms(solver::reference_cell(run, 1.0));
}

inline surrogate::VolumeRatio volume_ratio_of(const solver::SteinerTerms& terms) {
  return [terms](double offset_over_radius) { return solver::thickened_volume_ratio(terms, offset_over_radius); };
}

}  // namespace rbcal::cli
