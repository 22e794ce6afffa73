#include "solver/simulation/simulation_case.hpp"

#include <algorithm>
#include <numbers>
#include <stdexcept>

#include "formats/field_reader.hpp"
#include "formats/format_error.hpp"
#include "formats/json_file.hpp"
#include "formats/library_schema.hpp"
#include "solver/lattice_units.hpp"
#include "solver/simulation/cell_overlap.hpp"
#include "solver/simulation/detail/coupling_stability.hpp"

namespace rbcal::solver {

TriangleMesh reference_cell(const SimulationCase& c, double radius) {
  switch (c.shape) {
    case CellShape::Sphere: return make_sphere(c.triangles, radius);
    case CellShape::Spheroid: return make_spheroid(c.triangles, radius, c.aspect_ratio);
    case CellShape::Biconcave: break;
  }
  return make_biconcave_cell(c.triangles, radius, c.profile);
}

std::vector<Vec3> placed_nodes(const TriangleMesh& reference, const CellPlacement& p, const Vec3& centre, double scale) {
  Vec3 axis(p.rotation[0], p.rotation[1], p.rotation[2]);
  if (axis.norm() == 0.0) axis = Vec3::UnitZ();
  const Eigen::Matrix3d rot = Eigen::AngleAxisd(p.rotation[3] * std::numbers::pi / 180.0, axis.normalized()).toRotationMatrix();
  const Vec3 at = centre + scale * Vec3(p.center[0], p.center[1], p.center[2]);
  std::vector<Vec3> x;
  x.reserve(reference.vertices.size());
  for (const Vec3& v : reference.vertices) x.push_back(at + rot * v);
  return x;
}

std::string to_string(CellShape s) {
  switch (s) {
    case CellShape::Sphere: return "sphere";
    case CellShape::Spheroid: return "spheroid";
    case CellShape::Biconcave: break;
  }
  return "biconcave";
}
std::string to_string(Integrator i) { return i == Integrator::Euler ? "euler" : "rk4"; }
std::string to_string(NodeVelocity v) { return v == NodeVelocity::IntervalMean ? "interval_mean" : "last_step"; }

SimulationCase case_from_json(const nlohmann::json& j, const std::string& source) {
  const formats::FieldReader r(j, source);
  r.expect_schema(formats::kCaseSchema);

  // The fields case_to_json writes are the fields a case file may have: one list for both.
  SimulationCase every_field;
  every_field.target_phi = 0.1;
  every_field.cells.push_back({});
  every_field.skalak_c_per_ca = 1.0;
  every_field.coupling_interval = 2;  // so that node_velocity is written
  every_field.shape = CellShape::Spheroid;  // so that aspect_ratio is written
  every_field.overlap_allowed = true;
  every_field.single_precision = true;  // so that precision is written
  const nlohmann::json known = case_to_json(every_field);
  for (const char* section : {"params", "cells", "numerics", "run"}) {
    std::vector<std::string> keys;
    for (const auto& item : known[section].items()) keys.push_back(item.key());
    r.only_known_keys(section, keys);
  }

  SimulationCase c;
  c.flow.capillary_number = r.number_or("params.Ca", c.flow.capillary_number, 1e-6, 1e3);
  c.flow.viscosity_ratio = r.number_or("params.lambda", c.flow.viscosity_ratio, 1e-3, 1e3);
  c.flow.reduced_bending = r.number_or("params.kb_hat", c.flow.reduced_bending, 0.0, 1e3);
  c.target_phi = r.number_or("params.phi", 0.0, 0.0, 0.7);

  try {
    const std::string shape = r.text_or("cells.shape", "biconcave");
    if (shape != "sphere" && shape != "biconcave" && shape != "spheroid")
      r.fail("cells.shape", "must be \"sphere\", \"biconcave\" or \"spheroid\"");
    c.shape = shape == "sphere" ? CellShape::Sphere : shape == "spheroid" ? CellShape::Spheroid : CellShape::Biconcave;
    c.profile = biconcave_profile_from_string(r.text_or("cells.profile", "evans-fung"));
    c.law = membrane_law_from_string(r.text_or("cells.law", "skalak"));
    c.kernel = kernel_from_string(r.text_or("numerics.kernel", "peskin4"));
  } catch (const formats::FormatError&) {
    throw;
  } catch (const std::invalid_argument& e) {
    throw formats::FormatError(source, e.what());
  }
  c.triangles = r.integer_or("cells.triangles", c.triangles, 20, 1 << 20);
  try {
    subdivisions_for(c.triangles);
  } catch (const std::invalid_argument& e) {
    r.fail("cells.triangles", e.what());
  }
  if (c.shape == CellShape::Spheroid)
    c.aspect_ratio = r.number_or("cells.aspect_ratio", c.aspect_ratio, 0.05, 20.0);
  else if (r.find("cells.aspect_ratio"))
    r.fail("cells.aspect_ratio", "only a spheroid has an aspect ratio");
  c.skalak_c = r.number_or("cells.skalak_c", c.skalak_c, 0.0, 1e6);
  c.skalak_c_per_ca = r.number_or("cells.skalak_c_per_Ca", c.skalak_c_per_ca, 0.0, 1e6);
  if (const nlohmann::json* list = r.find("cells.placements")) {
    if (!list->is_array()) r.fail("cells.placements", "must be an array");
    for (std::size_t i = 0; i < list->size(); ++i) {
      const std::string path = "cells.placements." + std::to_string(i);
      if (!(*list)[i].is_object()) r.fail(path, "must be an object with center (and rotation)");
      CellPlacement cp;
      if (!r.find(path + ".center")) r.fail(path + ".center", "missing");
      cp.center = r.numbers_or<3>(path + ".center", cp.center);
      cp.rotation = r.numbers_or<4>(path + ".rotation", cp.rotation);
      c.cells.push_back(cp);
    }
  }
  if (const nlohmann::json* allowed = r.find("cells.overlap_allowed")) {
    if (!allowed->is_boolean()) r.fail("cells.overlap_allowed", "must be true or false");
    c.overlap_allowed = allowed->get<bool>();
  }

  // No default resolution: a case without one silently became the seed study's N_a 16 box of
  // about 9 GB. The two fields that set a case's size are asked for.
  for (const char* field : {"numerics.N_a", "numerics.box"})
    if (!r.find(field))
      r.fail(field, "missing: give the resolution numerics.N_a (lattice nodes per cell radius; the seed study used "
                    "16) and the box numerics.box [Lx, H, Lz] in cell radii (the seed study's [16, 10, 16])");
  c.resolution.nodes_per_radius = r.integer_or("numerics.N_a", c.resolution.nodes_per_radius, 2, 256);
  c.resolution.tau_out = r.number_or("numerics.tau_out", c.resolution.tau_out, 0.5000001, 10.0);
  c.resolution.box_in_radii = r.numbers_or<3>("numerics.box", c.resolution.box_in_radii);
  for (double b : c.resolution.box_in_radii)
    if (!(b > 0.0)) r.fail("numerics.box", "lengths must be positive");
  c.flow.reynolds_number = r.number_or("numerics.Re", c.flow.reynolds_number, 1e-6, 100.0);
  const std::string integrator = r.text_or("numerics.integrator", to_string(c.integrator));
  if (integrator != "rk4" && integrator != "euler") r.fail("numerics.integrator", "must be \"rk4\" or \"euler\"");
  c.integrator = integrator == "euler" ? Integrator::Euler : Integrator::RK4;
  c.indicator_tolerance = r.number_or("numerics.indicator_tolerance", c.indicator_tolerance, 0.0, 1.0);
  // "auto" (or absent): the largest interval up to 2 that the coupling's stability bound
  // allows (coupling_stability.hpp), chosen once the case is read.
  const nlohmann::json* interval = r.find("numerics.coupling_interval");
  const bool auto_interval = !interval || (interval->is_string() && *interval == "auto");
  if (interval && interval->is_string() && !auto_interval)
    r.fail("numerics.coupling_interval", "must be a whole number of fluid steps or \"auto\"");
  if (!auto_interval) c.coupling_interval = r.integer_or("numerics.coupling_interval", c.coupling_interval, 1, 1000);
  const std::string node_velocity = r.text_or("numerics.node_velocity", to_string(c.node_velocity));
  if (node_velocity != "interval_mean" && node_velocity != "last_step")
    r.fail("numerics.node_velocity", "must be \"interval_mean\" or \"last_step\"");
  c.node_velocity = node_velocity == "interval_mean" ? NodeVelocity::IntervalMean : NodeVelocity::LastStep;
  const std::string precision = r.text_or("numerics.precision", "double");
  if (precision != "double" && precision != "float") r.fail("numerics.precision", "must be \"double\" or \"float\"");
  c.single_precision = precision == "float";
  c.volume_stiffness = r.number_or("numerics.volume_stiffness", c.volume_stiffness, 0.0, 1e9);
  c.seed = static_cast<std::uint64_t>(r.number_or("numerics.seed", 1.0, 0.0, 9.0e15));

  c.strain_end = r.number_or("run.strain_end", c.strain_end, 0.0, 1e7);
  c.window = r.numbers_or<2>("run.window", c.window);
  if (!(c.window[0] >= 0.0 && c.window[0] < c.window[1] && c.window[1] <= c.strain_end))
    r.fail("run.window", "must satisfy 0 <= start < end <= run.strain_end");
  c.record_interval = r.number_or("run.record_interval", c.record_interval, 1e-6, 1e6);
  c.vtk_interval = r.number_or("run.vtk_interval", c.vtk_interval, 0.0, 1e7);
  c.checkpoint_interval = r.number_or("run.checkpoint_interval", c.checkpoint_interval, 0.0, 1e7);
  if (const nlohmann::json* q = r.find("run.quiescent")) {
    if (!q->is_boolean()) r.fail("run.quiescent", "must be true or false");
    c.quiescent = q->get<bool>();
  }
  if (c.cells.empty() && c.target_phi == 0.0) r.fail("cells.placements", "no cells: give placements (or params.phi)");
  // Two placed cells that overlap would start with membranes inside each other, which the
  // immersed boundary never separates (no contact force): refused, naming the pair.
  if (c.cells.size() > 1 && !c.overlap_allowed) {
    const TriangleMesh cell = reference_cell(c, 1.0);
    std::vector<std::vector<Vec3>> x;
    for (const CellPlacement& p : c.cells) x.push_back(placed_nodes(cell, p, Vec3::Zero(), 1.0));
    const auto& box = c.resolution.box_in_radii;
    if (const auto pair = first_overlapping_pair(x, cell.triangles, box[0], box[2]))
      r.fail("cells.placements." + std::to_string((*pair)[1]),
             "overlaps cells.placements." + std::to_string((*pair)[0]) +
                 " (a node of one lies inside the other); move the centres apart or turn the cells");
  }
  // The lattice this case implies must exist (e.g. the box a whole number of nodes at N_a):
  // found by fuzzing the plan reader, which otherwise failed later without naming the file.
  try {
    derive_lattice_units(c.flow, c.resolution);
  } catch (const std::invalid_argument& e) {
    r.fail("numerics", e.what());
  }
  if (auto_interval) {
    c.coupling_interval = stable_coupling_interval(c);
    c.coupling_interval_chosen = true;
  }
  return c;
}

SimulationCase read_case(const std::string& path) { return case_from_json(formats::read_json_file(path), path); }

nlohmann::json case_to_json(const SimulationCase& c) {
  nlohmann::json j;
  j["schema"] = formats::kCaseSchema;
  j["params"] = {{"Ca", c.flow.capillary_number}, {"lambda", c.flow.viscosity_ratio}, {"kb_hat", c.flow.reduced_bending}};
  if (c.target_phi > 0.0) j["params"]["phi"] = c.target_phi;
  j["cells"] = {{"shape", to_string(c.shape)},
                {"profile", to_string(c.profile)},
                {"triangles", c.triangles},
                {"law", to_string(c.law)},
                {"skalak_c", c.skalak_c}};
  if (c.shape == CellShape::Spheroid) j["cells"]["aspect_ratio"] = c.aspect_ratio;
  if (c.skalak_c_per_ca > 0.0) j["cells"]["skalak_c_per_Ca"] = c.skalak_c_per_ca;
  for (const CellPlacement& p : c.cells) j["cells"]["placements"].push_back({{"center", p.center}, {"rotation", p.rotation}});
  if (c.overlap_allowed) j["cells"]["overlap_allowed"] = true;
  j["numerics"] = {{"N_a", c.resolution.nodes_per_radius},
                   {"tau_out", c.resolution.tau_out},
                   {"box", c.resolution.box_in_radii},
                   {"Re", c.flow.reynolds_number},
                   {"kernel", to_string(c.kernel)},
                   {"integrator", to_string(c.integrator)},
                   {"indicator_tolerance", c.indicator_tolerance},
                   {"coupling_interval", c.coupling_interval},
                   {"volume_stiffness", c.volume_stiffness},
                   {"seed", c.seed}};
  // With one fluid step per membrane step both node velocities are the same: the field is
  // written only where it matters (so k = 1 cases read the same before and after it existed).
  if (c.coupling_interval > 1) j["numerics"]["node_velocity"] = to_string(c.node_velocity);
  // Written only for "float", so that double cases read the same as before it existed.
  if (c.single_precision) j["numerics"]["precision"] = "float";
  j["run"] = {{"strain_end", c.strain_end},
              {"window", c.window},
              {"record_interval", c.record_interval},
              {"vtk_interval", c.vtk_interval},
              {"checkpoint_interval", c.checkpoint_interval},
              {"quiescent", c.quiescent}};
  return j;
}

double SimulationCase::effective_skalak_c() const {
  return std::max(skalak_c, skalak_c_per_ca * flow.capillary_number);
}

nlohmann::json state_defining_json(const SimulationCase& c) {
  nlohmann::json j = case_to_json(c);
  j["cells"]["skalak_c"] = c.effective_skalak_c();
  j["cells"].erase("skalak_c_per_Ca");
  const bool quiescent = c.quiescent;
  j.erase("run");
  j["quiescent"] = quiescent;
  return j;
}

}  // namespace rbcal::solver
