#pragma once
// Bending resistance after Li, Dao, Lim & Suresh (Biophys. J. 88 (2005) 3707): an energy
// on every hinge (edge shared by two triangles),
//   E_b = sum_hinges k_d (1 - cos(theta - theta0)),
// theta the angle between the two triangle normals, theta0 its value in the reference
// shape (or 0: a flat reference). For a fine, nearly equilateral triangulation this
// matches the Helfrich energy with bending modulus k_c when k_d = 2 k_c / sqrt(3)
// (Gompper & Kroll, J. Phys. I France 6 (1996) 1305; used by Fedosov et al., Biophys. J.
// 98 (2010) 2215). Units: k_c and the energy in J (or the caller's energy unit).
#include <vector>

#include "solver/membrane/triangle_mesh.hpp"

namespace rbcal::solver {

enum class SpontaneousShape {
  Reference,  // theta0 from the reference mesh: the reference shape is stress-free
  Flat,       // theta0 = 0
};

class DihedralBending {
 public:
  DihedralBending(const TriangleMesh& reference, double bending_modulus, SpontaneousShape shape);

  // k_d = 2 k_c / sqrt(3).
  static double hinge_constant(double bending_modulus);

  // Adds -dE_b/dx to forces and returns E_b.
  double add_forces(const std::vector<Vec3>& x, std::vector<Vec3>& forces) const;
  double energy(const std::vector<Vec3>& x) const;

  // Signed angle between the normals of (a, b, c) and (b, a, d); positive where the
  // surface is convex (as on a sphere with outward orientation).
  static double hinge_angle(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

 private:
  double k_d_;
  std::vector<Hinge> hinges_;
  std::vector<double> theta0_;
};

}  // namespace rbcal::solver
