#pragma once
// The box correction's prior from twin runs: the same case in the library's box and in one
// twice as high (docs/library.md, "The box twins"). For each pair
//     beta = ln(eta_big / eta_library) / ln(eta_library),
// the exponent in ln eta_bulk = (1 + beta) ln eta_re (surrogate/offset_family.hpp), with its
// standard error from the two runs' standard errors. The prior for the bulk is
//     mean = 1.5 m,   sd = sqrt(s^2 + (0.5 m)^2 + se_m^2),
// m the twins' mean beta, s their scatter, se_m the mean's standard error. Why 1.5 m +- 0.5 m:
// the doubled box is not yet the bulk; a gap effect that decays as 1 / H (a wall layer of
// fixed width) leaves as much again between it and an infinite gap, one that decays faster
// leaves nothing.
#include <filesystem>
#include <string>
#include <vector>

#include "surrogate/library_case.hpp"

namespace rbcal::surrogate {

struct BoxTwinFiles {
  std::filesystem::path library_box;  // the run in the library's box (a case result file)
  std::filesystem::path bigger_box;   // its twin in the doubled box
};

struct BoxTwin {
  LibraryCase library_box, bigger_box;
  double beta = 0.0, beta_se = 0.0;
};

// The mean of several estimates of beta, their scatter (sample sd) and the mean's standard
// error from the estimates' own standard errors.
struct BetaSpread {
  double mean = 0.0, scatter = 0.0, mean_se = 0.0;
};
BetaSpread spread_of(const std::vector<double>& beta, const std::vector<double>& beta_se);

// The prior for the bulk from a measured step to the doubled box (its mean n, scatter s and
// standard error se) and the twins' gap effect m: beyond the doubled box lies half of m, with as
// much again as its uncertainty (the rule above), so mean n + 0.5 m, sd sqrt(s^2 + (0.5 m)^2 + se^2).
struct BulkPrior {
  double mean = 0.0, sd = 0.0;
};
BulkPrior bulk_prior(const BetaSpread& step, double twins_mean_beta);

struct BoxTwinPrior {
  std::vector<BoxTwin> twins;
  double mean_beta = 0.0, scatter = 0.0, mean_se = 0.0;  // m, s, se_m
  double mean = 0.0, sd = 0.0;                           // the prior for the bulk
};

// Throws std::invalid_argument naming the file when a run cannot be read, when a pair's runs
// are not the same point (phi, Ca, lambda), or when no pair is given.
BoxTwinPrior box_twin_prior(const std::vector<BoxTwinFiles>& pairs);

// One line per pair (phi_actual, both eta_re, their ratio, beta), then m, s, se_m and the prior.
std::string describe_box_twins(const BoxTwinPrior& prior);

}  // namespace rbcal::surrogate
