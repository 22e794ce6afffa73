#include "solver/membrane/volume_constraint.hpp"

#include <stdexcept>

namespace rbcal::solver {

double add_volume_gradient(const std::vector<Vec3>& x, const std::vector<Triangle>& triangles, double scale,
                           std::vector<Vec3>& forces) {
  double six_v = 0.0;
  const double s = scale / 6.0;
  for (const Triangle& t : triangles) {
    const Vec3 &a = x[t[0]], &b = x[t[1]], &c = x[t[2]];
    const Vec3 bc = b.cross(c);
    six_v += a.dot(bc);
    forces[t[0]] += s * bc;
    forces[t[1]] += s * c.cross(a);
    forces[t[2]] += s * a.cross(b);
  }
  return six_v / 6.0;
}

double correct_volume(std::vector<Vec3>& x, const std::vector<Triangle>& triangles, double v0) {
  std::vector<Vec3> gradient(x.size(), Vec3::Zero());
  const double v = add_volume_gradient(x, triangles, 1.0, gradient);
  double norm2 = 0.0;
  for (const Vec3& g : gradient) norm2 += g.squaredNorm();
  const double s = (v0 - v) / norm2;
  for (std::size_t i = 0; i < x.size(); ++i) x[i] += s * gradient[i];
  return v / v0 - 1.0;
}

VolumePenalty::VolumePenalty(double reference_volume, double stiffness) : v0_(reference_volume), k_v_(stiffness) {
  if (!(reference_volume > 0.0)) throw std::invalid_argument("volume penalty: reference volume must be positive");
  if (!(stiffness >= 0.0)) throw std::invalid_argument("volume penalty: stiffness must be >= 0");
}

double VolumePenalty::add_forces(const std::vector<Vec3>& x, const std::vector<Triangle>& triangles,
                                 std::vector<Vec3>& forces) const {
  const double v = enclosed_volume(x, triangles);
  const double strain = (v - v0_) / v0_;
  add_volume_gradient(x, triangles, -k_v_ * strain, forces);
  return 0.5 * k_v_ * strain * strain * v0_;
}

}  // namespace rbcal::solver
