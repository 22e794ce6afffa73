#pragma once
// Enclosed-volume forces of a closed membrane. dV/dx_i = (1/6) sum over the triangles
// (i, j, k) around vertex i of x_j x x_k (cyclic order), i.e. one third of the
// area-weighted outward normals around i.
//
// In immersed-boundary runs the interpolated velocity is not exactly divergence-free
// on the membrane, so a cell's volume drifts slowly. correct_volume removes the drift
// after each step, in the spirit of Freund (Phys. Fluids 19 (2007) 023301): the
// smallest displacement that restores V0 to first order, x += s dV/dx with
// s = (V0 - V) / |dV/dx|^2, i.e. a uniform normal shift weighted by the vertex areas.
// A penalty force cannot do this job: a uniform normal load on a closed surface only
// raises the inner pressure of an incompressible fluid and moves nothing.
//
// VolumePenalty, E_v = k_v (V - V0)^2 / (2 V0), F_i = -k_v ((V - V0) / V0) dV/dx_i (k_v in
// units of pressure), serves static equilibria. A uniform internal pressure p
// (E = -p V) gives F_i = p dV/dx_i: the inflation load of the Laplace-law test.
#include <vector>

#include "solver/membrane/triangle_mesh.hpp"

namespace rbcal::solver {

// Adds scale * dV/dx to forces and returns V.
double add_volume_gradient(const std::vector<Vec3>& x, const std::vector<Triangle>& triangles, double scale,
                           std::vector<Vec3>& forces);

// Shifts x so that the enclosed volume returns to v0 (to first order); returns the
// relative volume error before the correction. With `largest_shift`, also a bound on how far
// any node moved: |V0 - V| / |dV/dx| (no node's share of the gradient exceeds its norm).
double correct_volume(std::vector<Vec3>& x, const std::vector<Triangle>& triangles, double v0,
                      double* largest_shift = nullptr);

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
