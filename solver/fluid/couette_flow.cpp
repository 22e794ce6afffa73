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

}  // namespace rbcal::solver
