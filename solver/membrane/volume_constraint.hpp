#pragma once
// Enclosed-volume forces of a closed membrane. dV/dx_i = (1/6) sum over the triangles
// (i, j, k) around vertex i of x_j x x_k (cyclic order), i.e. one third of the
// area-weighted outward normals around i.
//
// VolumePenalty keeps a cell's volume at V0 against the slow drift that interpolation
// errors cause in immersed-boundary runs, in the manner of Freund (Phys. Fluids 19 (2007)
// 023301): an isotropic pressure proportional to the relative volume error,
//   E_v = k_v (V - V0)^2 / (2 V0),  F_i = -k_v ((V - V0) / V0) dV/dx_i,
// with k_v in units of pressure. A uniform internal pressure p (E = -p V) gives
// F_i = p dV/dx_i: that is the inflation load of the Laplace-law test.
#include <vector>

#include "solver/membrane/triangle_mesh.hpp"

namespace rbcal::solver {

// Adds scale * dV/dx to forces and returns V.
double add_volume_gradient(const std::vector<Vec3>& x, const std::vector<Triangle>& triangles, double scale,
                           std::vector<Vec3>& forces);

class VolumePenalty {
 public:
  VolumePenalty(double reference_volume, double stiffness);
  // Adds the penalty forces and returns E_v.
  double add_forces(const std::vector<Vec3>& x, const std::vector<Triangle>& triangles,
                    std::vector<Vec3>& forces) const;
  double reference_volume() const { return v0_; }
  double stiffness() const { return k_v_; }

 private:
  double v0_;
  double k_v_;
};

}  // namespace rbcal::solver
