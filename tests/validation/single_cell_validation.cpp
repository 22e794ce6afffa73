// Single-cell validations of the coupled solver (ctest label `validation`; tens of
// minutes on two cores). Each case is run with the same code path as `rbcal simulate`
// and its outputs are kept under validation_runs/ in the working directory; the measured
// numbers are recorded in docs/validation.md.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "solver/membrane/cell_shapes.hpp"
#include "solver/membrane/rigid_spheroid_viscosity.hpp"
#include "solver/membrane/thickened_volume.hpp"
#include "solver/simulation/case_runner.hpp"

using namespace rbcal::solver;

namespace {

SimulationCase spherical_capsule(double ca_g, int nodes_per_radius) {
  SimulationCase c;
  c.shape = CellShape::Sphere;
  c.triangles = 1280;
  c.law = MembraneLaw::NeoHookean;
  c.flow.capillary_number = ca_g;
  c.flow.viscosity_ratio = 1.0;
  c.flow.reduced_bending = 0.0;
  c.flow.reynolds_number = 0.2;
  c.resolution.nodes_per_radius = nodes_per_radius;
  c.resolution.box_in_radii = {6.0, 10.0, 8.0};
  c.cells.push_back({});
  c.strain_end = 6.0;
  c.window = {5.0, 6.0};
  c.record_interval = 0.05;
  return c;
}

nlohmann::json run(const SimulationCase& c, const std::string& name) {
  RunOptions o;
  o.output_dir = "validation_runs/" + name;
  o.overwrite = true;  // a rerun of the group starts afresh
  o.progress = &std::cerr;
  o.progress_seconds = 60.0;
  const nlohmann::json j = run_case(c, o);
  const auto& r = j["result"];
  std::cout << name << ": D = " << r["taylor_deformation"].get<double>() << ", inclination "
            << r["inclination_deg"].get<double>() << " deg, eta_re stresslet " << r["eta_re"].get<double>() << " +- "
            << r["eta_re_sem"].get<double>() << ", wall " << r["eta_re_wall"].get<double>() << " +- "
            << r["eta_re_wall_sem"].get<double>() << ", " << r["wall_seconds"].get<double>() << " s\n";
  return j;
}

// Both viscosity estimates agree within their errors (3 combined SEM, or 1e-3 when the
// series is so steady that the SEM vanishes).
void expect_viscosities_agree(const nlohmann::json& r) {
  const double diff = std::abs(r["eta_re"].get<double>() - r["eta_re_wall"].get<double>());
  const double sem = std::hypot(r["eta_re_sem"].get<double>(), r["eta_re_wall_sem"].get<double>());
  EXPECT_LT(diff, std::max(3.0 * sem, 1e-3)) << "stresslet vs wall-stress viscosity";
}

std::vector<std::vector<double>> read_series(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);  // header
  std::vector<std::vector<double>> rows;
  while (std::getline(in, line)) {
    std::stringstream ss(line);
    std::string cell;
    std::vector<double> row;
    while (std::getline(ss, cell, ',')) row.push_back(std::stod(cell));
    rows.push_back(row);
  }
  return rows;
}

}  // namespace

// Reference: data/reference/capsule_shear_neo_hookean.csv (Ramanujan & Pozrikidis 1998,
// Doddi & Bagchi 2008; Ca_G = 3 Ca_E). Agreement asked: within 8 % of the mean of the
// sources (they differ from each other by up to 7 %; our box has walls at 5 a and Re = 0.2).
class CapsuleTaylorDeformation : public ::testing::TestWithParam<std::pair<double, double>> {};

TEST_P(CapsuleTaylorDeformation, MatchesBoundaryIntegralResults) {
  const auto [ca_g, d_ref] = GetParam();
  const nlohmann::json j = run(spherical_capsule(ca_g, 8), "capsule_ca" + std::to_string(ca_g));
  const auto& r = j["result"];
  EXPECT_NEAR(r["taylor_deformation"].get<double>() / d_ref, 1.0, 0.08) << "Ca_G = " << ca_g;
  expect_viscosities_agree(r);
}

INSTANTIATE_TEST_SUITE_P(NeoHookean, CapsuleTaylorDeformation,
                         ::testing::Values(std::pair{0.0375, 0.083}, std::pair{0.075, 0.156},
                                           std::pair{0.15, 0.2695}, std::pair{0.3, 0.3885},
                                           std::pair{0.6, 0.4975}));

TEST(CapsuleResolution, DeformationConvergesWithLatticeResolution) {
  // Ca_G = 0.15 (Ca_E = 0.05) at N_a = 6, 8, 10: the change must shrink.
  std::vector<double> d;
  for (int n : {6, 8, 10})
    d.push_back(run(spherical_capsule(0.15, n), "capsule_resolution_Na" + std::to_string(n))["result"]
                    ["taylor_deformation"].get<double>());
  std::cout << "D at N_a = 6, 8, 10: " << d[0] << ", " << d[1] << ", " << d[2] << "\n";
  EXPECT_LT(std::abs(d[2] - d[1]), std::abs(d[1] - d[0]));
}

TEST(DiluteStiffSpheres, IntrinsicViscosityNearEinstein) {
  // One nearly rigid sphere (Ca_G = 0.01, D about 0.02): eta_sp / phi against Einstein's
  // 5/2 (Einstein 1906, 1911). Walls and the periodic images raise it; see
  // docs/validation.md. Asserted: between 2.5 and 4.
  SimulationCase c = spherical_capsule(0.01, 8);
  c.strain_end = 4.0;
  c.window = {3.0, 4.0};
  const nlohmann::json j = run(c, "stiff_sphere");
  const double phi = j["result"]["phi_actual"].get<double>();
  const double ratio = (j["result"]["eta_re"].get<double>() - 1.0) / phi;
  std::cout << "stiff sphere: phi = " << phi << ", eta_sp / phi = " << ratio << "\n";
  EXPECT_GT(ratio, 2.5);
  EXPECT_LT(ratio, 4.0);
  expect_viscosities_agree(j["result"]);
}

// The immersed boundary thickens a membrane by a fraction of a lattice spacing, so a
// coarse lattice sees a larger sphere and a higher eta_sp / phi. Measured at N_a 6, 8, 10,
// 12 (5120 triangles, so the mesh stays finer than the lattice): the error falls with the
// order p of (1 / N_a)^p, which the library's Richardson extrapolation must assume
// (studies/library-v2-development/README.md, "The order of convergence in the dilute
// limit"). Measured: orders
// 1.61 and 1.59 from the two consecutive triples, limit 2.61 (Einstein's 5/2 raised by
// the walls and periodic images). Asserted: the orders lie between 1.2 and 2.2, the
// limit between 2.5 and 2.8.
double three_point_order(const double n[3], const double y[3]) {
  const double ratio = (y[0] - y[1]) / (y[1] - y[2]);
  auto gap = [&](double p) {
    const double h0 = std::pow(1.0 / n[0], p), h1 = std::pow(1.0 / n[1], p), h2 = std::pow(1.0 / n[2], p);
    return (h0 - h1) / (h1 - h2) - ratio;
  };
  double lo = 0.1, hi = 8.0;  // bisection: the ratio rises with p
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (lo + hi);
    (gap(lo) * gap(mid) <= 0.0 ? hi : lo) = mid;
  }
  return 0.5 * (lo + hi);
}

TEST(DiluteStiffSpheres, IntrinsicViscosityConvergesWithTheLattice) {
  const double n[4] = {6, 8, 10, 12};
  double ratio[4];
  for (int i = 0; i < 4; ++i) {
    SimulationCase c = spherical_capsule(0.01, static_cast<int>(n[i]));
    c.triangles = 5120;
    c.strain_end = 4.0;
    c.window = {3.0, 4.0};
    const nlohmann::json j = run(c, "stiff_sphere_5120_n" + std::to_string(static_cast<int>(n[i])));
    ratio[i] = (j["result"]["eta_re"].get<double>() - 1.0) / j["result"]["phi_actual"].get<double>();
  }
  const double p1 = three_point_order(n, ratio), p2 = three_point_order(n + 1, ratio + 1);
  // The limit from the finest pair at the mean order.
  const double p = 0.5 * (p1 + p2);
  const double limit = ratio[3] - (ratio[2] - ratio[3]) / (std::pow(n[3] / n[2], p) - 1.0);
  std::cout << "eta_sp / phi at N_a 6, 8, 10, 12: " << ratio[0] << ", " << ratio[1] << ", " << ratio[2] << ", "
            << ratio[3] << "; orders " << p1 << ", " << p2 << "; limit " << limit << "\n";
  for (int i = 0; i < 3; ++i) EXPECT_GT(ratio[i], ratio[i + 1]) << "not falling at N_a " << n[i];
  EXPECT_GT(p1, 1.2);
  EXPECT_LT(p1, 2.2);
  EXPECT_GT(p2, 1.2);
  EXPECT_LT(p2, 2.2);
  EXPECT_GT(limit, 2.5);
  EXPECT_LT(limit, 2.8);
  // The same runs read as a thickened sphere: eta_sp / phi = X (1 + c / N_a)^3, the
  // hydrodynamic radius a + c dx. The best c (one X for all four) is the offset the default
  // library's effective volume fractions use, 0.75 +- 0.05 (data/library/default/recipe.json;
  // docs/library.md measured 0.79 with X spread 0.3 %).
  double best_c = 0.0, best_spread = 1e9;
  for (int k = 300; k <= 1200; ++k) {
    const double c = k / 1000.0;
    double x[4], mean = 0.0;
    for (int i = 0; i < 4; ++i) mean += (x[i] = ratio[i] / std::pow(1.0 + c / n[i], 3)) / 4.0;
    double spread = 0.0;
    for (int i = 0; i < 4; ++i) spread = std::max(spread, std::abs(x[i] / mean - 1.0));
    if (spread < best_spread) best_c = c, best_spread = spread;
  }
  std::cout << "thickened sphere: c " << best_c << " lattice spacings, X within " << best_spread << "\n";
  EXPECT_GT(best_c, 0.6);
  EXPECT_LT(best_c, 0.9);
  EXPECT_LT(best_spread, 0.02);
}

// A single red blood cell at lambda = 5 starting with its axis in the shear plane: at low
// Ca it flips over (tumbling: the shear-plane inclination sweeps through +-90 degrees),
// at high Ca its inclination stays bounded (tank-treading or swinging), as the seed study
// reports for its cells.
double inclination_range(const std::string& series, double from_strain) {
  double lo = 1e9, hi = -1e9;
  for (const auto& row : read_series(series))
    if (row[0] >= from_strain) {
      lo = std::min(lo, row[4]);
      hi = std::max(hi, row[4]);
    }
  return hi - lo;
}

SimulationCase single_rbc(double ca) {
  SimulationCase c;
  c.shape = CellShape::Biconcave;
  c.triangles = 1280;
  c.law = MembraneLaw::Skalak;
  c.flow.capillary_number = ca;
  c.flow.viscosity_ratio = 5.0;
  c.flow.reynolds_number = 0.2;
  c.resolution.nodes_per_radius = 8;
  c.resolution.tau_out = 0.8;  // keeps tau_in = 3 lambda nu_out + 1/2 = 2 moderate
  c.resolution.box_in_radii = {6.0, 8.0, 8.0};
  // Symmetry axis turned from z towards y by 60 degrees: in the shear plane.
  c.cells.push_back({{0.0, 0.0, 0.0}, {1.0, 0.0, 0.0, 60.0}});
  c.record_interval = 0.1;
  return c;
}

TEST(SingleRbc, TumblesAtLowCa) {
  SimulationCase stiff = single_rbc(0.05);
  stiff.strain_end = 20.0;
  stiff.window = {10.0, 20.0};
  run(stiff, "rbc_lambda5_ca0.05");
  const double low = inclination_range("validation_runs/rbc_lambda5_ca0.05/series.csv", 2.0);
  std::cout << "inclination range: " << low << " deg (Ca 0.05)\n";
  EXPECT_GT(low, 150.0);
}

// Rolling. The seed study (its Fig. 3(d) inset and the text after its Fig. 3) reports that a
// single RBC at Ca = 0.01, lambda = 5 shows small deformations and settles into rolling (the
// disc spinning in the shear plane, its symmetry axis along the vorticity x) after
// gamma_dot t of about 100. The cell starts with its axis halfway between the flow z and
// the vorticity x, off the shear plane (a start in the plane stays there by symmetry); it
// tumbles and precesses, drifting slowly towards the vorticity (docs/validation.md), so the
// run is 300 strain units long. N_a = 6 and Skalak C = 10 (the default library's area
// modulus) keep that affordable (about 25 minutes on 2 cores): with C = 100 the area
// modulus would limit the time step (docs/library.md).
double mean_axis_vorticity(const std::string& series, double from_strain) {
  double sum = 0.0;
  int n = 0;
  for (const auto& row : read_series(series))
    if (row[0] >= from_strain) {
      sum += row.at(7);
      ++n;
    }
  return n ? sum / n : 0.0;
}

TEST(SingleRbc, RollsAtLowCa) {
  // The shipped example: Ca 0.01, lambda 5, N_a 6, box 6a x 8a x 6a, strain 300, Re 0.2.
  const SimulationCase c = read_case(RBCAL_CASES_DIR "/single_rbc_rolling.json");
  run(c, "rbc_lambda5_ca0.01_rolling");
  const std::string series = "validation_runs/rbc_lambda5_ca0.01_rolling/series.csv";
  const double early = mean_axis_vorticity(series, 0.0), late = mean_axis_vorticity(series, 280.0);
  std::cout << "|n_x| of the symmetry axis: mean " << early << " over the run, " << late
            << " over gamma_dot t in [280, 300] (1: rolling)\n";
  EXPECT_GT(late, 0.9);
}

// High Ca. The seed study (text after its Fig. 3; phi = 0.05, Ca = 0.8) reports the one
// qualitative difference between viscosity ratios: cells with lambda <= 1 elongate at a
// steady, relatively large orientation angle, cells with lambda >= 5 take complex
// (polylobed) shapes; tank-treading or swinging at lambda = 5 it reports only in the dense
// suspension (phi = 0.41). The expectation of tank-treading for a single cell at
// lambda = 5 is therefore tested as the seed reports it: a steady angle at lambda = 1, none
// at lambda = 5 (where this solver's cell keeps flipping while breathing strongly).
double high_ca_inclination_range(double lambda, const std::string& name) {
  SimulationCase soft = single_rbc(0.8);
  soft.flow.viscosity_ratio = lambda;
  soft.strain_end = 12.0;
  soft.window = {6.0, 12.0};
  run(soft, name);
  const double range = inclination_range("validation_runs/" + name + "/series.csv", 6.0);
  std::cout << "inclination range over gamma_dot t in [6, 12]: " << range << " deg (Ca 0.8, lambda " << lambda
            << ")\n";
  return range;
}

TEST(SingleRbc, KeepsASteadyAngleAtHighCaForLambda1) {
  EXPECT_LT(high_ca_inclination_range(1.0, "rbc_lambda1_ca0.8"), 45.0);
}

TEST(SingleRbc, FindsNoSteadyAngleAtHighCaForLambda5) {
  EXPECT_GT(high_ca_inclination_range(5.0, "rbc_lambda5_ca0.8"), 90.0);
}

// The immersed boundary's thickening of a thin body, against an exact value: a rigid oblate
// spheroid of the red cell's aspect ratio (0.328) held in the rolling Jeffery orbit, whose
// intrinsic viscosity is Jeffery's 1 / (a b^4 J') = 4.119 (Jeffery, Proc. R. Soc. Lond. A 102
// (1922) 161; solver/membrane/rigid_spheroid_viscosity.hpp). Read as the thickened volume
// with the exact limit held, eta_sp / phi = X_inf B V(c dx) / V, each N_a gives its own c;
// studies/ib-thickening measured c 0.738, 0.658, 0.612 at N_a 6, 8, 10 with B 0.995 from a
// box twice as large, and the sphere's 0.698, 0.652, 0.629. Asserted: the spheroid stays
// rolling, its c falls with N_a, and at every N_a it lies within 0.06 of the sphere's (the
// volume form carries from the sphere to the thin body; the diameter form needs 1.1-1.3).
TEST(DiluteRigidSpheroid, ThickensAsTheSphereDoes) {
  const double eps = 0.328, box_raise = 0.995;
  const double exact = rolling_spheroid_intrinsic_viscosity(eps);
  const int n[3] = {6, 8, 10};
  const double sphere_c[3] = {0.698, 0.652, 0.629};  // studies/ib-thickening, B 0.992 removed
  double c_of[3];
  for (int i = 0; i < 3; ++i) {
    SimulationCase c = spherical_capsule(0.01, n[i]);
    c.shape = CellShape::Spheroid;
    c.aspect_ratio = eps;
    c.triangles = 5120;
    c.strain_end = 4.0;
    c.window = {3.0, 4.0};
    c.cells = {{{0.0, 0.0, 0.0}, {0.0, 1.0, 0.0, 90.0}}};  // symmetry axis on the vorticity x
    const std::string name = "rigid_spheroid_n" + std::to_string(n[i]);
    const nlohmann::json j = run(c, name);
    const double ratio = (j["result"]["eta_re"].get<double>() - 1.0) / j["result"]["phi_actual"].get<double>();
    EXPECT_GT(mean_axis_vorticity("validation_runs/" + name + "/series.csv", 3.0), 0.99) << "left the rolling orbit";
    const SteinerTerms terms = steiner_terms(make_spheroid(5120, 1.0, eps));
    double lo = 0.0, hi = 2.0;  // bisection on c: the thickened volume rises with it
    for (int k = 0; k < 60; ++k) {
      const double mid = 0.5 * (lo + hi);
      (exact * box_raise * thickened_volume_ratio(terms, mid / n[i]) < ratio ? lo : hi) = mid;
    }
    c_of[i] = 0.5 * (lo + hi);
    std::cout << "rigid spheroid N_a " << n[i] << ": eta_sp / phi " << ratio << " (exact " << exact << "), c "
              << c_of[i] << " (sphere " << sphere_c[i] << ")\n";
    EXPECT_NEAR(c_of[i], sphere_c[i], 0.06) << "N_a " << n[i];
  }
  EXPECT_GT(c_of[0], c_of[1]);
  EXPECT_GT(c_of[1], c_of[2]);
}
