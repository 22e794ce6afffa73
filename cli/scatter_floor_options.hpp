#pragma once
// The seed-scatter floor's options (surrogate/resolution_extrapolation.hpp), shared by
// `library extrapolate` and `library effective-phi`.
#include <CLI/CLI.hpp>
#include <vector>

#include "surrogate/resolution_extrapolation.hpp"

namespace rbcal::cli {

struct ScatterFloorOptions {
  std::vector<double> phi;  // --scatter-phi LOW,HIGH
};

inline void add_scatter_floor_options(CLI::App* cmd, surrogate::ExtrapolationOptions& floor, ScatterFloorOptions& o) {
  cmd->add_option("--scatter-floor", floor.scatter_floor,
                  "Relative sd added in quadrature to each dense run's error (seed scatter of its window mean)")
      ->capture_default_str()
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--scatter-phi", o.phi, "phi (as run) where the scatter floor starts and where it reaches its full value")
      ->delimiter(',')
      ->expected(2);
}

// Called from the command's callback, after parsing.
inline void apply_scatter_phi(const ScatterFloorOptions& o, surrogate::ExtrapolationOptions& floor) {
  if (o.phi.size() != 2) return;
  if (!(o.phi[0] <= o.phi[1])) throw CLI::ValidationError("--scatter-phi", "give LOW,HIGH with LOW <= HIGH");
  floor.scatter_phi_low = o.phi[0];
  floor.scatter_phi_high = o.phi[1];
}

}  // namespace rbcal::cli
