#pragma once
// VTK XML files that ParaView opens: membranes as PolyData (.vtp, ASCII) and lattice
// fields as ImageData (.vti, raw appended binary, little-endian), plus a .pvd collection
// listing snapshots by time. Positions and fields as given (lattice units).
#include <string>
#include <utility>
#include <vector>

#include "solver/membrane/triangle_mesh.hpp"

namespace rbcal::solver {

class FluidLattice;

struct VtkMeshes {
  const std::vector<std::vector<Vec3>>* positions;
  const std::vector<std::vector<Vec3>>* velocities;
  const std::vector<std::vector<Vec3>>* forces;
  const std::vector<Triangle>* triangles;
};

void write_membranes_vtp(const std::string& path, const VtkMeshes& meshes);
// Velocity, density and (if given) the inside fraction on the lattice.
void write_fluid_vti(const std::string& path, const FluidLattice& fluid, const std::vector<double>* alpha);
// A ParaView collection of (time, file) pairs.
void write_pvd(const std::string& path, const std::vector<std::pair<double, std::string>>& entries);

}  // namespace rbcal::solver
