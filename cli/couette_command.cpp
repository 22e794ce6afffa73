// `rbcal couette`: sheared plane Couette flow from rest to steady state, reported in
// physical units; a demonstration that the fluid solver reproduces the imposed shear.
#include <cmath>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>

#include "cli/commands.hpp"
#include "formats/units.hpp"
#include "formats/json_file.hpp"
#include "formats/provenance.hpp"
#include "solver/fluid/couette_flow.hpp"
#include "solver/lattice_units.hpp"

namespace rbcal::cli {

namespace {

struct CouetteOptions {
  solver::CouetteDemo demo;
  std::string json_path;
};

void run_couette(const CouetteOptions& opts) {
  const solver::CouetteDemo& o = opts.demo;
  const solver::CouetteDemoResult d = solver::run_couette_demo(o);
  const solver::LatticeUnits& lu = d.lattice;
  const solver::CouetteResult& r = d.run;
  const double dt = d.dt, measured_rate = d.measured_shear_rate, wall_stress = d.wall_shear_stress;
  const double measured_viscosity = d.viscosity_from_walls;
  std::printf("rbcal couette: plane Couette flow, D3Q19 TRT lattice Boltzmann\n");
  std::printf("  lattice           %d x %d x %d nodes (N_a = %d), tau = %g, nu = %.6g\n", lu.nx, lu.ny,
              lu.nz, o.nodes_per_radius, lu.tau_out, lu.nu_out);
  std::printf("  wall speed        %.4e lattice units (Mach %.3e), dt = %.4e s, dx = %.4e m\n",
              lu.wall_speed, lu.mach, dt, o.radius / o.nodes_per_radius);
  std::printf("  %s after %lld steps\n", r.converged ? "steady" : "NOT converged",
              static_cast<long long>(r.steps));
  std::printf("  imposed shear rate   %12.6f 1/s\n", o.shear_rate);
  std::printf("  measured shear rate  %12.6f 1/s   (relative error %.1e)\n", measured_rate,
              std::abs(measured_rate / o.shear_rate - 1.0));
  std::printf("  wall shear stress    %12.6e Pa\n", wall_stress);
  std::printf("  viscosity from walls %12.6f mPa s (imposed %.6f, relative error %.1e)\n",
              measured_viscosity * kMilli, o.plasma_viscosity * kMilli,
              std::abs(measured_viscosity / o.plasma_viscosity - 1.0));

  if (!opts.json_path.empty()) {
    nlohmann::json j;
    for (const auto& [name, value] : lu.entries()) j["lattice"][name] = value;
    j["steps"] = r.steps;
    j["converged"] = r.converged;
    j["imposed_shear_rate_per_s"] = o.shear_rate;
    j["measured_shear_rate_per_s"] = measured_rate;
    j["wall_shear_stress_Pa"] = wall_stress;
    j["viscosity_from_walls_Pa_s"] = measured_viscosity;
    j["provenance"] = formats::provenance_block();
    formats::write_json_atomically(opts.json_path, j);
  }
  if (!r.converged) throw std::runtime_error("Couette flow did not reach steady state");
}

}  // namespace

void add_couette_command(CLI::App& app) {
  auto opts = std::make_shared<CouetteOptions>();
  CLI::App* cmd = app.add_subcommand(
      "couette", "Demonstration: sheared plane Couette flow to steady state, measured vs imposed shear");
  cmd->add_option("--shear-rate", opts->demo.shear_rate, "Imposed shear rate [1/s]")->capture_default_str();
  cmd->add_option("--plasma-viscosity", opts->demo.plasma_viscosity, "Plasma viscosity eta0 [Pa s]")
      ->capture_default_str();
  cmd->add_option("--radius", opts->demo.radius, "Cell major radius a [m]; sets dx = a / N_a")
      ->capture_default_str();
  cmd->add_option("--height", opts->demo.height_in_radii, "Gap H between the walls [cell radii a]")
      ->capture_default_str();
  cmd->add_option("--nodes-per-radius", opts->demo.nodes_per_radius, "Lattice nodes per radius N_a")
      ->capture_default_str();
  cmd->add_option("--tau", opts->demo.tau, "Plasma relaxation time tau (> 1/2)")->capture_default_str();
  cmd->add_option("--reynolds", opts->demo.reynolds, "Reynolds number rho gamma_dot a^2 / eta0")
      ->capture_default_str();
  cmd->add_option("--tolerance", opts->demo.tolerance,
                  "Steady when the profile changes less than this (relative) per 200 steps")
      ->capture_default_str();
  cmd->add_option("--json", opts->json_path, "Also write the result as JSON to this file");
  cmd->callback([opts] { run_couette(*opts); });
}

}  // namespace rbcal::cli
