#include "solver/membrane/volume_constraint.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "solver/membrane/element_forces.hpp"
#include "solver/membrane/node_gather.hpp"

namespace rbcal::solver {

double add_volume_gradient(const std::vector<Vec3>& x, const std::vector<Triangle>& triangles, double scale,
                           std::vector<Vec3>& forces) {
  // Triangles in blocks (gather, a loop the compiler vectorises, scatter), as the
  // membrane's elastic and bending forces.
  constexpr int kBlock = 64;
  enum { AX, AY, AZ, BX, BY, BZ, CX, CY, CZ, kCoords };
  alignas(64) double in[kCoords][kBlock];
  alignas(64) double out[kCoords][kBlock];  // s b x c, s c x a, s a x b
  double six_v = 0.0;
  for (std::size_t first = 0; first < triangles.size(); first += kBlock) {
    const int n = static_cast<int>(std::min<std::size_t>(kBlock, triangles.size() - first));
    const Triangle* t = triangles.data() + first;
    gather_nodes_to_columns<kBlock>(x, n, [t](int i) { return t[i][0]; }, &in[AX]);
    gather_nodes_to_columns<kBlock>(x, n, [t](int i) { return t[i][1]; }, &in[BX]);
    gather_nodes_to_columns<kBlock>(x, n, [t](int i) { return t[i][2]; }, &in[CX]);
#pragma omp simd reduction(+ : six_v)
    for (int i = 0; i < n; ++i) {
      six_v += triangle_volume_gradient(&in[0][i], kBlock, scale, &out[0][i], kBlock);
    }
    for (int i = 0; i < n; ++i)
      for (int v = 0; v < 3; ++v)
        forces[triangles[first + i][v]] += Vec3(out[3 * v][i], out[3 * v + 1][i], out[3 * v + 2][i]);
  }
  return six_v / 6.0;
}

double correct_volume(std::vector<Vec3>& x, const std::vector<Triangle>& triangles, double v0,
                      double* largest_shift) {
  std::vector<Vec3> gradient(x.size(), Vec3::Zero());
  const double v = add_volume_gradient(x, triangles, 1.0, gradient);
  double norm2 = 0.0;
  for (const Vec3& g : gradient) norm2 += g.squaredNorm();
  const double s = (v0 - v) / norm2;
  for (std::size_t i = 0; i < x.size(); ++i) x[i] += s * gradient[i];
  if (largest_shift) *largest_shift = std::abs(v0 - v) / std::sqrt(norm2);
  return v / v0 - 1.0;
}

VolumePenalty::VolumePenalty(double reference_volume, double stiffness) : v0_(reference_volume), k_v_(stiffness) {
  if (!(reference_volume > 0.0)) throw std::invalid_argument("volume penalty: reference volume must be positive");
  if (!(stiffness >= 0.0)) throw std::invalid_argument("volume penalty: stiffness must be >= 0");
}

double VolumePenalty::add_forces(const std::vector<Vec3>& x, const std::vector<Triangle>& triangles,
                                 std::vector<Vec3>& forces) const {
  // One pass over the triangles gives the volume and its gradient; the penalty's factor
  // needs the volume, so the gradient waits in a per-thread scratch (cells run in parallel).
  thread_local std::vector<Vec3> gradient;
  gradient.assign(x.size(), Vec3::Zero());
  const double v = add_volume_gradient(x, triangles, 1.0, gradient);
  const double strain = (v - v0_) / v0_;
  const double scale = -k_v_ * strain;
  for (std::size_t i = 0; i < x.size(); ++i) forces[i] += scale * gradient[i];
  return 0.5 * k_v_ * strain * strain * v0_;
}

}  // namespace rbcal::solver
