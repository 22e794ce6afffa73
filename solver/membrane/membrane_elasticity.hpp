#pragma once
// In-plane elasticity of a membrane on linear (constant-strain) triangles. For a
// triangle with reference edge vectors E1, E2 and deformed edges e1, e2, the metrics
// G_ab = E_a . E_b and g_ab = e_a . e_b give the invariants
//   I1 + 2 = tr(G^-1 g) = lambda1^2 + lambda2^2,   I2 + 1 = det g / det G = (lambda1 lambda2)^2,
// so W = sum_T A0_T w(I1, I2) and the nodal forces -dW/dx follow by the chain rule
// through g (no local frames, no eigenvalues). This is the discrete counterpart of the
// weak form used by the seed study. Forces are invariant under rigid motions by
// construction: their sum and torque vanish.
#include <vector>

#include "solver/membrane/strain_energy.hpp"
#include "solver/membrane/triangle_mesh.hpp"

namespace rbcal::solver {

class MembraneElasticity {
 public:
  MembraneElasticity(const TriangleMesh& reference, const MembraneMaterial& material);

  // Adds -dW/dx to forces (same size as x) and returns W.
  double add_forces(const std::vector<Vec3>& x, std::vector<Vec3>& forces) const;
  double energy(const std::vector<Vec3>& x) const;

  const MembraneMaterial& material() const { return material_; }

  // Per element, as structure of arrays (the force loop runs over blocks of elements).
  struct Elements {
    std::vector<int> v0, v1, v2;
    std::vector<double> inv_g11, inv_g12, inv_g22;  // inverse reference metric
    std::vector<double> inv_det_g;                  // 1 / det G
    std::vector<double> area;                       // reference area A0
  };

  const Elements& elements() const { return elements_; }

 private:
  MembraneMaterial material_;
  Elements elements_;
};

}  // namespace rbcal::solver
