// `rbcal stretch`: optical-tweezers stretching of one red blood cell in static
// equilibrium; axial and transverse diameters versus force, optionally compared with
// (and G_s fitted to) measured diameters.
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "cli/data_folder.hpp"
#include "formats/json_file.hpp"
#include "formats/provenance.hpp"
#include "solver/membrane/stretch_fit.hpp"

namespace rbcal::cli {

namespace {

struct StretchOptions {
  double shear_modulus = 4e-6;  // N/m
  std::vector<double> forces_pn;
  int triangles = 1280;
  double radius = 3.91e-6;  // m
  std::string profile = "evans-fung";
  std::string law = "skalak";
  double skalak_c = 100.0;
  double bending_modulus = 5e-19;  // J
  double contact_fraction = 0.05;
  std::string compare_path = shipped_file("reference/mills_2004_optical_tweezers.csv");
  bool no_compare = false;
  bool fit = false;
  std::string json_path;
};

solver::StretchSettings settings_for(const StretchOptions& o, double shear_modulus) {
  solver::StretchSettings s;
  s.triangles = o.triangles;
  s.radius = o.radius;
  s.profile = solver::biconcave_profile_from_string(o.profile);
  s.material = {solver::membrane_law_from_string(o.law), shear_modulus, o.skalak_c};
  s.bending_modulus = o.bending_modulus;
  s.contact_fraction = o.contact_fraction;
  return s;
}

std::vector<solver::StretchPoint> run(const StretchOptions& o, double shear_modulus, const std::vector<double>& forces_pn) {
  std::vector<double> forces;
  for (double f : forces_pn) forces.push_back(f * 1e-12);
  return solver::stretch_cell(settings_for(o, shear_modulus), forces);
}

void run_stretch(StretchOptions o) {
  if (!(o.shear_modulus > 0.0)) throw std::invalid_argument("--shear-modulus must be positive");
  solver::StretchMeasurements measured;
  const bool compare = !o.no_compare;
  if (compare) {
    measured = solver::read_stretch_measurements(o.compare_path);
    if (o.forces_pn.empty()) o.forces_pn = measured.force_pn;
    else if (o.forces_pn != measured.force_pn)
      throw std::invalid_argument("--forces must match the forces of " + o.compare_path + " (or use --no-compare)");
  } else if (o.forces_pn.empty()) {
    for (int f = 0; f <= 200; f += 25) o.forces_pn.push_back(f);
  }
  if (o.fit && !compare) throw std::invalid_argument("--fit needs measurements (drop --no-compare)");

  double gs = o.shear_modulus;
  if (o.fit) {
    solver::StretchFitOptions fo;
    fo.progress = [](double shear_modulus, double misfit) {
      std::printf("  fit: G_s = %6.3f uN/m  rms misfit %.3f um\n", shear_modulus * 1e6, misfit);
      std::fflush(stdout);
    };
    gs = solver::fit_shear_modulus(settings_for(o, gs), measured, fo);
  }

  const std::vector<solver::StretchPoint> pts = run(o, gs, o.forces_pn);
  std::printf("rbcal stretch: optical-tweezers stretching, static equilibrium\n");
  std::printf("  G_s = %.3f uN/m, %s law (C = %g), k_c = %.3g J, %d triangles, radius %.3f um, %s profile,\n"
              "  forces on %.0f %% of the vertices at each end\n",
              gs * 1e6, o.law.c_str(), o.skalak_c, o.bending_modulus, o.triangles, o.radius * 1e6, o.profile.c_str(),
              100.0 * o.contact_fraction);
  const solver::MeshQuality q =
      solver::mesh_quality(solver::make_biconcave_cell(o.triangles, 1.0, solver::biconcave_profile_from_string(o.profile)));
  std::printf("  mesh: edges %.3f-%.3f a (spread %.2f), angles %.1f-%.1f deg\n", q.min_edge, q.max_edge, q.edge_spread,
              q.min_angle_deg, q.max_angle_deg);
  std::printf("  %9s %10s %10s", "force_pN", "D_A_um", "D_T_um");
  if (compare) std::printf(" %10s %10s", "meas_D_A", "meas_D_T");
  std::printf(" %11s %10s %6s\n", "vol_error", "area_chg", "conv");
  for (std::size_t i = 0; i < pts.size(); ++i) {
    std::printf("  %9.1f %10.3f %10.3f", pts[i].force * 1e12, pts[i].axial_diameter * 1e6,
                pts[i].transverse_diameter * 1e6);
    if (compare) std::printf(" %10.3f %10.3f", measured.axial_um[i], measured.transverse_um[i]);
    std::printf(" %11.2e %10.4f %6s\n", pts[i].volume_error, pts[i].area_change, pts[i].converged ? "yes" : "NO");
  }
  if (compare) std::printf("  rms misfit %.3f um against %s\n", solver::rms_misfit(pts, measured), o.compare_path.c_str());

  if (!o.json_path.empty()) {
    nlohmann::json j;
    j["provenance"] = formats::provenance_block();
    j["shear_modulus_N_per_m"] = gs;
    j["law"] = o.law;
    j["skalak_c"] = o.skalak_c;
    j["bending_modulus_J"] = o.bending_modulus;
    j["triangles"] = o.triangles;
    j["radius_m"] = o.radius;
    j["profile"] = o.profile;
    j["contact_fraction"] = o.contact_fraction;
    for (const auto& p : pts)
      j["points"].push_back({{"force_N", p.force},
                             {"axial_diameter_m", p.axial_diameter},
                             {"transverse_diameter_m", p.transverse_diameter},
                             {"volume_error", p.volume_error},
                             {"area_change", p.area_change},
                             {"converged", p.converged}});
    if (compare) j["rms_misfit_um"] = solver::rms_misfit(pts, measured);
    formats::write_json_atomically(o.json_path, j);
  }
  for (const auto& p : pts)
    if (!p.converged) throw std::runtime_error("equilibrium not reached at " + std::to_string(p.force * 1e12) + " pN");
}

}  // namespace

void add_stretch_command(CLI::App& app) {
  auto o = std::make_shared<StretchOptions>();
  CLI::App* cmd = app.add_subcommand(
      "stretch",
      "Optical-tweezers stretching of one RBC: axial/transverse diameters [um] vs force [pN] for a given G_s");
  cmd->add_option("--shear-modulus", o->shear_modulus, "Membrane shear modulus G_s [N/m]")->capture_default_str();
  cmd->add_option("--forces", o->forces_pn,
                  "Stretching forces [pN], comma separated (default: the forces of the comparison data, or 0..200 "
                  "in steps of 25 with --no-compare)")
      ->delimiter(',');
  cmd->add_option("--triangles", o->triangles, "Mesh triangles: 320, 1280 or 5120")->capture_default_str();
  cmd->add_option("--radius", o->radius, "Cell major radius a [m] (Evans-Fung R0 = 3.91e-6)")->capture_default_str();
  cmd->add_option("--profile", o->profile, "Biconcave profile: evans-fung (max thickness 0.656 a) or seed (a/2)")
      ->capture_default_str();
  cmd->add_option("--law", o->law, "Membrane law: skalak or neo-hookean")->capture_default_str();
  cmd->add_option("--skalak-c", o->skalak_c, "Skalak area-dilation coefficient C (K_s = G_s (1 + 2C))")
      ->capture_default_str();
  cmd->add_option("--bending-modulus", o->bending_modulus, "Bending modulus k_c [J]")->capture_default_str();
  cmd->add_option("--contact-fraction", o->contact_fraction, "Fraction of the vertices pulled at each end")
      ->capture_default_str();
  cmd->add_option("--compare", o->compare_path,
                  "CSV of measured diameters (force_pN,axial_um,transverse_um; '#' comments)")
      ->capture_default_str();
  cmd->add_flag("--no-compare", o->no_compare, "Do not compare with measurements");
  cmd->add_flag("--fit", o->fit, "Find the G_s that best reproduces the measured diameters (least squares)");
  cmd->add_option("--json", o->json_path, "Also write the results as JSON to this file");
  cmd->callback([o] { run_stretch(*o); });
}

}  // namespace rbcal::cli
