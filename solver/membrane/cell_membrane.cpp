#include "solver/membrane/cell_membrane.hpp"

namespace rbcal::solver {

CellMembrane::CellMembrane(const TriangleMesh& reference, const CellMembraneSettings& s)
    : reference_(reference),
      elastic_(reference, s.material),
      bending_(reference, s.bending_modulus, SpontaneousShape::Reference, s.bending_conversion),
      volume_(enclosed_volume(reference.vertices, reference.triangles), s.volume_stiffness),
      with_bending_(s.bending_modulus > 0.0) {}

double CellMembrane::add_forces(const std::vector<Vec3>& x, std::vector<Vec3>& forces) const {
  double w = elastic_.add_forces(x, forces);
  if (with_bending_) w += bending_.add_forces(x, forces);
  if (volume_.stiffness() > 0.0) w += volume_.add_forces(x, reference_.triangles, forces);
  return w;
}

}  // namespace rbcal::solver
