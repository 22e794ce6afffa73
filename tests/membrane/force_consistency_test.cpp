// Every membrane force contribution: zero in the reference shape, zero total force and
// torque on any shape, and equal to minus the gradient of its energy (central finite
// differences, relative error < 1e-6) on randomly perturbed meshes.
#include <gtest/gtest.h>

#include <functional>
#include <random>

#include "solver/membrane/cell_shapes.hpp"
#include "solver/membrane/dihedral_bending.hpp"
#include "solver/membrane/membrane_elasticity.hpp"
#include "solver/membrane/volume_constraint.hpp"

using namespace rbcal::solver;

namespace {

using ForceFn = std::function<double(const std::vector<Vec3>&, std::vector<Vec3>&)>;

std::vector<Vec3> perturbed(const TriangleMesh& m, double amplitude, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-amplitude, amplitude);
  std::vector<Vec3> x = m.vertices;
  for (Vec3& v : x) v += Vec3(u(rng), u(rng), u(rng));
  return x;
}

struct Contribution {
  const char* name;
  ForceFn forces;
};

std::vector<Contribution> contributions(const TriangleMesh& ref) {
  static std::vector<std::unique_ptr<MembraneElasticity>> keep_e;
  static std::vector<std::unique_ptr<DihedralBending>> keep_b;
  static std::vector<std::unique_ptr<VolumePenalty>> keep_v;
  keep_e.push_back(std::make_unique<MembraneElasticity>(ref, MembraneMaterial{MembraneLaw::Skalak, 1.3, 100.0}));
  auto* skalak = keep_e.back().get();
  keep_e.push_back(std::make_unique<MembraneElasticity>(ref, MembraneMaterial{MembraneLaw::NeoHookean, 0.7, 0.0}));
  auto* neo = keep_e.back().get();
  keep_b.push_back(std::make_unique<DihedralBending>(ref, 0.05, SpontaneousShape::Reference));
  auto* bend = keep_b.back().get();
  keep_v.push_back(std::make_unique<VolumePenalty>(enclosed_volume(ref.vertices, ref.triangles), 50.0));
  auto* vol = keep_v.back().get();
  const auto tris = ref.triangles;
  return {
      {"skalak", [skalak](const auto& x, auto& f) { return skalak->add_forces(x, f); }},
      {"neo-hookean", [neo](const auto& x, auto& f) { return neo->add_forces(x, f); }},
      {"bending", [bend](const auto& x, auto& f) { return bend->add_forces(x, f); }},
      {"volume", [vol, tris](const auto& x, auto& f) { return vol->add_forces(x, tris, f); }},
  };
}

}  // namespace

TEST(MembraneForces, VanishInTheReferenceShape) {
  const TriangleMesh ref = make_biconcave_cell(1280, 1.0, BiconcaveProfile::EvansFung);
  for (const Contribution& c : contributions(ref)) {
    std::vector<Vec3> f(ref.vertices.size(), Vec3::Zero());
    const double energy = c.forces(ref.vertices, f);
    double fmax = 0.0;
    for (const Vec3& v : f) fmax = std::max(fmax, v.norm());
    EXPECT_NEAR(energy, 0.0, 1e-12) << c.name;
    EXPECT_LT(fmax, 1e-11) << c.name;
  }
}

TEST(MembraneForces, TotalForceAndTorqueVanish) {
  const TriangleMesh ref = make_biconcave_cell(1280, 1.0, BiconcaveProfile::EvansFung);
  const std::vector<Vec3> x = perturbed(ref, 0.05, 11);
  for (const Contribution& c : contributions(ref)) {
    std::vector<Vec3> f(x.size(), Vec3::Zero());
    c.forces(x, f);
    Vec3 total = Vec3::Zero(), torque = Vec3::Zero();
    double scale = 0.0;
    for (std::size_t i = 0; i < x.size(); ++i) {
      total += f[i];
      torque += x[i].cross(f[i]);
      scale += f[i].norm();
    }
    ASSERT_GT(scale, 0.0) << c.name;
    EXPECT_LT(total.norm() / scale, 1e-13) << c.name;
    EXPECT_LT(torque.norm() / scale, 1e-13) << c.name;
  }
}

TEST(MembraneForces, EqualMinusTheEnergyGradient) {
  for (int triangles : {320, 1280}) {
    const TriangleMesh ref = make_biconcave_cell(triangles, 1.0, BiconcaveProfile::EvansFung);
    std::vector<Vec3> x = perturbed(ref, 0.08, 5 + triangles);
    for (const Contribution& c : contributions(ref)) {
      std::vector<Vec3> f(x.size(), Vec3::Zero());
      c.forces(x, f);
      auto energy = [&](const std::vector<Vec3>& y) {
        std::vector<Vec3> scratch(y.size(), Vec3::Zero());
        return c.forces(y, scratch);
      };
      const double h = 1e-6;
      double err2 = 0.0, norm2 = 0.0;
      for (std::size_t i = 0; i < x.size(); ++i)
        for (int d = 0; d < 3; ++d) {
          const double keep = x[i][d];
          x[i][d] = keep + h;
          const double ep = energy(x);
          x[i][d] = keep - h;
          const double em = energy(x);
          x[i][d] = keep;
          const double fd = -(ep - em) / (2.0 * h);
          err2 += (fd - f[i][d]) * (fd - f[i][d]);
          norm2 += f[i][d] * f[i][d];
        }
      EXPECT_LT(std::sqrt(err2 / norm2), 1e-6) << c.name << " at " << triangles << " triangles";
    }
  }
}
