#include "solver/membrane/dihedral_bending.hpp"

#include <cmath>
#include <stdexcept>

namespace rbcal::solver {

double DihedralBending::hinge_constant(double bending_modulus, BendingConversion conversion) {
  return conversion == BendingConversion::Sphere ? 2.0 * std::sqrt(3.0) * bending_modulus
                                                 : 2.0 * bending_modulus / std::sqrt(3.0);
}

double DihedralBending::hinge_angle(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const Vec3 n1 = (b - a).cross(c - a);  // triangle (a, b, c)
  const Vec3 n2 = (a - b).cross(d - b);  // triangle (b, a, d)
  const Vec3 e = b - a;
  // sin(theta) |n1||n2| = (n1 x n2) . e/|e|, cos(theta) |n1||n2| = n1 . n2
  return std::atan2(n1.cross(n2).dot(e) / e.norm(), n1.dot(n2));
}

DihedralBending::DihedralBending(const TriangleMesh& reference, double bending_modulus, SpontaneousShape shape,
                                 BendingConversion conversion)
    : k_d_(hinge_constant(bending_modulus, conversion)), hinges_(build_hinges(reference)) {
  if (!(bending_modulus >= 0.0)) throw std::invalid_argument("bending: modulus must be >= 0");
  cos0_.reserve(hinges_.size());
  sin0_.reserve(hinges_.size());
  for (const Hinge& h : hinges_) {
    const auto& v = reference.vertices;
    const double theta0 = shape == SpontaneousShape::Reference ? hinge_angle(v[h.a], v[h.b], v[h.c], v[h.d]) : 0.0;
    cos0_.push_back(std::cos(theta0));
    sin0_.push_back(std::sin(theta0));
  }
}

double DihedralBending::add_forces(const std::vector<Vec3>& x, std::vector<Vec3>& forces) const {
  double energy = 0.0;
  for (std::size_t i = 0; i < hinges_.size(); ++i) {
    const Hinge& h = hinges_[i];
    const Vec3 &a = x[h.a], &b = x[h.b], &c = x[h.c], &d = x[h.d];
    const Vec3 e = b - a;
    const Vec3 n1 = e.cross(c - a);
    const Vec3 n2 = (a - b).cross(d - b);
    const double len = e.norm();
    const double n1sq = n1.squaredNorm(), n2sq = n2.squaredNorm();
    // cos and sin of theta - theta0 from those of theta and theta0 (no atan2, sin, cos):
    // |n1 x n2| = |n1||n2| because both normals are perpendicular to the edge.
    const double sin_t = n1.cross(n2).dot(e) / len, cos_t = n1.dot(n2);
    const double inv_r = 1.0 / std::sqrt(sin_t * sin_t + cos_t * cos_t);
    const double cos_delta = (cos_t * cos0_[i] + sin_t * sin0_[i]) * inv_r;
    const double sin_delta = (sin_t * cos0_[i] - cos_t * sin0_[i]) * inv_r;
    energy += k_d_ * (1.0 - cos_delta);

    // Gradient of the dihedral angle: the wing vertices move along their triangle
    // normals at rate 1/height; the edge vertices take the rest so that the sum and
    // the torque of the gradient vanish.
    const Vec3 gc = -(len / n1sq) * n1;
    const Vec3 gd = -(len / n2sq) * n2;
    const double inv_len2 = 1.0 / (len * len);
    const Vec3 ga = ((c - b).dot(e) * inv_len2) * gc + ((d - b).dot(e) * inv_len2) * gd;
    const Vec3 gb = -((c - a).dot(e) * inv_len2) * gc - ((d - a).dot(e) * inv_len2) * gd;
    const double dE = k_d_ * sin_delta;
    forces[h.a] -= dE * ga;
    forces[h.b] -= dE * gb;
    forces[h.c] -= dE * gc;
    forces[h.d] -= dE * gd;
  }
  return energy;
}

double DihedralBending::energy(const std::vector<Vec3>& x) const {
  std::vector<Vec3> scratch(x.size(), Vec3::Zero());
  return add_forces(x, scratch);
}

}  // namespace rbcal::solver
