#pragma once
// One simulation case: cells, flow parameters, numerics and run length, read from and
// written to the case JSON of docs/reference.md (schema "rbcal.case/1"). Lengths in
// cell radii a, times as shear strain gamma_dot t; see lattice_units.hpp for the
// conversion to lattice units.
#include <array>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "solver/coupling/peskin_kernel.hpp"
#include "solver/lattice_units.hpp"
#include "solver/membrane/cell_shapes.hpp"
#include "solver/membrane/strain_energy.hpp"

namespace rbcal::solver {

enum class CellShape { Sphere, Biconcave, Spheroid };
enum class Integrator { Euler, RK4 };
// The fluid velocity that moves the membrane over a coupling interval of k fluid steps:
// the mean of the velocities interpolated after each of the k steps, or (the earlier
// scheme, kept to reproduce runs made with it) the velocity after the last one.
enum class NodeVelocity { IntervalMean, LastStep };

struct CellPlacement {
  std::array<double, 3> center{0.0, 0.0, 0.0};  // in a, relative to the box centre
  // Rotation of the reference cell (symmetry axis z) as axis (need not be unit) and angle [deg].
  std::array<double, 4> rotation{0.0, 0.0, 1.0, 0.0};
};

struct SimulationCase {
  // params
  FlowParameters flow;     // Ca, lambda, Re, kb_hat
  double target_phi = 0.0;  // volume fraction asked for (0: cells placed explicitly)
  // cells
  CellShape shape = CellShape::Biconcave;
  BiconcaveProfile profile = BiconcaveProfile::EvansFung;
  double aspect_ratio = 1.0;  // polar over equatorial semi-axis, spheroids only
  int triangles = 1280;
  MembraneLaw law = MembraneLaw::Skalak;
  double skalak_c = 100.0;
  // Optional growth of C with Ca: the membrane runs with C = max(skalak_c, skalak_c_per_ca
  // * Ca) (effective_skalak_c). The area strain of a cell scales as Ca / (1 + 2C), so a C
  // proportional to Ca bounds it equally at every Ca, while the explicit coupling's limit
  // (on G_s (1 + 2C) in lattice units, G_s ~ 1 / Ca) stays the same
  // (studies/library-v2-development/README.md,
  // "Area incompressibility at high Ca"). 0: C is skalak_c.
  double skalak_c_per_ca = 0.0;
  double effective_skalak_c() const;
  std::vector<CellPlacement> cells;
  // Placed cells that overlap are refused when the case is read, unless this is set
  // (cells.overlap_allowed: only for tests of the overlap diagnostics).
  bool overlap_allowed = false;
  // numerics
  LatticeResolution resolution;
  KernelKind kernel = KernelKind::Peskin4;
  // Euler by default: RK4 through the frozen field of one step changed eta_re of dense
  // cases by a few 1e-5 relative (docs/performance.md) at twice the cost of the step.
  Integrator integrator = Integrator::Euler;
  // The inside fraction is rebuilt once a membrane node has moved more than this many
  // lattice spacings since the last rebuild (0: every step). Cells move about 0.01-0.02
  // spacings per step, while the indicator is itself only accurate to O(dx); 0.1 and then
  // 0.2 (with coupling interval 2) changed eta_re of dense cases by a fraction of one
  // standard error (docs/performance.md).
  double indicator_tolerance = 0.2;
  // Fluid steps per membrane step (forces, spreading, inside fraction, node update).
  // 2 (with the interval mean below) changed eta_re of two dense cases by 0.17 standard
  // errors and halves the membrane's cost; it halves the stiffness the explicit coupling
  // takes too, so very stiff cases need 1. A case file's "auto" (or no value) takes 2 where
  // the stability bound allows it and 1 elsewhere (coupling_stability.hpp).
  int coupling_interval = 2;
  bool coupling_interval_chosen = false;  // set by "auto" (not written back: the number is)
  // Over an interval the mean velocity is both closer to the fluid's motion and more
  // stable: the bench case runs at k = 2 with it and blows up with the last step's
  // (docs/performance.md, "The interval's mean velocity"). At k = 1 the two are the same.
  NodeVelocity node_velocity = NodeVelocity::IntervalMean;
  // numerics.precision: "float" stores the populations in 32 bits, shifted by their rest
  // values, with the arithmetic in 64 bits (fluid_lattice.hpp); "double" (the default).
  bool single_precision = false;
  double volume_stiffness = 0.0;  // k_v in G_s / a of an optional volume penalty force
  std::uint64_t seed = 1;
  // run
  double strain_end = 100.0;                    // gamma_dot t at the end
  std::array<double, 2> window = {40.0, 100.0};  // averaging window in gamma_dot t
  double record_interval = 0.1;                 // strain between time-series rows
  double vtk_interval = 0.0;                    // strain between VTK snapshots (0: none)
  bool quiescent = false;  // walls and fluid at rest (tests): gamma_dot only sets the time unit
  double checkpoint_interval = 5.0;  // strain between checkpoints (0: none)
};

// The parts of a case that fix the physical state (params, cells, numerics, quiescent);
// a checkpoint may be resumed under a case that differs only in the run length,
// window or output intervals. The area constant appears as the C the membrane runs with
// (effective_skalak_c), so a rule that gives the same C defines the same state.
nlohmann::json state_defining_json(const SimulationCase& c);

// Parses a case; errors name the file and the JSON field ("numerics.N_a").
SimulationCase read_case(const std::string& path);
SimulationCase case_from_json(const nlohmann::json& j, const std::string& source);
nlohmann::json case_to_json(const SimulationCase& c);

// The nodes of a reference cell placed as p says: rotated, then moved to centre + scale * p.center.
std::vector<Vec3> placed_nodes(const TriangleMesh& reference, const CellPlacement& p, const Vec3& centre, double scale);

// The case's cell at rest (shape, profile and triangle count) with the given radius.
TriangleMesh reference_cell(const SimulationCase& c, double radius);

std::string to_string(CellShape s);
std::string to_string(Integrator i);
std::string to_string(NodeVelocity v);

}  // namespace rbcal::solver
