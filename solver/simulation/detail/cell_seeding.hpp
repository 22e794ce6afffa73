#pragma once
// Initial placement of N cells for a target volume fraction phi in the wall-bounded box,
// deterministic for a seed, with no overlapping membranes and every node at least
// `wall_gap` from the walls.
//
// N = round(phi V_box / V_cell); the phi reached is reported (within 0.5 % of the target
// for boxes holding a few hundred cells, like the seed study's). Two stages:
//  1. random sequential addition: uniformly random centres and orientations, accepted
//     when the cell's circumscribed sphere (radius a) overlaps no other's; this leaves no
//     overlap by construction and suffices for dilute suspensions;
//  2. if (1) stalls, slots: the box is cut into a grid of cells' bounding boxes (disc
//     axes along the streamwise z, the thin direction), a random choice of N slots is
//     filled, each cell spun randomly about its axis (which keeps it inside its slot) and
//     shifted randomly within the slot's slack. Neighbouring slots do not overlap, so
//     neither do the cells. Dense suspensions start this way and shear randomises them;
//  3. if the grid has too few slots, hexagonal rows of discs in the x-y plane (e.g. up
//     to phi 0.59 instead of 0.44 in the 6a x 8a x 6a box of the v2 library, Evans-Fung
//     cells). Cells touch their neighbours there; no stage shrinks them.
#include <cstdint>
#include <vector>

#include "solver/simulation/simulation_case.hpp"

namespace rbcal::solver {

struct SeedingResult {
  std::vector<CellPlacement> placements;  // centres in a, relative to the box centre
  double phi = 0.0;                       // reached volume fraction
  bool used_slots = false;
};

// reference: the cell mesh at radius 1 (symmetry axis z); box and wall_gap in a.
SeedingResult seed_cells(double target_phi, const TriangleMesh& reference, const std::array<double, 3>& box,
                         double wall_gap, std::uint64_t seed);

}  // namespace rbcal::solver
