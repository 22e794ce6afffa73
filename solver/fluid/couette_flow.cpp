#include "solver/fluid/couette_flow.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace rbcal::solver {

std::vector<double> streamwise_profile(const FluidLattice& fluid) {
  std::vector<double> profile(fluid.ny(), 0.0);
  for (int y = 0; y < fluid.ny(); ++y) {
    double sum = 0.0;
    for (int x = 0; x < fluid.nx(); ++x)
      for (int z = 0; z < fluid.nz(); ++z) sum += fluid.moments(fluid.index(x, y, z)).uz;
    profile[y] = sum / (static_cast<double>(fluid.nx()) * fluid.nz());
  }
  return profile;
}

namespace {

double least_squares_slope(const std::vector<double>& values) {
  const double n = static_cast<double>(values.size());
  const double mean_y = 0.5 * (n - 1.0);
  double mean_v = 0.0;
  for (double v : values) mean_v += v / n;
  double sxy = 0.0, sxx = 0.0;
  for (std::size_t i = 0; i < values.size(); ++i) {
    sxy += (static_cast<double>(i) - mean_y) * (values[i] - mean_v);
    sxx += (static_cast<double>(i) - mean_y) * (static_cast<double>(i) - mean_y);
  }
  return sxx > 0.0 ? sxy / sxx : 0.0;
}

}  // namespace

CouetteResult run_to_steady_couette(FluidLattice& fluid, const CouetteRun& run) {
  const FluidConfig& cfg = fluid.config();
  if (cfg.y_boundary != WallNormalBoundary::MovingWalls)
    throw std::invalid_argument("Couette flow needs moving walls in y");
  CouetteResult result;
  const double velocity_jump = cfg.wall_velocity_top - cfg.wall_velocity_bottom;
  result.imposed_shear_rate = velocity_jump / cfg.ny;
  const double scale = std::max(std::abs(velocity_jump), 1e-300);

  std::vector<double> previous = streamwise_profile(fluid);
  while (fluid.steps_done() < run.max_steps) {
    for (int i = 0; i < run.check_interval; ++i) fluid.step();
    std::vector<double> current = streamwise_profile(fluid);
    double change = 0.0;
    for (std::size_t y = 0; y < current.size(); ++y)
      change = std::max(change, std::abs(current[y] - previous[y]) / scale);
    previous.swap(current);
    if (change < run.tolerance) {
      result.converged = true;
      break;
    }
  }
  result.steps = fluid.steps_done();
  result.profile = previous;
  result.measured_shear_rate = least_squares_slope(previous);
  const WallTraction t = fluid.wall_traction();
  result.wall_shear_stress = 0.5 * (t.bottom[2] - t.top[2]);
  return result;
}

CouetteDemoResult run_couette_demo(const CouetteDemo& o) {
  if (!(o.shear_rate > 0.0)) throw std::invalid_argument("--shear-rate must be positive");
  if (!(o.plasma_viscosity > 0.0)) throw std::invalid_argument("--plasma-viscosity must be positive");
  if (!(o.radius > 0.0)) throw std::invalid_argument("--radius must be positive");
  FlowParameters flow;
  flow.reynolds_number = o.reynolds;
  LatticeResolution res;
  res.nodes_per_radius = o.nodes_per_radius;
  res.tau_out = o.tau;
  // The flow does not vary along x or z: a 4-node slab is the whole problem.
  res.box_in_radii = {4.0 / o.nodes_per_radius, o.height_in_radii, 4.0 / o.nodes_per_radius};
  CouetteDemoResult out;
  out.lattice = derive_lattice_units(flow, res);
  const LatticeUnits& lu = out.lattice;
  FluidConfig cfg;
  cfg.nx = lu.nx;
  cfg.ny = lu.ny;
  cfg.nz = lu.nz;
  cfg.viscosity = lu.nu_out;
  cfg.wall_velocity_bottom = -lu.wall_speed;
  cfg.wall_velocity_top = lu.wall_speed;
  FluidLattice fluid(cfg);
  CouetteRun run;
  run.tolerance = o.tolerance;
  out.run = run_to_steady_couette(fluid, run);
  // Physical scales: dt from the shear rate, stress from eta0 gamma_dot <-> nu gamma_dot_lu.
  out.dt = lu.shear_rate / o.shear_rate;
  const double stress_scale = o.plasma_viscosity * o.shear_rate / (lu.nu_out * lu.shear_rate);
  out.measured_shear_rate = out.run.measured_shear_rate / out.dt;
  out.wall_shear_stress = out.run.wall_shear_stress * stress_scale;
  out.viscosity_from_walls = out.wall_shear_stress / out.measured_shear_rate;
  return out;
}

}  // namespace rbcal::solver
