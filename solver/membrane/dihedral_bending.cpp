#include "solver/membrane/dihedral_bending.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace rbcal::solver {

double DihedralBending::hinge_constant(double bending_modulus, BendingConversion conversion) {
  return conversion == BendingConversion::Sphere ? 2.0 * std::sqrt(3.0) * bending_modulus
                                                 : 2.0 * bending_modulus / std::sqrt(3.0);
}

double DihedralBending::hinge_angle(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const auto [n1, n2] = wing_normals(a, b, c, d);
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
  inv_min_n1sq_.reserve(hinges_.size());
  inv_min_n2sq_.reserve(hinges_.size());
  for (const Hinge& h : hinges_) {
    const auto& v = reference.vertices;
    const double theta0 = shape == SpontaneousShape::Reference ? hinge_angle(v[h.a], v[h.b], v[h.c], v[h.d]) : 0.0;
    cos0_.push_back(std::cos(theta0));
    sin0_.push_back(std::sin(theta0));
    const auto [w1, w2] = wing_normals(v, h);
    const double n1 = w1.norm(), n2 = w2.norm();
    inv_min_n1sq_.push_back(1.0 / (kCollapsedArea * kCollapsedArea * n1 * n1));
    inv_min_n2sq_.push_back(1.0 / (kCollapsedArea * kCollapsedArea * n2 * n2));
  }
}

double DihedralBending::add_forces(const std::vector<Vec3>& x, std::vector<Vec3>& forces) const {
  // Hinges in blocks: gather the four nodes into arrays, compute in a loop the compiler
  // vectorises (no indirection inside), scatter the forces. Same arithmetic per hinge as
  // a plain loop; about 3x faster than one.
  constexpr int kBlock = 64;
  enum { AX, AY, AZ, BX, BY, BZ, CX, CY, CZ, DX, DY, DZ, kCoords };
  alignas(64) double in[kCoords][kBlock];
  alignas(64) double out[kCoords][kBlock];  // -dE/dx of nodes a, b, c, d
  alignas(64) double held_sq[kBlock];        // square of the collapsed-wing factor
  double energy = 0.0;
  const double kd = k_d_;
  for (std::size_t first = 0; first < hinges_.size(); first += kBlock) {
    const int n = static_cast<int>(std::min<std::size_t>(kBlock, hinges_.size() - first));
    for (int i = 0; i < n; ++i) {
      const Hinge& h = hinges_[first + i];
      const int node[4] = {h.a, h.b, h.c, h.d};
      for (int v = 0; v < 4; ++v)
        for (int d = 0; d < 3; ++d) in[3 * v + d][i] = x[node[v]][d];
    }
    const double* cos0 = cos0_.data() + first;
    const double* sin0 = sin0_.data() + first;
    const double* inv_min_n1sq = inv_min_n1sq_.data() + first;
    const double* inv_min_n2sq = inv_min_n2sq_.data() + first;
#pragma omp simd reduction(+ : energy)
    for (int i = 0; i < n; ++i) {
      const double ax = in[AX][i], ay = in[AY][i], az = in[AZ][i];
      const double bx = in[BX][i], by = in[BY][i], bz = in[BZ][i];
      const double cx = in[CX][i], cy = in[CY][i], cz = in[CZ][i];
      const double dx = in[DX][i], dy = in[DY][i], dz = in[DZ][i];
      const double ex = bx - ax, ey = by - ay, ez = bz - az;  // the edge
      const double ux = cx - ax, uy = cy - ay, uz = cz - az;
      const double vx = dx - bx, vy = dy - by, vz = dz - bz;
      // n1 = e x (c - a), n2 = (a - b) x (d - b) = v x e
      const double n1x = ey * uz - ez * uy, n1y = ez * ux - ex * uz, n1z = ex * uy - ey * ux;
      const double n2x = vy * ez - vz * ey, n2y = vz * ex - vx * ez, n2z = vx * ey - vy * ex;
      const double len2 = ex * ex + ey * ey + ez * ez;
      const double n1sq = n1x * n1x + n1y * n1y + n1z * n1z, n2sq = n2x * n2x + n2y * n2y + n2z * n2z;
      // One division and two square roots for |e|, 1/|e|, 1/(|n1| |n2|), 1/|n1|^2 and
      // 1/|n2|^2 (divisions and roots bound this loop; it had seven and three).
      const double len = std::sqrt(len2);
      const double n1n2sq = n1sq * n2sq;
      const double q = 1.0 / (len * n1n2sq);
      const double inv_len = q * n1n2sq, inv_n1n2sq = q * len;
      // cos and sin of theta - theta0 from those of theta and theta0 (no atan2, sin, cos):
      // |n1 x n2| = |n1||n2| because both normals are perpendicular to the edge.
      const double crx = n1y * n2z - n1z * n2y, cry = n1z * n2x - n1x * n2z, crz = n1x * n2y - n1y * n2x;
      const double sin_t = (crx * ex + cry * ey + crz * ez) * inv_len, cos_t = n1x * n2x + n1y * n2y + n1z * n2z;
      const double inv_r = std::sqrt(inv_n1n2sq);
      const double cos_delta = (cos_t * cos0[i] + sin_t * sin0[i]) * inv_r;
      const double sin_delta = (sin_t * cos0[i] - cos_t * sin0[i]) * inv_r;
      energy += kd * (1.0 - cos_delta);
      // Gradient of the dihedral angle: the wing vertices move along their triangle
      // normals at rate 1/height; the edge vertices take the rest so that the sum and
      // the torque of the gradient vanish.
      const double sc = -len * n2sq * inv_n1n2sq, sd = -len * n1sq * inv_n1n2sq;
      const double gcx = sc * n1x, gcy = sc * n1y, gcz = sc * n1z;
      const double gdx = sd * n2x, gdy = sd * n2y, gdz = sd * n2z;
      const double inv_len2 = inv_len * inv_len;
      const double pc = ((cx - bx) * ex + (cy - by) * ey + (cz - bz) * ez) * inv_len2;
      const double pd = (vx * ex + vy * ey + vz * ez) * inv_len2;
      const double qc = (ux * ex + uy * ey + uz * ez) * inv_len2;
      const double qd = ((dx - ax) * ex + (dy - ay) * ey + (dz - az) * ez) * inv_len2;
      // A collapsed wing's hold (header) is applied after the loop, where it is needed:
      // here only the squared factor, min(1, |n|^2 / |n_min|^2) over the two wings.
      const double r1 = n1sq * inv_min_n1sq[i], r2 = n2sq * inv_min_n2sq[i];
      held_sq[i] = r1 < r2 ? (r1 < 1.0 ? r1 : 1.0) : (r2 < 1.0 ? r2 : 1.0);
      const double de = -kd * sin_delta;
      out[AX][i] = de * (pc * gcx + pd * gdx);
      out[AY][i] = de * (pc * gcy + pd * gdy);
      out[AZ][i] = de * (pc * gcz + pd * gdz);
      out[BX][i] = -de * (qc * gcx + qd * gdx);
      out[BY][i] = -de * (qc * gcy + qd * gdy);
      out[BZ][i] = -de * (qc * gcz + qd * gdz);
      out[CX][i] = de * gcx;
      out[CY][i] = de * gcy;
      out[CZ][i] = de * gcz;
      out[DX][i] = de * gdx;
      out[DY][i] = de * gdy;
      out[DZ][i] = de * gdz;
    }
    for (int i = 0; i < n; ++i) {
      const Hinge& h = hinges_[first + i];
      const int node[4] = {h.a, h.b, h.c, h.d};
      // Rare: a wing below kCollapsedArea of its rest area.
      const double held = held_sq[i] < 1.0 ? std::sqrt(held_sq[i]) : 1.0;
      for (int v = 0; v < 4; ++v)
        forces[node[v]] += held * Vec3(out[3 * v][i], out[3 * v + 1][i], out[3 * v + 2][i]);
    }
  }
  return energy;
}

double DihedralBending::energy(const std::vector<Vec3>& x) const {
  std::vector<Vec3> scratch(x.size(), Vec3::Zero());
  return add_forces(x, scratch);
}

}  // namespace rbcal::solver
