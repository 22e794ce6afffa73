#include "solver/coupling/stresslet.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <numbers>

namespace rbcal::solver {

Mat3 cell_stresslet(const std::vector<Vec3>& x, const std::vector<Vec3>& membrane_forces,
                    const std::vector<Vec3>& velocities, const std::vector<Triangle>& triangles, double eta0,
                    double viscosity_ratio) {
  const Vec3 c = vertex_centroid(x);
  Mat3 s = Mat3::Zero();
  for (std::size_t i = 0; i < x.size(); ++i) {
    const Vec3 r = x[i] - c;
    const Vec3 q = -membrane_forces[i];
    s += 0.5 * (r * q.transpose() + q * r.transpose());
  }
  if (viscosity_ratio != 1.0) {
    const double k = -eta0 * (1.0 - viscosity_ratio) / 6.0;  // a third of half the cross product
    for (const Triangle& t : triangles) {
      const Vec3 n2a = (x[t[1]] - x[t[0]]).cross(x[t[2]] - x[t[0]]);  // 2 A n
      for (int m = 0; m < 3; ++m) {
        const Vec3& v = velocities[t[m]];
        s += k * (v * n2a.transpose() + n2a * v.transpose());
      }
    }
  }
  return s;
}

Mat3 volume_second_moment(const std::vector<Vec3>& x, const std::vector<Triangle>& triangles, Vec3* centroid) {
  // Tetrahedra from a reference point: volume and first moment give the centroid, then
  // int r r dV over tetra (0, a, b, c) = det/120 (aa + bb + cc + (a+b+c)(a+b+c)).
  const Vec3 o = vertex_centroid(x);
  double six_v = 0.0;
  Vec3 first = Vec3::Zero();
  Mat3 second = Mat3::Zero();
  for (const Triangle& t : triangles) {
    const Vec3 a = x[t[0]] - o, b = x[t[1]] - o, cc = x[t[2]] - o;
    const double det = a.dot(b.cross(cc));
    const Vec3 sum = a + b + cc;
    six_v += det;
    first += det * sum / 24.0;
    second += det / 120.0 * (a * a.transpose() + b * b.transpose() + cc * cc.transpose() + sum * sum.transpose());
  }
  const double volume = six_v / 6.0;
  const Vec3 shift = first / volume;  // centroid relative to o
  if (centroid) *centroid = o + shift;
  return second - volume * shift * shift.transpose();
}

ShearPlaneShape shear_plane_shape(const std::vector<Vec3>& x, const std::vector<Triangle>& triangles) {
  const Mat3 m = volume_second_moment(x, triangles);
  const double volume = enclosed_volume(x, triangles);
  Eigen::Matrix2d plane;  // (z, y) block: flow direction first
  plane << m(2, 2), m(2, 1), m(1, 2), m(1, 1);
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(plane);
  ShearPlaneShape s;
  // Equivalent ellipsoid: semi-axis^2 = 5 (second moment) / V.
  s.major = std::sqrt(5.0 * eig.eigenvalues()(1) / volume);
  s.minor = std::sqrt(5.0 * eig.eigenvalues()(0) / volume);
  s.taylor_deformation = (s.major - s.minor) / (s.major + s.minor);
  const Eigen::Vector2d axis = eig.eigenvectors().col(1);  // (z, y) components
  s.inclination = std::atan2(axis(1), axis(0));
  if (s.inclination > std::numbers::pi / 2) s.inclination -= std::numbers::pi;
  if (s.inclination < -std::numbers::pi / 2) s.inclination += std::numbers::pi;
  return s;
}

Vec3 short_axis(const std::vector<Vec3>& x, const std::vector<Triangle>& triangles) {
  Eigen::SelfAdjointEigenSolver<Mat3> eig(volume_second_moment(x, triangles));
  return eig.eigenvectors().col(0);  // eigenvalues ascending
}

}  // namespace rbcal::solver
