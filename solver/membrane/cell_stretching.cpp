#include "solver/membrane/cell_stretching.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

#include "solver/membrane/dihedral_bending.hpp"
#include "solver/membrane/membrane_elasticity.hpp"
#include "solver/membrane/volume_constraint.hpp"
#include "solver/numerics/detail/lbfgs.hpp"

namespace rbcal::solver {

namespace {

std::vector<Vec3> unpack(const Eigen::VectorXd& v) {
  std::vector<Vec3> x(v.size() / 3);
  for (std::size_t i = 0; i < x.size(); ++i) x[i] = v.segment<3>(3 * i);
  return x;
}

}  // namespace

std::vector<StretchPoint> stretch_cell(const StretchSettings& s, const std::vector<double>& forces) {
  if (!(s.radius > 0.0)) throw std::invalid_argument("stretch: radius must be positive");
  if (!(s.contact_fraction > 0.0 && s.contact_fraction < 0.5))
    throw std::invalid_argument("stretch: contact fraction must be in (0, 0.5)");
  for (double f : forces)
    if (!(f >= 0.0)) throw std::invalid_argument("stretch: forces must be >= 0");

  // Work in units of a (length), G_s a^2 (energy) and G_s a (force).
  const double gs = s.material.shear_modulus;
  const TriangleMesh reference = make_biconcave_cell(s.triangles, 1.0, s.profile);
  MembraneMaterial unit_material = s.material;
  unit_material.shear_modulus = 1.0;
  const MembraneElasticity elastic(reference, unit_material);
  const DihedralBending bending(reference, s.bending_modulus / (gs * s.radius * s.radius), SpontaneousShape::Reference);
  const double v0 = enclosed_volume(reference.vertices, reference.triangles);
  const double a0 = surface_area(reference.vertices, reference.triangles);

  // End patches: the vertices furthest out along +x and -x.
  const int nv = static_cast<int>(reference.vertices.size());
  const int patch = std::max(1, static_cast<int>(std::lround(s.contact_fraction * nv)));
  std::vector<int> order(nv);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(),
            [&](int i, int j) { return reference.vertices[i].x() < reference.vertices[j].x(); });

  Eigen::VectorXd x(3 * nv);
  for (int i = 0; i < nv; ++i) x.segment<3>(3 * i) = reference.vertices[i];

  const double penalty = 100.0;  // augmented-Lagrangian stiffness, units of G_s / a
  double multiplier = 0.0;
  std::vector<double> sorted = forces;
  std::sort(sorted.begin(), sorted.end());
  std::vector<StretchPoint> points;
  for (double force : sorted) {
    const double per_vertex = force / (gs * s.radius) / patch;
    auto objective = [&](const Eigen::VectorXd& v, Eigen::VectorXd& gradient) {
      const std::vector<Vec3> pos = unpack(v);
      std::vector<Vec3> f(nv, Vec3::Zero());
      double energy = elastic.add_forces(pos, f) + bending.add_forces(pos, f);
      const double c = (enclosed_volume(pos, reference.triangles) - v0) / v0;
      energy += v0 * (multiplier * c + 0.5 * penalty * c * c);
      add_volume_gradient(pos, reference.triangles, -(multiplier + penalty * c), f);
      for (int k = 0; k < patch; ++k) {
        const int left = order[k], right = order[nv - 1 - k];
        f[left].x() -= per_vertex;
        f[right].x() += per_vertex;
        energy += per_vertex * (pos[left].x() - pos[right].x());
      }
      for (int i = 0; i < nv; ++i) gradient.segment<3>(3 * i) = -f[i];
      return energy;
    };

    StretchPoint point;
    point.force = force;
    LbfgsSettings ls;
    ls.gradient_tolerance = s.gradient_tolerance;
    double c = 0.0;
    for (int pass = 0; pass < 30; ++pass) {
      const LbfgsResult r = minimize_lbfgs(objective, x, ls);
      point.iterations += r.iterations;
      point.converged = r.converged;
      c = (enclosed_volume(unpack(x), reference.triangles) - v0) / v0;
      if (std::abs(c) < s.volume_tolerance && r.converged) break;
      multiplier += penalty * c;
    }
    const std::vector<Vec3> pos = unpack(x);
    const Bounds box = bounding_box(pos);
    point.axial_diameter = (box.hi.x() - box.lo.x()) * s.radius;
    point.transverse_diameter = (box.hi.y() - box.lo.y()) * s.radius;
    point.volume_error = c;
    point.area_change = surface_area(pos, reference.triangles) / a0 - 1.0;
    point.converged = point.converged && std::abs(c) < s.volume_tolerance;
    points.push_back(point);
  }
  return points;
}

}  // namespace rbcal::solver
