#pragma once
// Candidate grids for new library cases: a plan's grid refined between its values.
#include "formats/plan_grid.hpp"

namespace rbcal::surrogate {

using formats::ParameterGrid;
using formats::ParameterPoint;

// The grid with the midpoint inserted between neighbouring values of each axis (phi
// linearly, Ca and lambda geometrically); axes are sorted and de-duplicated first.
ParameterGrid refined(const ParameterGrid& grid);

}  // namespace rbcal::surrogate
