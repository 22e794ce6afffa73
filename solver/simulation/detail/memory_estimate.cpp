#include "solver/simulation/detail/memory_estimate.hpp"

#include <cmath>
#include <sstream>
#include <cstdio>

#include "solver/lattice_units.hpp"
#include "solver/membrane/cell_shapes.hpp"

namespace rbcal::solver {

namespace {

// From /usr/bin/time -f %M of `rbcal simulate` on the tiny capsule case in a 4a box with a
// checkpoint every step: 43.5 MB at N_a 8 (32^3 nodes) and 260.6 MB at N_a 16 (64^3 nodes).
constexpr double kBytesPerNode = 950.0;
constexpr double kBaseBytes = 13.0e6;
// Per membrane node: positions, velocities, forces, their checkpoint copies, the element
// data of the shared reference (a generous bound).
constexpr double kBytesPerMembraneNode = 600.0;

std::string gib(double bytes) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.3g GiB", bytes / (1024.0 * 1024.0 * 1024.0));
  return buffer;
}

}  // namespace

std::uint64_t estimated_peak_bytes(const SimulationCase& c) {
  const LatticeUnits u = derive_lattice_units(c.flow, c.resolution);
  const double nodes = static_cast<double>(u.nx) * u.ny * u.nz;
  // Cells: the placed ones, or as many as the volume fraction asks for (an upper bound on
  // the seeding's count: the box over the cell's volume at that fraction).
  const double radius = 1.0;
  const TriangleMesh cell = reference_cell(c, radius);
  const double cell_volume = std::abs(enclosed_volume(cell.vertices, cell.triangles));
  const auto& box = c.resolution.box_in_radii;
  const double cells = c.cells.empty() ? std::ceil(c.target_phi * box[0] * box[1] * box[2] / cell_volume) + 1.0
                                       : static_cast<double>(c.cells.size());
  // Float storage halves the two population arrays (19 x 4 bytes saved in each).
  const double per_node = c.single_precision ? kBytesPerNode - 2.0 * 19.0 * 4.0 : kBytesPerNode;
  return static_cast<std::uint64_t>(kBaseBytes + per_node * nodes +
                                    kBytesPerMembraneNode * cells * static_cast<double>(cell.vertices.size()));
}

std::string memory_refusal(const SimulationCase& c, std::uint64_t available) {
  if (available == 0) return "";
  const double need = static_cast<double>(estimated_peak_bytes(c));
  if (need <= 0.9 * static_cast<double>(available)) return "";
  const LatticeUnits u = derive_lattice_units(c.flow, c.resolution);
  const auto& box = c.resolution.box_in_radii;
  std::ostringstream why;
  why << "the case needs about " << gib(need) << " of memory and " << gib(static_cast<double>(available))
      << " is available: its lattice is " << u.nx << " x " << u.ny << " x " << u.nz << " nodes (numerics.N_a "
      << c.resolution.nodes_per_radius << " times numerics.box [" << box[0] << ", " << box[1] << ", " << box[2]
      << "])" << "; lower numerics.N_a or numerics.box, or run it on a larger machine";
  return why.str();
}

}  // namespace rbcal::solver
