#include "solver/membrane/membrane_elasticity.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "solver/membrane/element_forces.hpp"
#include "solver/membrane/node_gather.hpp"

namespace rbcal::solver {

MembraneElasticity::MembraneElasticity(const TriangleMesh& reference, const MembraneMaterial& material)
    : material_(material) {
  if (!(material.shear_modulus > 0.0)) throw std::invalid_argument("membrane: shear modulus must be positive");
  if (material.law == MembraneLaw::Skalak && !(material.area_dilation_c > -0.5))
    throw std::invalid_argument("membrane: Skalak C must exceed -1/2 (positive area modulus)");
  for (std::size_t t = 0; t < reference.triangles.size(); ++t) {
    const Triangle& tri = reference.triangles[t];
    const Vec3 e1 = reference.vertices[tri[1]] - reference.vertices[tri[0]];
    const Vec3 e2 = reference.vertices[tri[2]] - reference.vertices[tri[0]];
    const double g11 = e1.dot(e1), g12 = e1.dot(e2), g22 = e2.dot(e2);
    const double det = g11 * g22 - g12 * g12;
    if (!(det > 0.0)) throw std::invalid_argument("membrane: reference triangle " + std::to_string(t) + " is degenerate");
    elements_.v0.push_back(tri[0]);
    elements_.v1.push_back(tri[1]);
    elements_.v2.push_back(tri[2]);
    elements_.inv_g11.push_back(g22 / det);
    elements_.inv_g12.push_back(-g12 / det);
    elements_.inv_g22.push_back(g11 / det);
    elements_.inv_det_g.push_back(1.0 / det);
    elements_.area.push_back(0.5 * std::sqrt(det));
  }
}

namespace {

// Elements in blocks, as in DihedralBending::add_forces: gather the three nodes into
// arrays, compute in a loop the compiler vectorises, scatter the forces. The law is a
// template argument so that the loop body has no branch.
template <MembraneLaw law>
double add_element_forces(const std::vector<Vec3>& x, const MembraneElasticity::Elements& el,
                          const MembraneMaterial& m, std::vector<Vec3>& forces) {
  constexpr int kBlock = 64;
  enum { AX, AY, AZ, BX, BY, BZ, CX, CY, CZ, kCoords };
  alignas(64) double in[kCoords][kBlock];
  alignas(64) double out[6][kBlock];  // -dW/dx of nodes v1 and v2 (v0 takes minus their sum)
  const double gs = m.shear_modulus, c = m.area_dilation_c;
  double energy = 0.0;
  const std::size_t count = el.v0.size();
  for (std::size_t first = 0; first < count; first += kBlock) {
    const int n = static_cast<int>(std::min<std::size_t>(kBlock, count - first));
    const int *v0 = el.v0.data() + first, *v1 = el.v1.data() + first, *v2 = el.v2.data() + first;
    gather_nodes_to_columns<kBlock>(x, n, [v0](int i) { return v0[i]; }, &in[AX]);
    gather_nodes_to_columns<kBlock>(x, n, [v1](int i) { return v1[i]; }, &in[BX]);
    gather_nodes_to_columns<kBlock>(x, n, [v2](int i) { return v2[i]; }, &in[CX]);
    const double* inv_g11 = el.inv_g11.data() + first;
    const double* inv_g12 = el.inv_g12.data() + first;
    const double* inv_g22 = el.inv_g22.data() + first;
    const double* inv_det_g = el.inv_det_g.data() + first;
    const double* area = el.area.data() + first;
#pragma omp simd reduction(+ : energy)
    for (int i = 0; i < n; ++i) {
      const ElasticElementReference r{inv_g11[i], inv_g12[i], inv_g22[i], inv_det_g[i], area[i]};
      energy += elastic_element_forces<law>(&in[0][i], kBlock, r, gs, c, &out[0][i], kBlock);
    }
    for (int i = 0; i < n; ++i) {
      const Vec3 f1(out[0][i], out[1][i], out[2][i]), f2(out[3][i], out[4][i], out[5][i]);
      forces[el.v1[first + i]] += f1;
      forces[el.v2[first + i]] += f2;
      forces[el.v0[first + i]] -= f1 + f2;
    }
  }
  return energy;
}

}  // namespace

double MembraneElasticity::add_forces(const std::vector<Vec3>& x, std::vector<Vec3>& forces) const {
  return material_.law == MembraneLaw::Skalak ? add_element_forces<MembraneLaw::Skalak>(x, elements_, material_, forces)
                                              : add_element_forces<MembraneLaw::NeoHookean>(x, elements_, material_, forces);
}

double MembraneElasticity::energy(const std::vector<Vec3>& x) const {
  std::vector<Vec3> scratch(x.size(), Vec3::Zero());
  return add_forces(x, scratch);
}

}  // namespace rbcal::solver
