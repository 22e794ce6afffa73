// Fitting G_s to optical-tweezers diameters: measurements made by the model itself at a
// known G_s are fitted back to it (the fit's tolerance, 1 % in G_s), and a malformed
// measurement file is refused naming its line and field.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "solver/membrane/stretch_fit.hpp"
#include "../scratch_path.hpp"

using namespace rbcal::solver;

TEST(StretchFit, RecoversTheShearModulusThatMadeTheMeasurements) {
  StretchSettings s;
  s.triangles = 320;
  s.material.shear_modulus = 5.3e-6;
  const std::vector<double> forces_pn = {30.0, 90.0, 150.0};
  std::vector<double> forces;
  for (double f : forces_pn) forces.push_back(f * 1e-12);
  StretchMeasurements m;
  for (const StretchPoint& p : stretch_cell(s, forces)) {
    m.axial_um.push_back(p.axial_diameter * 1e6);
    m.transverse_um.push_back(p.transverse_diameter * 1e6);
  }
  m.force_pn = forces_pn;
  StretchFitOptions o;
  o.shear_modulus_min = 2e-6;
  o.shear_modulus_max = 12e-6;
  int evaluations = 0;
  o.progress = [&](double, double) { ++evaluations; };
  const double fitted = fit_shear_modulus(s, m, o);
  EXPECT_NEAR(fitted / 5.3e-6, 1.0, 0.01);
  EXPECT_GT(evaluations, 5);
}

TEST(StretchFit, RefusesAMalformedFileNamingLineAndField) {
  const auto path = rbcal::testing_support::scratch_path("stretch.csv");
  {
    std::ofstream out(path);
    out << "# comment\nforce_pN,axial_um,transverse_um\n0,7.8,7.8\n50,9.1,minus\n";
  }
  try {
    read_stretch_measurements(path.string());
    FAIL() << "accepted a malformed file";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(path.string() + ":4: field transverse_um"), std::string::npos) << e.what();
  }
  std::filesystem::remove(path);
}
