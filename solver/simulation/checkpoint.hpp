#pragma once
// Binary checkpoints of a shear-flow simulation: the lattice populations and step count,
// and every cell's node positions, velocities, membrane forces and the positions the
// inside fraction was last built from, all as raw doubles, so
// that a restarted run continues bit-identically (the viscosity and force fields are
// functions of the positions and are rebuilt). The case JSON is stored alongside and must
// match on restart. Files are written atomically (temporary file + rename).
#include <cstdint>
#include <string>
#include <vector>

#include "solver/membrane/triangle_mesh.hpp"

namespace rbcal::solver {

struct CheckpointState {
  std::string case_json;  // the case the state belongs to (compact JSON)
  std::int64_t steps = 0;
  std::vector<double> populations;
  std::vector<std::vector<Vec3>> positions, velocities, forces;
  // Node positions the inside fraction was last built from (numerics.indicator_tolerance);
  // empty where the viscosity is uniform.
  std::vector<std::vector<Vec3>> indicator_positions;
  // Inside a coupling interval under numerics.node_velocity "interval_mean": the fluid
  // velocity field summed over the interval's steps so far, and their number (empty and
  // 0 otherwise, and in format 2 files).
  std::vector<double> velocity_sum;
  std::uint64_t velocity_sum_steps = 0;
};

void write_checkpoint(const std::string& path, const CheckpointState& state);
// Throws std::runtime_error naming the file if it is missing, truncated or not a checkpoint.
CheckpointState read_checkpoint(const std::string& path);

}  // namespace rbcal::solver
