#include "solver/membrane/membrane_elasticity.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace rbcal::solver {

MembraneElasticity::MembraneElasticity(const TriangleMesh& reference, const MembraneMaterial& material)
    : material_(material) {
  if (!(material.shear_modulus > 0.0)) throw std::invalid_argument("membrane: shear modulus must be positive");
  if (material.law == MembraneLaw::Skalak && !(material.area_dilation_c > -0.5))
    throw std::invalid_argument("membrane: Skalak C must exceed -1/2 (positive area modulus)");
  elements_.reserve(reference.triangles.size());
  for (std::size_t t = 0; t < reference.triangles.size(); ++t) {
    const Triangle& tri = reference.triangles[t];
    const Vec3 e1 = reference.vertices[tri[1]] - reference.vertices[tri[0]];
    const Vec3 e2 = reference.vertices[tri[2]] - reference.vertices[tri[0]];
    const double g11 = e1.dot(e1), g12 = e1.dot(e2), g22 = e2.dot(e2);
    const double det = g11 * g22 - g12 * g12;
    if (!(det > 0.0)) throw std::invalid_argument("membrane: reference triangle " + std::to_string(t) + " is degenerate");
    elements_.push_back({tri[0], tri[1], tri[2], g22 / det, -g12 / det, g11 / det, 1.0 / det, 0.5 * std::sqrt(det)});
  }
}

double MembraneElasticity::add_forces(const std::vector<Vec3>& x, std::vector<Vec3>& forces) const {
  double energy = 0.0;
  for (const Element& el : elements_) {
    const Vec3 e1 = x[el.v1] - x[el.v0];
    const Vec3 e2 = x[el.v2] - x[el.v0];
    const double g11 = e1.dot(e1), g12 = e1.dot(e2), g22 = e2.dot(e2);
    const double i1 = el.inv_g11 * g11 + 2.0 * el.inv_g12 * g12 + el.inv_g22 * g22 - 2.0;
    const double j2 = (g11 * g22 - g12 * g12) * el.inv_det_g;
    const EnergyDensity w = strain_energy(material_, i1, j2 - 1.0);
    energy += el.area * w.w;
    // dI1/de1 = 2 (G^11 e1 + G^12 e2), dI2/de1 = 2 (g22 e1 - g12 e2) / det G; likewise for e2.
    const double a = 2.0 * el.area * w.dw_dI1;
    const double b = 2.0 * el.area * w.dw_dI2 * el.inv_det_g;
    const Vec3 f1 = -(a * (el.inv_g11 * e1 + el.inv_g12 * e2) + b * (g22 * e1 - g12 * e2));
    const Vec3 f2 = -(a * (el.inv_g12 * e1 + el.inv_g22 * e2) + b * (g11 * e2 - g12 * e1));
    forces[el.v1] += f1;
    forces[el.v2] += f2;
    forces[el.v0] -= f1 + f2;
  }
  return energy;
}

double MembraneElasticity::energy(const std::vector<Vec3>& x) const {
  std::vector<Vec3> scratch(x.size(), Vec3::Zero());
  return add_forces(x, scratch);
}

}  // namespace rbcal::solver
