#pragma once
// Test fixtures: libraries drawn from a known smooth ln eta_re(phi, Ca, lambda), as
// in-memory training cases or as case files in a temporary folder.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <random>
#include <string>
#include <vector>

#include "surrogate/training_case.hpp"

namespace rbcal::surrogate::testing {

// ln eta_re = phi (2.5 + 0.4 ln(1/Ca) + 0.15 ln lambda) + 0.08 phi^2 exp(-(ln Ca - ln 0.1)^2 / 2) sin(ln lambda):
// the seed study's exp(alpha phi) form plus a smooth bump the linear mean cannot follow.
double known_log_viscosity(double phi, double ca, double lambda);

struct SyntheticGrid {
  std::vector<double> phi{0.05, 0.1, 0.15, 0.2, 0.25, 0.3, 0.35, 0.4};
  std::vector<double> ca{0.01, 0.03, 0.1, 0.3, 0.8};
  std::vector<double> lambda{1.0, 5.0, 10.0};
};

// One case per grid point: phi_actual = phi (1 + 0.01 u), relative SEM 0.5 - 2 %, and
// eta_re drawn with that noise around exp(known_log_viscosity(phi_actual, ...)).
std::vector<TrainingCase> synthetic_training_cases(const SyntheticGrid& grid, unsigned seed);

// The JSON the solver writes for one finished case (all fields the reader checks).
nlohmann::json case_json(double phi, double ca, double lambda, double phi_actual, double eta_re, double eta_re_sem);

// A fresh, empty folder under the system temp dir, named after the running test; removed
// when the test program exits.
std::filesystem::path fresh_temp_folder(const std::string& name);

void write_text(const std::filesystem::path& file, const std::string& text);

// LIB/cases/<id>.json for every point of the grid, with eta_re from synthetic_training_cases.
void write_synthetic_library(const std::filesystem::path& root, const SyntheticGrid& grid, unsigned seed);

}  // namespace rbcal::surrogate::testing
