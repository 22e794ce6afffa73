#include "solver/simulation/simulation_case.hpp"

#include <fstream>
#include <sstream>
#include <stdexcept>

#include "solver/io/json_file.hpp"

namespace rbcal::solver {

std::string to_string(CellShape s) { return s == CellShape::Sphere ? "sphere" : "biconcave"; }
std::string to_string(Integrator i) { return i == Integrator::Euler ? "euler" : "rk4"; }

namespace {

// Reads optional fields with errors that name the source and the field path.
class Reader {
 public:
  Reader(const nlohmann::json& root, std::string source) : root_(root), source_(std::move(source)) {}

  [[noreturn]] void fail(const std::string& field, const std::string& what) const {
    throw std::invalid_argument(source_ + ": field " + field + ": " + what);
  }

  const nlohmann::json* find(const std::string& path) const {
    const nlohmann::json* node = &root_;
    std::stringstream ss(path);
    std::string key;
    while (std::getline(ss, key, '.')) {
      if (!node->is_object()) fail(path, "parent is not an object");
      auto it = node->find(key);
      if (it == node->end()) return nullptr;
      node = &*it;
    }
    return node;
  }

  double number(const std::string& path, double fallback, double lo, double hi) const {
    const nlohmann::json* n = find(path);
    if (!n) return fallback;
    if (!n->is_number()) fail(path, "must be a number");
    const double v = n->get<double>();
    if (!(v >= lo && v <= hi)) fail(path, "must be in [" + fmt(lo) + ", " + fmt(hi) + "], got " + fmt(v));
    return v;
  }

  int integer(const std::string& path, int fallback, int lo, int hi) const {
    const nlohmann::json* n = find(path);
    if (!n) return fallback;
    if (!n->is_number_integer()) fail(path, "must be an integer");
    const long long v = n->get<long long>();
    if (v < lo || v > hi) fail(path, "must be in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
    return static_cast<int>(v);
  }

  std::string text(const std::string& path, const std::string& fallback) const {
    const nlohmann::json* n = find(path);
    if (!n) return fallback;
    if (!n->is_string()) fail(path, "must be a string");
    return n->get<std::string>();
  }

  template <std::size_t N>
  std::array<double, N> numbers(const std::string& path, std::array<double, N> fallback) const {
    const nlohmann::json* n = find(path);
    if (!n) return fallback;
    return array_at<N>(*n, path);
  }

  template <std::size_t N>
  std::array<double, N> array_at(const nlohmann::json& n, const std::string& path) const {
    if (!n.is_array() || n.size() != N) fail(path, "must be an array of " + std::to_string(N) + " numbers");
    std::array<double, N> out{};
    for (std::size_t i = 0; i < N; ++i) {
      if (!n[i].is_number()) fail(path, "must be an array of " + std::to_string(N) + " numbers");
      out[i] = n[i].get<double>();
    }
    return out;
  }

 private:
  static std::string fmt(double v) {
    std::ostringstream s;
    s << v;
    return s.str();
  }
  const nlohmann::json& root_;
  std::string source_;
};

}  // namespace

SimulationCase case_from_json(const nlohmann::json& j, const std::string& source) {
  Reader r(j, source);
  if (!j.is_object()) r.fail("(top level)", "must be a JSON object");
  const std::string schema = r.text("schema", "");
  if (schema != "rbcal.case/1") r.fail("schema", "must be \"rbcal.case/1\", got \"" + schema + "\"");

  SimulationCase c;
  c.flow.capillary_number = r.number("params.Ca", c.flow.capillary_number, 1e-6, 1e3);
  c.flow.viscosity_ratio = r.number("params.lambda", c.flow.viscosity_ratio, 1e-3, 1e3);
  c.flow.reduced_bending = r.number("params.kb_hat", c.flow.reduced_bending, 0.0, 1e3);
  c.target_phi = r.number("params.phi", 0.0, 0.0, 0.7);

  try {
    const std::string shape = r.text("cells.shape", "biconcave");
    if (shape != "sphere" && shape != "biconcave") r.fail("cells.shape", "must be \"sphere\" or \"biconcave\"");
    c.shape = shape == "sphere" ? CellShape::Sphere : CellShape::Biconcave;
    c.profile = biconcave_profile_from_string(r.text("cells.profile", "evans-fung"));
    c.law = membrane_law_from_string(r.text("cells.law", "skalak"));
    c.kernel = kernel_from_string(r.text("numerics.kernel", "peskin4"));
  } catch (const std::invalid_argument& e) {
    if (std::string(e.what()).rfind(source, 0) == 0) throw;
    throw std::invalid_argument(source + ": " + e.what());
  }
  c.triangles = r.integer("cells.triangles", c.triangles, 20, 1 << 20);
  try {
    subdivisions_for(c.triangles);
  } catch (const std::invalid_argument& e) {
    r.fail("cells.triangles", e.what());
  }
  c.skalak_c = r.number("cells.skalak_c", c.skalak_c, 0.0, 1e6);
  if (const nlohmann::json* list = r.find("cells.placements")) {
    if (!list->is_array()) r.fail("cells.placements", "must be an array");
    for (std::size_t i = 0; i < list->size(); ++i) {
      const std::string path = "cells.placements[" + std::to_string(i) + "]";
      const nlohmann::json& p = (*list)[i];
      if (!p.is_object()) r.fail(path, "must be an object with center (and rotation)");
      CellPlacement cp;
      if (!p.contains("center")) r.fail(path + ".center", "is missing");
      cp.center = r.array_at<3>(p["center"], path + ".center");
      if (p.contains("rotation")) cp.rotation = r.array_at<4>(p["rotation"], path + ".rotation");
      c.cells.push_back(cp);
    }
  }

  c.resolution.nodes_per_radius = r.integer("numerics.N_a", c.resolution.nodes_per_radius, 2, 256);
  c.resolution.tau_out = r.number("numerics.tau_out", c.resolution.tau_out, 0.5000001, 10.0);
  c.resolution.box_in_radii = r.numbers<3>("numerics.box", c.resolution.box_in_radii);
  for (double b : c.resolution.box_in_radii)
    if (!(b > 0.0)) r.fail("numerics.box", "lengths must be positive");
  c.flow.reynolds_number = r.number("numerics.Re", c.flow.reynolds_number, 1e-6, 100.0);
  const std::string integrator = r.text("numerics.integrator", to_string(c.integrator));
  if (integrator != "rk4" && integrator != "euler") r.fail("numerics.integrator", "must be \"rk4\" or \"euler\"");
  c.integrator = integrator == "euler" ? Integrator::Euler : Integrator::RK4;
  c.indicator_tolerance = r.number("numerics.indicator_tolerance", c.indicator_tolerance, 0.0, 1.0);
  c.coupling_interval = r.integer("numerics.coupling_interval", c.coupling_interval, 1, 1000);
  c.volume_stiffness = r.number("numerics.volume_stiffness", c.volume_stiffness, 0.0, 1e9);
  c.seed = static_cast<std::uint64_t>(r.number("numerics.seed", 1.0, 0.0, 9.0e15));

  c.strain_end = r.number("run.strain_end", c.strain_end, 0.0, 1e7);
  c.window = r.numbers<2>("run.window", c.window);
  if (!(c.window[0] >= 0.0 && c.window[0] < c.window[1] && c.window[1] <= c.strain_end))
    r.fail("run.window", "must satisfy 0 <= start < end <= run.strain_end");
  c.record_interval = r.number("run.record_interval", c.record_interval, 1e-6, 1e6);
  c.vtk_interval = r.number("run.vtk_interval", c.vtk_interval, 0.0, 1e7);
  c.checkpoint_interval = r.number("run.checkpoint_interval", c.checkpoint_interval, 0.0, 1e7);
  if (const nlohmann::json* q = r.find("run.quiescent")) {
    if (!q->is_boolean()) r.fail("run.quiescent", "must be true or false");
    c.quiescent = q->get<bool>();
  }
  if (c.cells.empty() && c.target_phi == 0.0) r.fail("cells.placements", "no cells: give placements (or params.phi)");
  return c;
}

SimulationCase read_case(const std::string& path) { return case_from_json(read_json_file(path, "case file"), path); }

nlohmann::json case_to_json(const SimulationCase& c) {
  nlohmann::json j;
  j["schema"] = "rbcal.case/1";
  j["params"] = {{"Ca", c.flow.capillary_number}, {"lambda", c.flow.viscosity_ratio}, {"kb_hat", c.flow.reduced_bending}};
  if (c.target_phi > 0.0) j["params"]["phi"] = c.target_phi;
  j["cells"] = {{"shape", to_string(c.shape)},
                {"profile", to_string(c.profile)},
                {"triangles", c.triangles},
                {"law", to_string(c.law)},
                {"skalak_c", c.skalak_c}};
  for (const CellPlacement& p : c.cells) j["cells"]["placements"].push_back({{"center", p.center}, {"rotation", p.rotation}});
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
  j["run"] = {{"strain_end", c.strain_end},
              {"window", c.window},
              {"record_interval", c.record_interval},
              {"vtk_interval", c.vtk_interval},
              {"checkpoint_interval", c.checkpoint_interval},
              {"quiescent", c.quiescent}};
  return j;
}

nlohmann::json state_defining_json(const SimulationCase& c) {
  nlohmann::json j = case_to_json(c);
  const bool quiescent = c.quiescent;
  j.erase("run");
  j["quiescent"] = quiescent;
  return j;
}

}  // namespace rbcal::solver
