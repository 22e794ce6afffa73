#pragma once
// A simulation library: a folder LIB/ with finished cases in LIB/cases/<id>.json (plus
// their <id>.csv time series, not read here), optionally LIB/plan.json (the planned
// grid) and LIB/work/ (cases in progress, ignored). docs/reference.md, "Library folder".
#include <filesystem>
#include <optional>
#include <vector>

#include "surrogate/grid_refinement.hpp"
#include "surrogate/library_case.hpp"

namespace rbcal::surrogate {

struct SimulationLibrary {
  std::filesystem::path root;
  std::vector<LibraryCase> cases;  // sorted by file name, so every reader sees one order
  std::optional<ParameterGrid> plan;
};

// Reads every LIB/cases/*.json and LIB/plan.json if present. Rejects, naming the files:
// a case that fails its schema check; cases whose numerics signature
// (formats/library_schema.hpp: resolution, box, kernel, integrator, indicator tolerance,
// coupling interval, volume stiffness, mesh, cell shape and law, averaging window,
// kb_hat; not Re, which a plan may lower for low Ca) differs from the first case's; two
// cases with the same (phi, Ca, lambda); no cases at all.
SimulationLibrary read_library(const std::filesystem::path& root);

// The same consistency checks on cases already read (first case = reference).
void check_library_consistency(const std::vector<LibraryCase>& cases);

}  // namespace rbcal::surrogate
