#pragma once
// All membrane forces of one cell: in-plane elasticity, bending and the volume penalty.
// One instance serves every cell that shares the reference mesh (the reference data is
// per element, the state is the positions passed in). Units: the caller's (lattice
// units in the flow solver).
#include <vector>

#include "solver/membrane/dihedral_bending.hpp"
#include "solver/membrane/membrane_elasticity.hpp"
#include "solver/membrane/volume_constraint.hpp"

namespace rbcal::solver {

struct CellMembraneSettings {
  MembraneMaterial material;
  double bending_modulus = 0.0;  // k_c; 0 switches bending off
  BendingConversion bending_conversion = BendingConversion::Sphere;
  double volume_stiffness = 0.0;  // k_v (pressure units); 0 switches the penalty off
};

class CellMembrane {
 public:
  CellMembrane(const TriangleMesh& reference, const CellMembraneSettings& settings);

  // Adds the membrane forces -dW/dx to forces and returns W.
  double add_forces(const std::vector<Vec3>& x, std::vector<Vec3>& forces) const;

  const TriangleMesh& reference() const { return reference_; }
  double reference_volume() const { return volume_.reference_volume(); }
  const MembraneElasticity& elasticity() const { return elastic_; }
  const DihedralBending& bending() const { return bending_; }
  bool has_bending() const { return with_bending_; }
  double volume_stiffness() const { return volume_.stiffness(); }

 private:
  TriangleMesh reference_;
  MembraneElasticity elastic_;
  DihedralBending bending_;
  VolumePenalty volume_;
  bool with_bending_;
};

}  // namespace rbcal::solver
