#pragma once
// Bending resistance after Li, Dao, Lim & Suresh (Biophys. J. 88 (2005) 3707): an energy
// on every hinge (edge shared by two triangles),
//   E_b = sum_hinges k_d (1 - cos(theta - theta0)),
// theta the angle between the two triangle normals, theta0 its value in the reference
// shape (or 0: a flat reference).
//
// The discrete constant k_d and the continuum bending modulus k_c are related by the
// shape the match is made on. For an equilateral triangulation of edge l on a sphere of
// radius R, theta = l / (sqrt(3) R) and there are 8 sqrt(3) pi R^2 / l^2 edges, so
// E_b = (4 pi / sqrt(3)) k_d; Helfrich's 8 pi k_c then needs k_d = 2 sqrt(3) k_c
// (BendingConversion::Sphere, the default). On a cylinder the same argument gives
// k_d = 2 k_c / sqrt(3) (Gompper & Kroll, J. Phys. I France 6 (1996) 1305; the factor
// quoted by Fedosov et al., Biophys. J. 98 (2010) 2215): BendingConversion::Cylinder.
// The dihedral energy is not isotropic in curvature, so no single factor serves both.
// On icosahedral meshes, whose triangles are not all equilateral, the sphere's energy
// with the Sphere factor is 1.032, 1.034 and 1.035 times 8 pi k_c at 320, 1280 and
// 5120 triangles: it settles about 3.5 % high instead of converging to Helfrich's value.
//
// The angle's gradient grows as 1 / (area of a wing triangle): a triangle that collapses
// (dense, high-Ca runs squeeze a few to under 1 % of their rest area) would get a force
// that jumps a thousandfold in one step and blows the run up. Below kCollapsedArea of
// its rest area a wing's gradient is therefore held at that area's value: the hinge's
// forces are scaled by |n| / (kCollapsedArea |n_rest|), a common factor, so they stay
// free of net force and torque. Healthy meshes are unaffected.
#include <vector>

#include "solver/membrane/element_forces.hpp"
#include "solver/membrane/triangle_mesh.hpp"

namespace rbcal::solver {

enum class BendingConversion {
  Sphere,    // k_d = 2 sqrt(3) k_c
  Cylinder,  // k_d = 2 k_c / sqrt(3)
};

enum class SpontaneousShape {
  Reference,  // theta0 from the reference mesh: the reference shape is stress-free
  Flat,       // theta0 = 0
};

class DihedralBending {
 public:
  DihedralBending(const TriangleMesh& reference, double bending_modulus, SpontaneousShape shape,
                  BendingConversion conversion = BendingConversion::Sphere);

  // k_d for the continuum modulus k_c.
  static double hinge_constant(double bending_modulus, BendingConversion conversion);

  // Adds -dE_b/dx to forces and returns E_b.
  double add_forces(const std::vector<Vec3>& x, std::vector<Vec3>& forces) const;
  double energy(const std::vector<Vec3>& x) const;

  // Signed angle between the normals of (a, b, c) and (b, a, d); positive where the
  // surface is convex (as on a sphere with outward orientation).
  static double hinge_angle(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

  double hinge_constant() const { return k_d_; }
  const std::vector<Hinge>& hinges() const { return hinges_; }
  // Each hinge's reference data, in the order of hinges() (for the device path).
  std::vector<HingeReference> references() const;

  // Fraction of its rest area below which a wing triangle's gradient is held.
  static constexpr double kCollapsedArea = 0.02;

 private:
  double k_d_;
  std::vector<Hinge> hinges_;
  std::vector<double> cos0_, sin0_;  // of each hinge's spontaneous angle
  // 1 / the smallest |n|^2 (n: twice the area vector) used for the wings (a, b, c) and
  // (b, a, d).
  std::vector<double> inv_min_n1sq_, inv_min_n2sq_;
};

}  // namespace rbcal::solver
