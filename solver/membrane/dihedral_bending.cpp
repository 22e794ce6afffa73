#include "solver/membrane/dihedral_bending.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "solver/membrane/element_forces.hpp"
#include "solver/membrane/node_gather.hpp"

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
    const Hinge* h = hinges_.data() + first;
    gather_nodes_to_columns<kBlock>(x, n, [h](int i) { return h[i].a; }, &in[AX]);
    gather_nodes_to_columns<kBlock>(x, n, [h](int i) { return h[i].b; }, &in[BX]);
    gather_nodes_to_columns<kBlock>(x, n, [h](int i) { return h[i].c; }, &in[CX]);
    gather_nodes_to_columns<kBlock>(x, n, [h](int i) { return h[i].d; }, &in[DX]);
    const double* cos0 = cos0_.data() + first;
    const double* sin0 = sin0_.data() + first;
    const double* inv_min_n1sq = inv_min_n1sq_.data() + first;
    const double* inv_min_n2sq = inv_min_n2sq_.data() + first;
#pragma omp simd reduction(+ : energy)
    for (int i = 0; i < n; ++i) {
      const HingeReference r{cos0[i], sin0[i], inv_min_n1sq[i], inv_min_n2sq[i]};
      energy += hinge_forces(&in[0][i], kBlock, r, kd, &out[0][i], kBlock, held_sq[i]);
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

std::vector<HingeReference> DihedralBending::references() const {
  std::vector<HingeReference> r(hinges_.size());
  for (std::size_t i = 0; i < r.size(); ++i) r[i] = {cos0_[i], sin0_[i], inv_min_n1sq_[i], inv_min_n2sq_[i]};
  return r;
}

double DihedralBending::energy(const std::vector<Vec3>& x) const {
  std::vector<Vec3> scratch(x.size(), Vec3::Zero());
  return add_forces(x, scratch);
}

}  // namespace rbcal::solver
