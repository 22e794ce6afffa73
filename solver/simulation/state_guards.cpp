#include "solver/simulation/state_guards.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace rbcal::solver {

std::string run_stopped(std::int64_t step, double strain, const std::string& what) {
  return "run stopped at step " + std::to_string(step) + " (strain " + std::to_string(strain) + "): " + what;
}

std::string node_mach_exceeded(double mach) {
  std::ostringstream what;
  what << "membrane-node Mach number " << mach << " exceeds " << kMaxNodeMach << " (the coupling went unstable)";
  return what.str();
}

void check_state(const Observables& o, std::int64_t step) {
  auto fail = [&](const std::string& what) { throw std::runtime_error(run_stopped(step, o.strain, what)); };
  if (!std::isfinite(o.eta_re_stresslet)) fail("eta_re from the stresslet is not finite");
  if (!std::isfinite(o.eta_re_wall)) fail("eta_re from the wall stress is not finite");
  for (std::size_t i = 0; i < o.cells.size(); ++i)
    if (!std::isfinite(o.cells[i].volume_error) || std::abs(o.cells[i].volume_error) > 0.5)
      fail("cell " + std::to_string(i) + ": volume error " + std::to_string(o.cells[i].volume_error));
  if (!(o.max_mach < kMaxNodeMach)) fail(node_mach_exceeded(o.max_mach));
}

}  // namespace rbcal::solver
