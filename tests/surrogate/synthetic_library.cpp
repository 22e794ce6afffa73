#include "synthetic_library.hpp"

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <system_error>
#include <vector>

namespace rbcal::surrogate::testing {

double known_log_viscosity(double phi, double ca, double lambda) {
  const double l = std::log(ca), m = std::log(lambda);
  const double bump = 0.08 * phi * phi * std::exp(-0.5 * (l - std::log(0.1)) * (l - std::log(0.1))) * std::sin(m);
  return phi * (2.5 - 0.4 * l + 0.15 * m) + bump;
}

namespace {

struct SyntheticCase {
  double phi, ca, lambda, phi_actual, eta_re, sem;
};

std::vector<SyntheticCase> synthetic_cases(const SyntheticGrid& grid, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0), relative_sem(0.005, 0.02);
  std::normal_distribution<double> normal(0.0, 1.0);
  std::vector<SyntheticCase> out;
  for (double phi : grid.phi)
    for (double ca : grid.ca)
      for (double lambda : grid.lambda) {
        SyntheticCase c{phi, ca, lambda, phi * (1.0 + 0.01 * unit(rng)), 0.0, 0.0};
        const double rel = relative_sem(rng);
        c.eta_re = std::exp(known_log_viscosity(c.phi_actual, ca, lambda) + rel * normal(rng));
        c.sem = rel * c.eta_re;
        out.push_back(c);
      }
  return out;
}

std::string case_id(const SyntheticCase& c) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "phi%.3f_Ca%.3f_lam%.2f", c.phi, c.ca, c.lambda);
  return buf;
}

}  // namespace

std::vector<TrainingCase> synthetic_training_cases(const SyntheticGrid& grid, unsigned seed) {
  std::vector<TrainingCase> out;
  for (const SyntheticCase& c : synthetic_cases(grid, seed)) {
    const double rel = c.sem / c.eta_re;
    out.push_back({case_id(c), c.phi_actual, std::log(c.ca), std::log(c.lambda), std::log(c.eta_re), rel * rel});
  }
  return out;
}

nlohmann::json case_json(double phi, double ca, double lambda, double phi_actual, double eta_re, double eta_re_sem) {
  return {
      {"schema", "rbcal.case/1"},
      {"params", {{"phi", phi}, {"Ca", ca}, {"lambda", lambda}, {"kb_hat", 0.0078}}},
      {"cells", {{"law", "skalak"}, {"shape", "biconcave"}, {"profile", "evans-fung"}, {"skalak_c", 100.0}, {"triangles", 320}}},
      {"numerics",
       {{"N_a", 4}, {"Re", 0.2}, {"box", {8.0, 5.0, 8.0}}, {"integrator", "rk4"}, {"kernel", "peskin4"}, {"seed", 1},
        {"tau_out", 1.0}}},
      {"run", {{"strain_end", 20.0}, {"window", {10.0, 20.0}}}},
      {"lattice", {{"nx", 32.0}}},
      {"result",
       {{"eta_re", eta_re},
        {"eta_re_sem", eta_re_sem},
        {"eta_re_wall", eta_re * 1.01},
        {"eta_re_wall_sem", 2.0 * eta_re_sem},
        {"phi_actual", phi_actual},
        {"n_cells", 12},
        {"steps", 5000},
        {"wall_seconds", 12.5}}},
      {"provenance", {{"date", "2026-11-22T00:00:00Z"}, {"rbcal_version", "0.1.0"}}},
  };
}

namespace {

// The folders fresh_temp_folder made, removed when the test program exits (their names
// carry the process id, so they would otherwise pile up run after run).
class TempFolders {
 public:
  ~TempFolders() {
    std::error_code ignored;
    for (const auto& p : folders_) std::filesystem::remove_all(p, ignored);
  }
  void add(const std::filesystem::path& p) { folders_.push_back(p); }

 private:
  std::vector<std::filesystem::path> folders_;
};

}  // namespace

std::filesystem::path fresh_temp_folder(const std::string& name) {
  static TempFolders made;
  const std::filesystem::path p = std::filesystem::temp_directory_path() / ("rbcal_surrogate_tests_" + std::to_string(getpid()) + "_" + name);
  std::filesystem::remove_all(p);
  std::filesystem::create_directories(p);
  made.add(p);
  return p;
}

void write_text(const std::filesystem::path& file, const std::string& text) {
  std::filesystem::create_directories(file.parent_path());
  std::ofstream(file) << text;
}

void write_synthetic_library(const std::filesystem::path& root, const SyntheticGrid& grid, unsigned seed) {
  for (const SyntheticCase& c : synthetic_cases(grid, seed))
    write_text(root / "cases" / (case_id(c) + ".json"),
               case_json(c.phi, c.ca, c.lambda, c.phi_actual, c.eta_re, c.sem).dump(2));
}

}  // namespace rbcal::surrogate::testing
